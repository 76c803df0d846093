// SPDX-License-Identifier: GPL-3.0-or-later
// Cancellation stops long work promptly and leaves nothing behind: parsing a large log, and writing it into a
// workspace. Promptness is measured as a ratio to the time the whole operation takes (the 200 ms on a
// multi-second operation), so a loaded machine slows both sides alike instead of making the test flaky.
#include <chrono>
#include <future>
#include <thread>

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include "common/importer.h"
#include "store/workspace.h"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

void write_big_log(const QString& path, int rows) {
  QFile f(path);
  QVERIFY(f.open(QIODevice::WriteOnly));
  QByteArray chunk;
  f.write("# platform: NUC\n# supply_voltage_V: 16\ntime_s,current_A\n");
  for (int i = 0; i < rows; ++i) {
    chunk += QByteArray::number(i * 1e-4, 'f', 4) + ',' + QByteArray::number(2.0 + (i % 977) * 1e-3, 'f', 3) + '\n';
    if (chunk.size() > (1 << 20)) {
      f.write(chunk);
      chunk.clear();
    }
  }
  f.write(chunk);
}

// Runs `work(cancel)` twice to completion (warm-up, then timed) to learn its duration T, then again cancelling at
// fractions of T. Returns the worst ratio (time from cancel() to the work ending) / T over the runs that were
// cancelled.
template <class Work>
double worst_cancel_ratio(Work work, int* cancelled_runs) {
  bs::CancelToken never;
  work(never);  // warm-up: the first run pays for page faults, file creation and cold caches
  const auto t_full = Clock::now();
  work(never);
  const double full = seconds_since(t_full);
  double worst = 0;
  *cancelled_runs = 0;
  for (double fraction : {0.1, 0.2, 0.3}) {
    bs::CancelToken cancel;
    auto done = std::async(std::launch::async, [&] {
      try {
        work(cancel);
        return false;
      } catch (const bs::Cancelled&) {
        return true;
      }
    });
    std::this_thread::sleep_for(std::chrono::duration<double>(full * fraction));
    const auto t_cancel = Clock::now();
    cancel.cancel();
    const bool was_cancelled = done.get();
    const double latency = seconds_since(t_cancel);
    if (!was_cancelled) continue;  // finished before the cancel arrived: nothing to measure
    ++*cancelled_runs;
    // Prompt means within a tenth of the whole operation, or within the 200 ms when the operation is so
    // short that a tenth of it is below the scheduler's jitter.
    worst = std::max(worst, latency < 0.2 ? 0.0 : latency / full);
    qInfo("cancel at %.0f %% of %.3f s: stopped after %.1f ms", fraction * 100, full, latency * 1e3);
  }
  return worst;
}

}  // namespace

class TestCancelLatency : public QObject {
  Q_OBJECT
 private slots:
  void parsing_a_large_log_stops_promptly() {
    QTemporaryDir dir;
    const QString path = dir.filePath("big.csv");
    write_big_log(path, 1'500'000);
    int cancelled = 0;
    const double ratio =
        worst_cancel_ratio([&](const bs::CancelToken& c) { (void)bs::import_file(path.toStdString(), c); }, &cancelled);
    QVERIFY2(cancelled >= 2, "the cancels did not reach a running parse");
    QVERIFY2(ratio < 0.1, qPrintable(QString("cancel took %1 of the whole parse").arg(ratio)));
  }

  void writing_a_large_import_stops_promptly_and_leaves_nothing() {
    QTemporaryDir dir;
    const QString log = dir.filePath("big.csv");
    write_big_log(log, 1'500'000);
    bs::ImportBatch batch = bs::import_file(log.toStdString(), bs::CancelToken{});
    // Many traces make the write long enough to cancel in the middle (each is one row plus its channels).
    const bs::PowerTrace one = batch.power_traces.at(0);
    for (int i = 1; i < 12; ++i) batch.power_traces.push_back(one);
    int round = 0;
    const std::string ws_path = dir.filePath("w.bsw").toStdString();
    int cancelled = 0;
    const double ratio = worst_cancel_ratio(
        [&](const bs::CancelToken& c) {
          bs::Workspace ws(ws_path);
          ws.add_import(batch, "hash-" + std::to_string(round++), &c);
        },
        &cancelled);
    QVERIFY2(cancelled >= 2, "the cancels did not reach a running write");
    QVERIFY2(ratio < 0.1, qPrintable(QString("cancel took %1 of the whole write").arg(ratio)));
    // Only the uncancelled runs left an import, each whole.
    bs::Workspace ws(ws_path);
    QCOMPARE(ws.imports().size(), std::size_t(2 + 3 - cancelled));
    QCOMPARE(ws.power_traces().size(), ws.imports().size() * batch.power_traces.size());
    QCOMPARE(ws.integrity_check(), std::string("ok"));
  }
};

QTEST_GUILESS_MAIN(TestCancelLatency)
#include "test_cancel_latency.moc"
