// SPDX-License-Identifier: GPL-3.0-or-later
// `benchscope-cli roofline` on the paper's sample data: every device's ceiling, the rotation kernel's runs, and
// the NUC's and Jetson's preprocessing stages placed at their modelled intensity and measured throughput.
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

#include "../../support/cli_harness.h"

using namespace bs::test;  // the CLI harness (run_cli, kPaper) and the readers of its output

class TestCliRoofline : public QObject {
  Q_OBJECT
 private slots:
  void paper_json() {
    QByteArray out;
    QCOMPARE(run_cli({"roofline", kPaper, "--json"}, &out), 0);
    const QJsonObject doc = QJsonDocument::fromJson(out).object();
    QCOMPARE(doc["format"].toString(), QString("benchscope-roofline"));
    QCOMPARE(doc["ceilings"].toArray().size(), 8);  // 4 CPUs, 4 GPUs
    QVERIFY(doc["rotation"].toArray().size() >= 8);
    const QJsonArray stages = doc["stages"].toArray();
    QCOMPARE(stages.size(), 2);
    const double ops = 35.0 * 1280 * 1024;  // bilinear demosaic 8 + reprojection 27 ops per pixel
    QStringList platforms;
    for (const auto v : stages) {
      const QJsonObject s = v.toObject();
      platforms << s["platform"].toString();
      QCOMPARE(s["ops_per_frame"].toDouble(), ops);
      QCOMPARE(s["bytes_per_frame"].toDouble(), 16.0 * 1280 * 1024);
      QCOMPARE(s["intensity"].toDouble(), 35.0 / 16.0);
      const double mean = s["time_s"].toObject()["mean"].toDouble();
      QVERIFY(std::fabs(s["achieved"].toDouble() - ops / mean) < 1);
      QCOMPARE(s["origin"].toString(), QString("reconstructed"));
      QVERIFY(s["source"].toString().contains("pipeline-"));
      if (s["platform"] == "NUC") {
        QCOMPARE(mean, 0.00621);
        QCOMPARE(s["device"].toString(), QString("NUC GPU (Iris Plus 650)"));
      }
    }
    platforms.sort();
    QCOMPARE(platforms, QStringList({"Jetson TX2", "NUC"}));
  }
  void paper_text() {
    QByteArray out;
    QCOMPARE(run_cli({"roofline", kPaper}, &out), 0);
    QVERIFY2(out.contains("Preprocessing stages") && out.contains("6.21 \xC2\xB1 0.99 (n = 500)") &&
                 out.contains("7.39 Gop/s"),
             out.constData());
  }
  void usage() { QCOMPARE(run_cli({"roofline"}), 2); }
};

QTEST_GUILESS_MAIN(TestCliRoofline)
#include "test_cli_roofline.moc"
