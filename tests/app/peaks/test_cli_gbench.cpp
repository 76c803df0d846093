// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli peaks on Google Benchmark JSON: a threads:N family is a peak-table row (from files and from a
// workspace, where the sweep is derived again from the stored result set), its peak the highest mean with n and SD.
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

namespace {

const QString kCli = BENCHSCOPE_BINARY_DIR "/app/cli/benchscope-cli";
const QString kData = BENCHSCOPE_TEST_DATA_DIR "/importers/google-benchmark/";

struct Result {
  int code;
  QByteArray out, err;
};

Result cli(const QStringList& args) {
  QProcess p;
  p.start(kCli, args);
  p.waitForFinished(120000);
  return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, p.readAllStandardOutput(),
          p.readAllStandardError()};
}

QJsonObject row_named(const QJsonArray& rows, const QString& variant) {
  for (const auto& v : rows)
    if (v.toObject()["variant"].toString() == variant) return v.toObject();
  return {};
}

}  // namespace

class TestCliGbench : public QObject {
  Q_OBJECT
 private slots:
  // rotation-threads-sweep.json: means 9, 18, 32, 33 GFLOPS at 1, 2, 4, 8 threads (3 repetitions each, see
  // test_google_benchmark_json). rotation-repetitions.json: one point, mean (2.9612 + 2.9565 + 2.9255) / 3 =
  // 2.94773e10 FLOPS, SD 1.9e8 from its _stddev row; its best repetition 2.9612e10 must not be the peak.
  void peaks_of_google_benchmark_files_and_workspace() {
    QTemporaryDir dir;
    const QString ws = dir.filePath("g.bsw");
    const QStringList files{kData + "rotation-threads-sweep.json", kData + "rotation-repetitions.json"};
    QCOMPARE(cli(QStringList{"import", ws, "--quiet"} + files).code, 0);
    for (const QStringList& input : {files, QStringList{ws}}) {
      const Result peaks = cli(QStringList{"peaks"} + input + QStringList{"--json"});
      QCOMPARE(peaks.code, 0);
      const QJsonObject doc = QJsonDocument::fromJson(peaks.out).object();
      const QJsonArray rows = doc["rows"].toArray();
      QCOMPARE(rows.size(), 2);
      const QJsonObject sweep = row_named(rows, "BM_Rotation (FLOPS)");
      QCOMPARE(sweep["peak_flops"].toDouble(), 33e9);
      QCOMPARE(sweep["workers_at_peak"].toInt(), 8);
      QCOMPARE(sweep["n"].toInt(), 3);
      QCOMPARE(sweep["sd_flops"].toDouble(), 0.0);
      QVERIFY(sweep["dims"].isNull() && sweep["iterations"].isNull());
      QCOMPARE(sweep["backend"].toString(), QString("Google Benchmark"));
      QCOMPARE(sweep["origin"].toString(), QString("measured"));
      const QJsonObject single = row_named(rows, "BM_Rotate/4096 (FLOPS)");
      QVERIFY(std::abs(single["peak_flops"].toDouble() - 2.9477e10) < 1e3);
      QCOMPARE(single["n"].toInt(), 3);
      QVERIFY(std::abs(single["sd_flops"].toDouble() - 1.9e8) < 1e-3);
      QCOMPARE(doc["throughput"].toArray().size(), 0);  // both FLOPS counters are sweeps now, listed once
    }
    const Result human = cli({"peaks", ws});
    QCOMPARE(human.code, 0);
    QVERIFY2(human.out.contains("BM_Rotation (FLOPS)") && human.out.contains("33.00 GFLOPS"), human.out.constData());
  }
};

QTEST_GUILESS_MAIN(TestCliGbench)
#include "test_cli_gbench.moc"
