// SPDX-License-Identifier: GPL-3.0-or-later
// `benchscope-cli bench dnn` end to end on a built-in architecture at a small input: the table and labels, the run
// stored in a workspace with its FLOPs (recounted, and OpenCV's), the targets that are not available saying why,
// and usage errors; `platforms` then shows the stored run in its inference table.
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <filesystem>

#include <opencv2/imgcodecs.hpp>

#include "store/workspace.h"
#include "vision/pipeline/dnn_bench.h"

#include "../../support/cli_harness.h"
#include "../../support/sysfs_fixture.h"

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
#ifdef BENCHSCOPE_WITH_FIGURES_TEST
    // `figures` draws the inference-time figure from the stored runs (skipped for data without any).
    const QString figs = dir_.filePath("figs");
    const auto f = cli({"figures", ws, "--out", figs, "--format", "svg"});
    QVERIFY2(f.code == 0, f.err.constData());
    QVERIFY2(f.out.contains("inference.svg"), f.out.constData());
    const QByteArray svg = bs::test::bytes_of(figs + "/inference.svg");
    QVERIFY(svg.contains("architecture timing: no detections") && svg.contains("mobilenet-ssd 128x128"));
    QVERIFY2(f.err.contains("inference: robot mobilenet-ssd 128x128 cpu (architecture timing) (measured)"),
             f.err.constData());
