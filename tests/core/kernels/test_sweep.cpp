// SPDX-License-Identifier: GPL-3.0-or-later
#include <QtTest>

#include "analysis/flops.h"
#include "kernels/sweep.h"
#include "kernels/worker_spec.h"

using namespace bs::kernels;

class TestSweep : public QObject {
  Q_OBJECT
 private slots:
  void worker_specs() {
    QCOMPARE(parse_worker_spec("1,2,4,8"), (std::vector<std::int64_t>{1, 2, 4, 8}));
    QCOMPARE(parse_worker_spec("256:1024:256"), (std::vector<std::int64_t>{256, 512, 768, 1024}));
    QCOMPARE(parse_worker_spec("1:100:32"), (std::vector<std::int64_t>{1, 33, 65, 97}));  // the paper's CPU sweep
    QCOMPARE(parse_worker_spec("8,1,2,4:8:2"), (std::vector<std::int64_t>{1, 2, 4, 6, 8}));
    QCOMPARE(parse_worker_spec("256:1024000:256").size(), std::size_t{4000});
    QCOMPARE(parse_dims_list("4,1,2"), (std::vector<int>{1, 2, 4}));
  }
  void bad_specs_name_the_problem_data() {
    QTest::addColumn<QString>("spec");
    QTest::addColumn<QString>("message");
    QTest::newRow("empty") << "" << "empty";
    QTest::newRow("zero") << "0,4" << "at least 1";
    QTest::newRow("negative step") << "1:10:-1" << "at least 1";
    QTest::newRow("zero step") << "1:10:0" << "at least 1";
    QTest::newRow("reversed") << "10:1:1" << "start is greater than stop";
    QTest::newRow("junk") << "4x" << "expected a whole number";
    QTest::newRow("two colons") << "1:2" << "START:STOP:STEP";
    QTest::newRow("too many") << "1:2000000:1" << "more than";
    QTest::newRow("overflow") << "99999999999999999999" << "too large";
  }
  void bad_specs_name_the_problem() {
    QFETCH(QString, spec);
    QFETCH(QString, message);
    try {
      parse_worker_spec(spec.toStdString());
      QFAIL("accepted");
    } catch (const std::invalid_argument& e) {
      QVERIFY2(QString(e.what()).contains(message), e.what());
    }
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, parse_dims_list("65"));
  }
  void sweep_produces_verified_runs() {
    const CpuInfo cpu = detect_cpu(/*calibrate=*/false);
    const Backend simd = cpu_backends(cpu).front();
    SweepSpec spec;
    spec.workers = {1, 8, 64};
    spec.dims = {1, 4};
    spec.iterations = 2000;
    spec.repeats = 2;
    int points = 0;
    const auto result = run_sweep(simd, cpu, spec, bs::CancelToken{}, {}, [&](const bs::FlopsRun&) { ++points; });
    QVERIFY(!result.cancelled);
    QCOMPARE(points, 6);
    QCOMPARE(result.runs.size(), std::size_t{2});
    for (const auto& run : result.runs) {
      QCOMPARE(run.samples.size(), std::size_t{3});
      QCOMPARE(run.samples[0].seconds.size(), std::size_t{2});
      QCOMPARE(run.provenance.origin, bs::DataOrigin::Measured);
      QVERIFY(!run.provenance.host.empty() && !run.provenance.cpu_model.empty());
      QCOMPARE(run.variant, std::string("throughput"));
      QVERIFY(bs::find_peak(run)->flops > 0);
    }
  }
  void cancel_keeps_a_valid_partial_run() {
    const CpuInfo cpu = detect_cpu(false);
    const Backend simd = cpu_backends(cpu).front();
    SweepSpec spec;
    spec.workers = {1, 2, 3, 4, 5, 6, 7, 8};
    spec.iterations = 1000;
    bs::CancelToken cancel;
    int completed = 0;
    const auto result = run_sweep(simd, cpu, spec, cancel, {}, [&](const bs::FlopsRun&) {
      if (++completed == 3) cancel.cancel();
    });
    QVERIFY(result.cancelled);
    QCOMPARE(result.runs.size(), std::size_t{1});
    QCOMPARE(result.runs[0].samples.size(), std::size_t{3});
    for (const auto& s : result.runs[0].samples) QVERIFY(s.seconds.size() == 1 && s.seconds[0] > 0);
  }
  void cancel_interrupts_a_long_point_between_chunks() {
    // One point of 4096 workers x 4 points x 2e6 steps would take tens of seconds; a pre-set cancel must stop it
    // at the first chunk boundary instead. Counted in chunks of work, not in wall-clock time.
    const CpuInfo cpu = detect_cpu(false);
    const Backend simd = cpu_backends(cpu).front();
    bs::CancelToken cancel;
    cancel.cancel();
    std::vector<float> out;
    QVERIFY_THROWS_EXCEPTION(bs::Cancelled, simd.run_point({4, 2'000'000}, 4096, Variant::Throughput, out, cancel));
  }
};

QTEST_APPLESS_MAIN(TestSweep)
#include "test_sweep.moc"
