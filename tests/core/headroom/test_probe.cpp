// SPDX-License-Identifier: GPL-3.0-or-later
// The probe's contract, never its timing: a short run gives one record per thread whose bookkeeping holds, says which
// policy it really got, and a cancelled run stops every thread and throws. Runs as a normal thread (realtime off) so
// the test neither needs rights nor disturbs a shared machine; no latency or duration is asserted.
#include <QTest>

#include "headroom/probe.h"

using namespace bs::headroom;

class TestProbe : public QObject {
  Q_OBJECT
 private slots:
  void validation_names_the_problem() {
    ProbeConfig c;
    QCOMPARE(QString::fromStdString(validate(c)), QString());
    QCOMPARE(c.period_ns(), 1'000'000LL);
    c.rate_hz = 20'000;
    QVERIFY(QString::fromStdString(validate(c)).startsWith("rate 20000"));
    c.rate_hz = 100;
    c.computation_ns = 10'000'000;  // the whole 10 ms period
    QVERIFY(QString::fromStdString(validate(c)).contains("is not below the period (10000 us)"));
    c.computation_ns = 0;
    c.priority = 0;
    QVERIFY(QString::fromStdString(validate(c)).startsWith("priority 0"));
    c.priority = 80;
    c.cpus = {100000};
    QVERIFY(QString::fromStdString(validate(c)).startsWith("CPU 100000 does not exist"));
    c.cpus.clear();
    c.threads = 0;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, run_probe(c, 0.1));
  }

  void short_run_keeps_its_books() {
    ProbeConfig c;
    c.rate_hz = 500;
    c.threads = 2;
    c.realtime = false;
    c.computation_ns = 20'000;
    c.limit_ns = 200'000;
    const ProbeResult r = run_probe(c, 0.2);
    QCOMPARE(r.threads.size(), std::size_t{2});
    for (int k = 0; k < 2; ++k) {
      const ThreadLatency& t = r.threads[static_cast<std::size_t>(k)];
      QCOMPARE(t.index, k);
      QVERIFY(t.histogram.cycles > 0);
      QCOMPARE(QString::fromStdString(t.histogram.bookkeeping_error()), QString());
      QCOMPARE(QString::fromStdString(t.policy), QString("SCHED_OTHER"));
      QVERIFY(!t.priority);
      QVERIFY(!t.realtime());
      QCOMPARE(t.period_ns, 2'000'000LL);
      QCOMPARE(t.deadline_ns, 2'000'000LL);
      QCOMPARE(t.computation_ns, 20'000LL);
      QCOMPARE(t.histogram.bins.size(), std::size_t{200});
      QVERIFY(t.misses.has_value());
      QVERIFY(t.misses->count <= t.histogram.cycles);
      QVERIFY(t.mean_ns.has_value());
      QVERIFY(*t.max_response_ns >= 20'000);  // the computation ran: a response includes it
    }
  }

  void cancel_stops_every_thread() {
    ProbeConfig c;
    c.realtime = false;
    bs::CancelToken cancel;
    int reports = 0;
    cancel.set_progress([&](double, std::string_view step) {
      QCOMPARE(QString::fromUtf8(step.data(), static_cast<int>(step.size())), QString("idle"));
      if (++reports == 3) cancel.cancel();
    });
    QVERIFY_THROWS_EXCEPTION(bs::Cancelled, run_probe(c, 3600, &cancel, "idle"));
    QCOMPARE(reports, 3);
  }
};

QTEST_APPLESS_MAIN(TestProbe)
#include "test_probe.moc"
