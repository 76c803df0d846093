// SPDX-License-Identifier: GPL-3.0-or-later
// `benchscope-cli pipeline` end to end on a frame made by `benchscope-cli synth-frame`: the timing table, the
// JSON document, the figure-3 images, the run stored in a workspace, and clear errors for bad arguments and files.
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <opencv2/imgcodecs.hpp>

#include "store/workspace.h"
#include "vision/reproject/cuda_preprocess.h"

#include "../../support/cli_harness.h"

namespace {

using Result = bs::test::CliResult;
using bs::test::cli;

}  // namespace

class TestCliPipeline : public QObject {
  Q_OBJECT
  QTemporaryDir dir_;
  QString raw_, sidecar_;

 private slots:
  void initTestCase() {
    QVERIFY(dir_.isValid());
    // A quarter-size capture keeps the test quick; the sidecar carries the lens (scaled to 320 px) and the view.
    const Result r = cli({"synth-frame", "--out", dir_.filePath("f"), "--size", "320x256"});
    QVERIFY2(r.code == 0, r.err.constData());
    raw_ = dir_.filePath("f.raw");
    sidecar_ = dir_.filePath("f.json");
  }

  void table_figures_and_workspace() {
    const QString figs = dir_.filePath("figs"), ws = dir_.filePath("w.bsw");
    const Result r = cli({"pipeline", raw_, "--lens", sidecar_, "--frames", "6", "--detector", "none", "--demosaic",
                          "mhc", "--out", figs, "--workspace", ws, "--platform", "test-robot"});
    QVERIFY2(r.code == 0, r.err.constData());
    for (const char* want : {"stage", "mean ± SD (ms)", "p95 (ms)", "preprocess", "end-to-end", "throughput:", " fps",
                             "6 frames processed"})
      QVERIFY2(r.out.contains(want), qPrintable(QString(want) + "\n" + r.out));
    QVERIFY(!r.out.contains("detect "));  // --detector none: no detection stage
    // Figure 3: mosaic as grey at the sensor size, then colour images.
    const auto read = [&](const char* name) {
      return cv::imread((figs + "/" + name).toStdString(), cv::IMREAD_UNCHANGED);
    };
    const cv::Mat raw = read("fig3-raw.png"), dem = read("fig3-demosaiced.png"), rep = read("fig3-reprojected.png");
    QCOMPARE(raw.size(), cv::Size(320, 256));
    QCOMPARE(raw.channels(), 1);
    QCOMPARE(dem.size(), cv::Size(320, 256));
    QCOMPARE(dem.channels(), 3);
    QVERIFY(!rep.empty());
    QCOMPARE(rep.channels(), 3);
    // The stored run: measured, this host, the stages in seconds with n = 6.
    const bs::Workspace w(ws.toStdString());
    const auto runs = w.pipeline_runs();
    QCOMPARE(runs.size(), std::size_t{1});
    const bs::PipelineRun& run = runs[0].run;
    QCOMPARE(run.platform, std::string("test-robot"));
    QCOMPARE(run.demosaic, std::string("mhc"));
    QCOMPARE(run.frame_width, 320);
    QCOMPARE(run.provenance.origin, bs::DataOrigin::Measured);
    QVERIFY(!run.provenance.host.empty());
    QCOMPARE(run.stage("preprocess")->n, std::size_t{6});
    QVERIFY(run.stage("preprocess")->mean_s > 0 && run.stage("preprocess")->mean_s < 10);
    QVERIFY(*run.stage("preprocess")->p50_s <= *run.stage("preprocess")->p95_s);
    QVERIFY(!run.stage("detect"));
    QVERIFY(run.throughput_fps && *run.throughput_fps > 0);
  }

  void json_with_hog_detection_reimports() {
    const Result r = cli({"pipeline", raw_, "--lens", sidecar_, "--frames", "3", "--json"});
    QVERIFY2(r.code == 0, r.err.constData());
    const QJsonObject doc = QJsonDocument::fromJson(r.out).object();
    QCOMPARE(doc["format"].toString(), QString("benchscope-pipeline-v1"));
    QCOMPARE(doc["detector"].toString(), QString("hog"));
    QCOMPARE(doc["demosaic"].toString(), QString("fused"));
    const QJsonObject stages = doc["stages"].toObject();
    QCOMPARE(stages["preprocess"].toObject()["n"].toInt(), 3);
    QCOMPARE(stages["detect"].toObject()["n"].toInt(), 3);
    QCOMPARE(doc["provenance"].toObject()["origin"].toString(), QString("measured"));
    // What --json prints is a pipeline file `import` reads.
    QFile f(dir_.filePath("run.json"));
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(r.out);
    f.close();
    const Result imp = cli({"import", dir_.filePath("j.bsw"), f.fileName()});
    QVERIFY2(imp.code == 0 && imp.out.contains("1 pipeline run"), imp.out + imp.err);
  }

