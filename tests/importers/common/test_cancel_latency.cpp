// SPDX-License-Identifier: GPL-3.0-or-later
// Cancellation stops long work promptly and leaves nothing behind: parsing a large log, and writing it into a
// workspace. Deterministic: the cancel comes from the work's own progress reports (the k-th of them, as the GUI's
// Cancel button lands between two), and promptness is counted in work done after it (reports, each a bounded amount
// of work: 1024 lines read, one chunk of samples stored), never timed, so a loaded machine cannot fail it.
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include "store/workspace.h"
#include "workspace/registry.h"

namespace {

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

// Runs `work` once to completion counting its progress reports (n), then again cancelling at the reports k = 0,
// n/3 and 2n/3. Each cancelled run must throw Cancelled before it reports again: the work between two reports is
// the most a cancel can cost. Returns what went wrong (empty: nothing).
template <class Work>
QString check_cancel_points(Work work) {
  int n = 0;
  {
    bs::CancelToken counting;
    counting.set_progress([&](double, std::string_view) { ++n; });
    work(counting);
  }
  if (n < 6) return QString("only %1 progress reports: too few to cancel in between").arg(n);
  for (const int k : {0, n / 3, 2 * n / 3}) {
    bs::CancelToken cancel;
    int reports = 0, after_cancel = 0;
    cancel.set_progress([&](double, std::string_view) {
      if (reports > k) ++after_cancel;
      if (reports++ == k) cancel.cancel();
    });
    bool stopped = false;
    try {
      work(cancel);
    } catch (const bs::Cancelled&) {
      stopped = true;
    }
    const QString at = QString("cancel at report %1 of %2").arg(k).arg(n);
    if (!stopped) return at + ": the work ran to its end";
    if (after_cancel != 0) return at + QString(": %1 more reports after it").arg(after_cancel);
  }
  return {};
}

}  // namespace

class TestCancelLatency : public QObject {
  Q_OBJECT
 private slots:
  void parsing_a_large_log_stops_promptly() {
    QTemporaryDir dir;
    const QString path = dir.filePath("big.csv");
    write_big_log(path, 200'000);
    const QString wrong =
        check_cancel_points([&](const bs::CancelToken& c) { (void)bs::import_file(path.toStdString(), c); });
    QVERIFY2(wrong.isEmpty(), qPrintable(wrong));
  }

  void writing_a_large_import_stops_promptly_and_leaves_nothing() {
    QTemporaryDir dir;
    const QString log = dir.filePath("big.csv");
    write_big_log(log, 200'000);
    bs::ImportBatch batch = bs::import_file(log.toStdString(), bs::CancelToken{});
    // Several traces, so that cancels land in the first, a middle and a late one.
    const bs::PowerTrace one = batch.power_traces.at(0);
    for (int i = 1; i < 6; ++i) batch.power_traces.push_back(one);
    int round = 0;
    const std::string ws_path = dir.filePath("w.bsw").toStdString();
    const QString wrong = check_cancel_points([&](const bs::CancelToken& c) {
      bs::Workspace ws(ws_path);
      ws.add_import(batch, "hash-" + std::to_string(round++), &c);
    });
    QVERIFY2(wrong.isEmpty(), qPrintable(wrong));
    // Only the uncancelled run left an import, whole.
    bs::Workspace ws(ws_path);
    QCOMPARE(ws.imports().size(), std::size_t(1));
    QCOMPARE(ws.power_traces().size(), batch.power_traces.size());
    QCOMPARE(ws.integrity_check(), std::string("ok"));
  }
};

QTEST_GUILESS_MAIN(TestCancelLatency)
#include "test_cancel_latency.moc"
