// SPDX-License-Identifier: GPL-3.0-or-later
// `benchscope-cli bench dnn` end to end on a built-in architecture at a small input: the table and labels, the run
// stored in a workspace with its FLOPs (recounted, and OpenCV's), the targets that are not available saying why,
// and usage errors; `platforms` then shows the stored run in its inference table.
#include <QTemporaryDir>
#include <QTest>

#include "store/workspace.h"
#include "vision/dnn_bench.h"

#include "../support/cli_harness.h"

using bs::test::cli;

class TestCliDnn : public QObject {
  Q_OBJECT
  QTemporaryDir dir_;

 private slots:
  void architecture_timing_is_stored_and_labelled() {
    const QString ws = dir_.filePath("dnn.bsw");
    const auto r = cli({"bench", "dnn", "--arch", "mobilenet-ssd", "--input", "128x128", "--runs", "3", "--backend",
                        "all", "--platform", "robot", "--workspace", ws});
    QVERIFY2(r.code == 0, r.err.constData());
    const QString out = QString::fromUtf8(r.out);
    QVERIFY2(out.contains("architecture timing: no detections"), r.out.constData());
    QVERIFY(out.contains("load average before"));
    // Targets that cannot run here are named with the reason (on Debian's OpenCV at least CUDA).
    for (const bs::vision::DnnTarget& t : bs::vision::dnn_targets())
      if (!t.available)
        QVERIFY2(out.contains(QString::fromStdString("target " + t.id + ": not available: " + t.why_not)),
                 r.out.constData());
    const bs::Workspace w(ws.toStdString());
    const auto runs = w.dnn_runs();
    QVERIFY(!runs.empty());
    const bs::DnnRun& d = runs.front().run;
    QCOMPARE(d.platform, std::string("robot"));
    QCOMPARE(d.model, std::string("mobilenet-ssd"));
    QVERIFY(d.architecture_only);
    QCOMPARE(d.input_width, 128);
    QCOMPARE(d.forward.n, std::size_t{3});
    QVERIFY(d.forward.mean_s > 0 && d.forward.p95_s);
    QVERIFY(d.flops > 0 && d.opencv_flops > d.flops);  // OpenCV counts depthwise convolutions as full ones
    QCOMPARE(d.model_hash, std::string("builtin:mobilenet-ssd:seed1"));
    // The Platforms table of the CLI shows it beside the paper's platforms.
    const auto imp = cli({"import", ws, BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018"});
    QVERIFY2(imp.code == 0, imp.err.constData());
    const auto p = cli({"platforms", ws});
    QVERIFY2(p.code == 0, p.err.constData());
    QVERIFY2(
        p.out.contains("Detection network inference") && p.out.contains("mobilenet-ssd (SSD), architecture timing"),
        p.out.constData());
  }

  void usage_errors() {
    auto r = cli({"bench", "dnn", "--arch", "resnet"});
    QCOMPARE(r.code, 2);
    QVERIFY(r.err.contains("mobilenet-ssd or yolo-n"));
    r = cli({"bench", "dnn", "--arch", "yolo-n", "--input", "300x300", "--runs", "1"});
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains("multiples of 32"), r.err.constData());
    r = cli({"bench", "dnn", "--model", dir_.filePath("missing.onnx")});
    QCOMPARE(r.code, 1);
    QVERIFY(r.err.contains("missing.onnx"));
    r = cli({"bench", "dnn", "--model", "a.onnx", "--arch", "yolo-n"});
    QCOMPARE(r.code, 2);
    if (!bs::vision::dnn_target("cuda").available) {
      r = cli({"bench", "dnn", "--backend", "cuda", "--arch", "yolo-n", "--input", "64x64"});
      QCOMPARE(r.code, 1);
      QVERIFY(r.out.contains("target cuda: not available"));
    }
  }
};

QTEST_GUILESS_MAIN(TestCliDnn)
#include "test_cli_dnn.moc"