  void detection_workers_and_scale_are_recorded() {
    const Result r = cli({"pipeline", raw_, "--lens", sidecar_, "--frames", "5", "--detect-workers", "3",
                          "--detect-scale", "0.75", "--json"});
    QVERIFY2(r.code == 0, r.err.constData());
    const QJsonObject doc = QJsonDocument::fromJson(r.out).object();
    const QJsonObject stages = doc["stages"].toObject();
    QCOMPARE(stages["detect"].toObject()["n"].toInt(), 5);
    QCOMPARE(stages["end-to-end"].toObject()["n"].toInt(), 5);
    // The stored run says how it was made.
    QVERIFY2(doc["device"].toString().contains("3 detection workers"), qPrintable(doc["device"].toString()));
    const QString note = doc["provenance"].toObject()["note"].toString();
    QVERIFY2(note.contains("3 detection workers, detect scale 0.75"), qPrintable(note));
    // The table says it too.
    const Result t = cli({"pipeline", raw_, "--lens", sidecar_, "--frames", "2", "--detect-workers", "1"});
    QVERIFY2(t.code == 0 && t.out.contains("detection on 1 worker thread\n"), t.out + t.err);
  }

  void bench_pipeline_prints_both_throughputs() {
    // Two frames at a small scale: checks the report's shape and arithmetic inputs, not any speed.
    const Result r =
        cli({"bench", "pipeline", "--frames", "2", "--rounds", "1", "--detect-workers", "2", "--detect-scale", "0.25"});
    QVERIFY2(r.code == 0, r.err.constData());
    for (const char* want :
         {"sequential (one thread", "concurrent pipeline (capture, preprocessing, 2 detection workers)", "(n = 2)",
          "concurrent / sequential = ", "theoretical bound: ", "default threading",
          "HOG people detector at scale 0.25 (320x256)"})
      QVERIFY2(r.out.contains(want), qPrintable(QString(want) + "\n" + r.out));
  }

  void grey_png_frame() {
    // The figure's grey mosaic is itself a valid frame (PNG, one channel, pattern BGGR by default).
    const QString figs = dir_.filePath("figs2");
    QVERIFY(cli({"pipeline", raw_, "--lens", sidecar_, "--frames", "1", "--detector", "none", "--out", figs}).code ==
            0);
    const Result r = cli({"pipeline", figs + "/fig3-raw.png", "--lens", sidecar_, "--frames", "2", "--detector", "none",
                          "--demosaic", "opencv", "--policy", "drop-oldest"});
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY(r.out.contains("preprocess"));
  }

  void opencl_backend() {
    const Result r = cli(
        {"pipeline", raw_, "--lens", sidecar_, "--frames", "3", "--detector", "none", "--backend", "opencl", "--json"});
    if (r.code == 1 && r.err.contains("OpenCL:")) QSKIP(r.err.constData());  // no OpenCL device on this machine
    QVERIFY2(r.code == 0, r.err.constData());
    const QJsonObject doc = QJsonDocument::fromJson(r.out).object();
    QCOMPARE(doc["backend"].toString(), QString("opencl"));
    QVERIFY(doc["device"].toString().contains("(OpenCL)"));
    QCOMPARE(doc["stages"].toObject()["preprocess"].toObject()["n"].toInt(), 3);
  }

  void cuda_backend_runs_or_says_why() {
    // With a GPU (and nvcc at build time) the run succeeds on it; otherwise it fails at once with the reason the
    // library gives, never with a crash or a silent CPU fallback.
    const std::string why = bs::vision::cuda_preprocessing_unavailable();
    const Result r = cli(
        {"pipeline", raw_, "--lens", sidecar_, "--backend", "cuda", "--detector", "none", "--frames", "2", "--json"});
    if (why.empty()) {
      QVERIFY2(r.code == 0, r.err.constData());
      const QJsonObject doc = QJsonDocument::fromJson(r.out).object();
      QCOMPARE(doc["backend"].toString(), QString("cuda"));
      QVERIFY(doc["device"].toString().contains("(CUDA)"));
    } else {
      QCOMPARE(r.code, 1);
      QVERIFY2(QString::fromUtf8(r.err).contains("CUDA preprocessing: " + QString::fromStdString(why)),
               r.err.constData());
    }
  }

  // --synthetic: the Pipeline tab's measurement from the command line (what a robot runs for the tab, issue #44),
  // stored with the settings that made it; no frame file involved.
  void synthetic_capture_is_measured_and_stored() {
    const QString ws = dir_.filePath("synthetic.bsw");
    const Result r = cli({"pipeline", "--synthetic", "--frames", "4", "--detector", "none", "--detect-workers", "1",
                          "--platform", "Bench", "--workspace", ws});
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY2(r.out.contains("4 frames processed"), r.out.constData());
    QVERIFY2(r.err.contains("captured 4 of 4 frames"), r.err.constData());
    const bs::Workspace w(ws.toStdString(), bs::Workspace::OpenMode::ReadOnly);
    const auto runs = w.pipeline_runs();
    QCOMPARE(runs.size(), std::size_t{1});
    const bs::PipelineRun& run = runs[0].run;
    QCOMPARE(run.platform, std::string("Bench"));
    QCOMPARE(run.demosaic, std::string("fused"));
    QCOMPARE(run.detector, std::string("none"));
    QCOMPARE(run.frame_width, 1280);
    QVERIFY(!run.stage(bs::pipeline_stage::kDetect));  // no detector, no detection stage
    QCOMPARE(run.stage(bs::pipeline_stage::kPreprocess)->n, std::size_t{4});
    QVERIFY2(run.provenance.note.find("synthetic paper capture") != std::string::npos, run.provenance.note.c_str());
    QVERIFY2(run.provenance.tool.find("benchscope-cli") != std::string::npos, run.provenance.tool.c_str());
  }