#endif
  }

  // A real ONNX file (tests/data/dnn/yolov8-known.onnx, SOURCES there): `bench dnn --model` finds its family and
  // input size, times it and stores it with the file's hash; `pipeline --detector` runs it as the detection stage
  // and figure 3 shows its two boxes where the fixture's known output puts them.
  void onnx_model_file_is_timed_and_detects() {
    const QString model = BENCHSCOPE_TEST_DATA_DIR "/dnn/yolov8-known.onnx";
    const QString ws = dir_.filePath("onnx.bsw");
    const auto r = cli(
        {"bench", "dnn", "--model", model, "--runs", "2", "--backend", "cpu", "--platform", "lab", "--workspace", ws});
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY2(r.out.contains("yolov8-known.onnx (YOLOv8 output), input 640x640, batch 1"), r.out.constData());
    QVERIFY(!r.out.contains("architecture timing"));
    const bs::Workspace w(ws.toStdString());
    const auto runs = w.dnn_runs();
    QCOMPARE(runs.size(), std::size_t{1});
    const bs::DnnRun& d = runs.front().run;
    QCOMPARE(d.model, std::string("yolov8-known.onnx"));
    QCOMPARE(d.family, std::string("YOLOv8"));
    QVERIFY(!d.architecture_only);
    QCOMPARE(d.model_hash, bs::file_content_hash(model.toStdString()));
    QCOMPARE(d.forward.n, std::size_t{2});
    // The 1x1 convolution: 48 outputs x (2 x 3 multiply-adds + 1 bias add) = 336, plus the pooling's share.
    QVERIFY2(d.flops >= 336, std::to_string(d.flops).c_str());

    QVERIFY(cli({"synth-frame", "--out", dir_.filePath("f"), "--size", "320x256"}).code == 0);
    const QString figs = dir_.filePath("figs");
    const auto p = cli({"pipeline", dir_.filePath("f.raw"), "--lens", dir_.filePath("f.json"), "--frames", "2",
                        "--detector", model, "--detect-scale", "1", "--detect-workers", "1", "--out", figs});
    QVERIFY2(p.code == 0, p.err.constData());
    const cv::Mat fig = cv::imread((figs + "/fig3-reprojected.png").toStdString(), cv::IMREAD_COLOR);
    QCOMPARE(fig.size(), cv::Size(1280, 1024));  // the sidecar's view
    // The view (1280x1024) is letterboxed into 640x640: scaled by 0.5 to 640x512 at y = 64, so x doubles and
    // y = (y - 64) x 2. Anchor 0 -> x 512..768, y 448..576; anchor 2 -> x 160..240, y 232..392. draw_detections
    // draws each edge 3 px wide in pure green.
    const auto green = [&](int x, int y) { return fig.at<cv::Vec3b>(y, x) == cv::Vec3b(0, 255, 0); };
    for (const cv::Rect& b :
         {cv::Rect(cv::Point(512, 448), cv::Point(768, 576)), cv::Rect(cv::Point(160, 232), cv::Point(240, 392))}) {
      const int cx = b.x + b.width / 2, cy = b.y + b.height / 2;
      QVERIFY2(green(b.x, cy) && green(b.x + b.width, cy) && green(cx, b.y) && green(cx, b.y + b.height),
               qPrintable(QString("box %1,%2 %3x%4").arg(b.x).arg(b.y).arg(b.width).arg(b.height)));
    }
  }

  // --json: stdout is the document alone (the tables go to stderr), one row per target that ran with every
  // figure of the table, nothing rounded; the targets that could not run say why. With a fixture power sensor
  // (constant 3.96 W) the energy per inference is there; without one it is null.
  void json_rows() {
    QTemporaryDir sys;
    const std::filesystem::path root = sys.path().toStdString();
    bs::test::ina3221x_channel(root, "6-0040", 0, "POM_5V_IN", 3960, 792, 5000);
    bs::test::ina3221x_channel(root, "6-0040", 1, "POM_5V_CPU", 1068, 213, 5000);
    for (const bool power : {false, true}) {
      QStringList args{"bench", "dnn", "--arch", "mobilenet-ssd", "--input", "96x96", "--runs", "12", "--json"};
      if (power)
        args << "--power"
             << "auto"
             << "--sysfs-root" << sys.path() << "--power-interval-ms"
             << "5";
      QProcess p;
      QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
      env.insert("BENCHSCOPE_NVML_LIBRARY", "none");  // the fixture's sensor only, whatever GPU is here
      p.setProcessEnvironment(env);
      p.start(bs::test::kCli, args);
      QVERIFY(p.waitForFinished(300000));
      const QByteArray out = p.readAllStandardOutput(), err = p.readAllStandardError();
      QVERIFY2(p.exitCode() == 0, err.constData());
      QJsonParseError pe;
      const QJsonObject doc = QJsonDocument::fromJson(out, &pe).object();
      QVERIFY2(pe.error == QJsonParseError::NoError, out.constData());
      QVERIFY2(err.contains("forward mean ± SD (ms)") && err.contains("load average after"), err.constData());
      QCOMPARE(doc["format"].toString(), QString("benchscope-dnn-bench"));
      QCOMPARE(doc["version"].toInt(), 1);
      QCOMPARE(doc["warmup_passes"].toInt(), 2);
      QVERIFY(doc["cpu"].toObject()["ceiling_gflops"].toDouble() > 0);
      int available = 0;
      QStringList unavailable;
      for (const bs::vision::DnnTarget& t : bs::vision::dnn_targets()) {
        if (t.available)
          ++available;
        else
          unavailable << QString::fromStdString(t.id + ": " + t.why_not);
      }
      QStringList listed;
      for (const auto& v : doc["unavailable"].toArray())
        listed << v.toObject()["backend"].toString() + ": " + v.toObject()["why_not"].toString();
      QCOMPARE(listed, unavailable);
      const QJsonArray runs = doc["runs"].toArray();
      QCOMPARE(runs.size(), available);
      const QJsonObject r = runs[0].toObject();
      QCOMPARE(r["backend"].toString(), QString("cpu"));
      QCOMPARE(r["model"].toString(), QString("mobilenet-ssd"));
      QCOMPARE(r["family"].toString(), QString("SSD"));
      QVERIFY(r["architecture_only"].toBool());
      QCOMPARE(r["label"].toString(), QString("architecture timing: no detections"));
      QCOMPARE(r["input"].toObject()["width"].toInt(), 96);
      QCOMPARE(r["batch"].toInt(), 1);
      QCOMPARE(r["n"].toInt(), 12);
      const QJsonObject f = r["forward_s"].toObject();
      const double mean = f["mean"].toDouble();
      QVERIFY(mean > 0 && f["sd"].toDouble() >= 0);
      QVERIFY(f["min"].toDouble() <= f["p50"].toDouble() && f["p50"].toDouble() <= f["p95"].toDouble() &&
              f["p95"].toDouble() <= f["max"].toDouble());
      QVERIFY(f["min"].toDouble() <= mean && mean <= f["max"].toDouble());
      QCOMPARE(r["per_image_s"].toDouble(), mean);
      QVERIFY(std::fabs(r["inferences_per_s"].toDouble() * mean - 1) < 1e-9);
      const double flops = r["flops"].toDouble();
      QVERIFY(flops > 0 && r["opencv_flops"].toDouble() > flops);  // depthwise counted as full convolutions
      QCOMPARE(r["flops_per_image"].toDouble(), flops);
      QVERIFY(std::fabs(r["achieved_gflops"].toDouble() - flops / mean / 1e9) < 1e-6 * flops / mean / 1e9);
      // The published count is at the architecture's standard input (300x300): 1.2 G multiply-adds.
      QCOMPARE(r["published"].toObject()["gflops_per_image"].toDouble(), 2.4);
      QVERIFY(r["ceiling_gflops"].toDouble() > 0);
      QVERIFY(std::fabs(r["fraction_of_ceiling"].toDouble() -
                        r["achieved_gflops"].toDouble() / r["ceiling_gflops"].toDouble()) < 1e-9);
      QVERIFY(r["cores_busy"].toDouble() > 0);
      if (!power) {
        QVERIFY(r["energy_per_inference_j"].isNull() && r["inferences_per_wh"].isNull() &&
                doc["power_sensor"].isNull());
        continue;
      }
      // 3.96 W over the timed passes: energy per inference = 3.96 W x the time per pass (and a little between).
      QVERIFY2(std::fabs(r["mean_power_w"].toDouble() - 3.96) < 1e-6, out.constData());
      const double e = r["energy_per_inference_j"].toDouble();
      QVERIFY2(e >= 3.96 * mean * 0.9 && e <= 3.96 * f["max"].toDouble() * 1.5, out.constData());
      QVERIFY(std::fabs(r["inferences_per_wh"].toDouble() * e - 3600) < 1e-6);
    }
  }

  // OpenCV prints an OpenCL program's build log on stdout; with --json stdout must still be the document alone.
  // Run where OpenCV's dnn can use an OpenCL device (PoCL's CPU device counts when allowed); skipped elsewhere.
  void json_stays_clean_on_opencl() {
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("OPENCV_OPENCL_DEVICE", ":CPU:");
    env.insert("OPENCV_DNN_OPENCL_ALLOW_ALL_DEVICES", "1");
    p.setProcessEnvironment(env);
    p.start(bs::test::kCli, {"bench", "dnn", "--arch", "mobilenet-ssd", "--input", "64x64", "--runs", "1", "--backend",
                             "opencl", "--json"});
    QVERIFY(p.waitForFinished(300000));
    const QByteArray out = p.readAllStandardOutput(), err = p.readAllStandardError();
    if (p.exitCode() == 1 && err.contains("no requested dnn target is available"))
      QSKIP("no OpenCL device OpenCV's dnn can use here");
    QVERIFY2(p.exitCode() == 0, err.constData());
    QJsonParseError pe;
    const QJsonObject doc = QJsonDocument::fromJson(out, &pe).object();
    QVERIFY2(pe.error == QJsonParseError::NoError, out.constData());
    QCOMPARE(doc["runs"].toArray().size(), 1);
    QCOMPARE(doc["runs"].toArray()[0].toObject()["backend"].toString(), QString("opencl"));
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
