// SPDX-License-Identifier: GPL-3.0-or-later
// `benchscope-cli compare` as a lab's CI would run it: a 10 % slower build with 8 repetitions per point fails with
// exit code 3; the same build measured again (noise only) passes with 0; --json carries the verdicts.
#include <random>

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include "../../support/cli_harness.h"

namespace {

using bs::test::run_cli;

// A run JSON v1 file with one OpenCL run, 8 repetitions per worker count, times scaled by `slowdown`.
QString write_run(const QString& path, double slowdown, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.01);
  QJsonArray samples;
  for (int w : {1024, 2048, 4096}) {
    QJsonArray seconds;
    for (int k = 0; k < 8; ++k)
      seconds.append(1e-3 * w / 1024.0 * (w == 4096 ? 0.8 : 1.0) * (1 + slowdown) * (1 + noise(rng)));
    samples.append(QJsonObject{{"workers", w}, {"seconds", seconds}});
  }
  const QJsonObject run{{"platform", "robot"},    {"device", "GPU"},
                        {"device_kind", "gpu"},   {"backend", "OpenCL"},
                        {"kernel", "rotation2d"}, {"params", QJsonObject{{"dims", 4}, {"iterations", 40000}}},
                        {"samples", samples}};
  QFile f(path);
  if (!f.open(QIODevice::WriteOnly)) return {};
  f.write(QJsonDocument(QJsonObject{{"format", "benchscope-run"}, {"version", 1}, {"runs", QJsonArray{run}}}).toJson());
  return path;
}

}  // namespace

class TestCliCompare : public QObject {
  Q_OBJECT
 private slots:
  void slowdown_fails_noise_passes() {
    QTemporaryDir dir;
    const QString base = write_run(dir.filePath("base.json"), 0.0, 1);
    const QString again = write_run(dir.filePath("again.json"), 0.0, 2);
    const QString slow = write_run(dir.filePath("slow.json"), 0.10, 3);
    QByteArray out;
    QCOMPARE(run_cli({"compare", base, slow}, &out), 3);
    QVERIFY2(out.contains("regression") && out.contains("1 regressions"), out.constData());
    QCOMPARE(run_cli({"compare", base, again}, &out), 0);
    QVERIFY2(out.contains("0 regressions"), out.constData());
    // A 20 % threshold lets the 10 % slowdown through.
    QCOMPARE(run_cli({"compare", base, slow, "--threshold", "20%"}, &out), 0);
    QCOMPARE(run_cli({"compare", base, slow, "--json"}, &out), 3);
    const QJsonObject doc = QJsonDocument::fromJson(out).object();
    QCOMPARE(doc["format"].toString(), QString("benchscope-compare"));
    QCOMPARE(doc["regressions"].toInt(), 1);
    const QJsonObject row = doc["rows"].toArray().at(0).toObject();
    QCOMPARE(row["verdict"].toString(), QString("regression"));
    QVERIFY(row["key"].toString().endsWith("W=4096"));
    QVERIFY(row["change"].toDouble() < -0.05);
    QCOMPARE(row["a"].toObject()["n"].toInt(), 8);
  }
  void usage_errors() {
    QCOMPARE(run_cli({"compare", "only-one"}), 2);
    QCOMPARE(run_cli({"compare", "a", "b", "--threshold", "lots"}), 2);
  }
};

QTEST_GUILESS_MAIN(TestCliCompare)
#include "test_cli_compare.moc"