  void errors() {
    struct Case {
      QStringList args;
      int code;
      const char* message;
    };
    QFile short_raw(dir_.filePath("short.raw"));
    QVERIFY(short_raw.open(QIODevice::WriteOnly));
    short_raw.write(QByteArray(100, '\0'));
    short_raw.close();
    QFile::copy(sidecar_, dir_.filePath("short.json"));
    const Case cases[] = {
        {{"pipeline", raw_}, 2, "--lens"},
        {{"pipeline", "--lens", sidecar_}, 2, "at least one frame"},
        {{"pipeline", raw_, "--lens", sidecar_, "--backend", "tpu"}, 2, "--backend"},
        {{"pipeline", raw_, "--lens", sidecar_, "--backend", "cuda", "--demosaic", "mhc"}, 2, "--demosaic bilinear"},
        {{"pipeline", raw_, "--lens", sidecar_, "--backend", "opencl", "--demosaic", "mhc"}, 2, "--demosaic bilinear"},
        {{"pipeline", raw_, "--lens", sidecar_, "--demosaic", "magic"}, 2, "--demosaic"},
        {{"pipeline", raw_, "--lens", sidecar_, "--policy", "never"}, 2, "--policy"},
        {{"pipeline", raw_, "--lens", sidecar_, "--frames", "0"}, 2, "--frames"},
        {{"pipeline", raw_, "--lens", sidecar_, "--bogus"}, 2, "--bogus"},
        {{"pipeline", raw_, "--lens", sidecar_, "--detect-workers", "0"}, 2, "--detect-workers must be a whole number"},
        {{"pipeline", raw_, "--lens", sidecar_, "--detect-workers", "1.5"},
         2,
         "--detect-workers must be a whole number"},
        {{"pipeline", raw_, "--lens", sidecar_, "--detect-workers", "9999"}, 2, "from 1 to 256"},
        {{"pipeline", raw_, "--lens", sidecar_, "--detect-workers", "two"}, 2, "--detect-workers expects a number"},
        {{"pipeline", raw_, "--lens", sidecar_, "--detect-scale", "0"}, 2, "--detect-scale must be greater than 0"},
        {{"pipeline", raw_, "--lens", sidecar_, "--detect-scale", "1.5"}, 2, "at most 1"},
        {{"pipeline", raw_, "--lens", sidecar_, "--detect-scale", "-0.5"}, 2, "--detect-scale must be"},
        {{"bench", "pipeline", "--detect-scale", "2"}, 2, "--detect-scale must be"},
        {{"bench", "pipeline", "--detect-workers", "0"}, 2, "--detect-workers must be"},
        {{"bench", "pipeline", "--frames", "1"}, 2, "--frames must be"},
        {{"pipeline", dir_.filePath("nope.raw"), "--lens", sidecar_}, 1, "nope.raw: no such file"},
        {{"pipeline", raw_, "--lens", dir_.filePath("nope.json")}, 1, "nope.json: cannot open lens file"},
        {{"pipeline", dir_.filePath("short.raw"), "--lens", sidecar_}, 1, "short.raw: is 100 bytes"},
        {{"pipeline", raw_, "--lens", "paper"}, 1, "but the lens is for 1280x1024"},
        {{"pipeline", dir_.filePath("f-truth.png"), "--lens", sidecar_}, 1, "channels"},
        {{"pipeline", raw_, "--lens", sidecar_, "--detector", dir_.filePath("missing.onnx")},
         1,
         "missing.onnx: no such model file"},
        {{"pipeline", "--synthetic", raw_}, 2, "give no frame files"},
        {{"pipeline", "--synthetic", "--lens", sidecar_}, 2, "uses the paper's lens"},
        {{"pipeline", "--synthetic", "--policy", "drop-oldest"}, 2, "leave out --policy"},
        {{"pipeline", "--synthetic", "--out", dir_.filePath("x")}, 2, "leave out --out"},
        {{"pipeline", "--synthetic", "--frames", "0"}, 2, "--frames must be"},
        {{"pipeline", "--synthetic", "--backend", "tpu"}, 2, "--backend must be"},
        {{"pipeline", "--synthetic", "--detector", dir_.filePath("missing.onnx")}, 1, "missing.onnx: no such model"},
    };
    for (const Case& c : cases) {
      const Result r = cli(c.args);
      QVERIFY2(r.code == c.code, qPrintable(c.args.join(' ') + " -> " + QString::number(r.code) + ": " + r.err));
      QVERIFY2(r.err.contains(c.message), qPrintable(c.args.join(' ') + ": " + r.err));
    }
  }
};

QTEST_GUILESS_MAIN(TestCliPipeline)
#include "test_cli_pipeline.moc"
