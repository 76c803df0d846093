// SPDX-License-Identifier: GPL-3.0-or-later
// The inference-time figure (template kind "inference", in the paper template as the optional figure
// "inference"): which bench dnn runs it draws and in what order, the bars' heights and error bars (time per image
// and its SD, batch included), the architecture-timing runs hatched and named as such, the files written through
// render_figures with their sources, and the figure skipped (and said so) when the data has no inference run.
#include <qcustomplot.h>
#include <QJsonArray>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include "../support/file_bytes.h"
#include "inference_figure.h"
#include "paper_figures.h"
#include "rendered_figures.h"

namespace {

bs::DnnRun run(const std::string& platform, const std::string& model, const std::string& backend, bool arch, int side,
               int batch, double mean_s, double sd_s, std::size_t n, const std::string& date) {
  bs::DnnRun r;
  r.platform = platform;
  r.model = model;
  r.model_hash = arch ? "builtin:" + model + ":seed1" : "sha256:" + model;
  r.backend = backend;
  r.device = backend == "cpu" ? "CPU (2 OpenCV threads)" : "GPU (OpenCL)";
  r.family = model == "yolo-n" ? "YOLOv8" : "SSD";
  r.architecture_only = arch;
  r.input_width = r.input_height = side;
  r.batch = batch;
  r.flops = 2'500'000'000LL * batch;
  r.forward = {"inference", n, mean_s, sd_s, mean_s - sd_s, mean_s + sd_s, mean_s, mean_s + sd_s};
  r.provenance.origin = bs::DataOrigin::Measured;
  r.provenance.date = date;
  return r;
}

std::vector<bs::DnnRun> runs() {
  return {
      run("vm", "mobilenet-ssd", "opencl", true, 300, 1, 2.58, 0.50, 10, "2026-11-23T10:00:00Z"),
      run("vm", "mobilenet-ssd", "cpu", true, 300, 1, 0.092, 0.0107, 20, "2026-11-23T10:00:00Z"),
      run("vm", "mobilenet-ssd", "cpu", true, 300, 1, 0.120, 0.0200, 20, "2026-11-20T09:00:00Z"),  // older
      run("vm", "yolo-n", "cpu", true, 640, 2, 0.80, 0.10, 5, "2026-11-23T10:00:00Z"),
      run("NUC", "ssd_mobilenet.onnx", "cpu", false, 300, 1, 0.050, 0.004, 20, "2026-01-01T00:00:00Z"),
  };
}

bs::FigureTemplate inference_template(std::vector<std::string> platforms = {}) {
  bs::FigureTemplate t;
  t.id = "inference";
  t.kind = "inference";
  t.x_label = "Time per image (ms)";
  t.y_scale = 1e-3;
  t.platforms = std::move(platforms);
  return t;
}

}  // namespace

class TestInferenceFigure : public QObject {
  Q_OBJECT
 private slots:
  void newest_run_per_platform_network_and_target_in_axis_order() {
    QJsonArray left_out;
    const auto shown = bs::ui::inference_figure_runs(inference_template(), runs(), left_out);
    QCOMPARE(shown.size(), std::size_t{4});
    QCOMPARE(shown[0].platform, std::string("NUC"));
    QCOMPARE(shown[1].backend, std::string("cpu"));  // vm mobilenet-ssd: cpu before opencl
    QCOMPARE(shown[1].forward.mean_s, 0.092);        // the newer of the two cpu runs
    QCOMPARE(shown[2].backend, std::string("opencl"));
    QCOMPARE(shown[3].model, std::string("yolo-n"));
    QCOMPARE(left_out.size(), 1);
    QVERIFY(left_out[0].toObject()["reason"].toString().startsWith("an older run (2026-11-20T09:00:00Z)"));
    QCOMPARE(bs::ui::inference_bar_label(shown[3]), std::string("vm\nyolo-n 640x640, batch 2"));
    // A template naming platforms keeps to them and says what it left out.
    QJsonArray out2;
    QCOMPARE(bs::ui::inference_figure_runs(inference_template({"NUC"}), runs(), out2).size(), std::size_t{1});
    QCOMPARE(out2.size(), 4);
    QVERIFY(out2[0].toObject()["reason"].toString().startsWith("not one of the figure's platforms (NUC)"));
  }

  void bars_are_the_time_per_image_with_its_sd() {
    QCustomPlot plot;
    plot.resize(400, 300);
    QJsonArray left_out;
    const QJsonArray sources = bs::ui::inference_figure(plot, inference_template(), runs(), {}, left_out);
    QCOMPARE(sources.size(), 4);
    // Series: cpu (trained model), cpu (architecture timing), opencl (architecture timing).
    std::map<QString, QCPBars*> bars;
    std::map<QCPBars*, QCPErrorBars*> errors;
    for (int i = 0; i < plot.plottableCount(); ++i) {
      if (auto* b = qobject_cast<QCPBars*>(plot.plottable(i))) bars[b->name()] = b;
      if (auto* e = qobject_cast<QCPErrorBars*>(plot.plottable(i)))
        errors[qobject_cast<QCPBars*>(e->dataPlottable())] = e;
    }
    QCOMPARE(bars.size(), std::size_t{3});
    const QString arch = ", architecture timing: no detections";
    QVERIFY(bars.count("cpu") && bars.count("cpu" + arch) && bars.count("opencl" + arch));
    QCOMPARE(bars["cpu"]->brush().style(), Qt::SolidPattern);
    QCOMPARE(bars["cpu" + arch]->brush().style(), Qt::BDiagPattern);  // hatched: no trained weights
    QCOMPARE(bars["opencl" + arch]->brush().style(), Qt::BDiagPattern);
    const auto values = [&](const QString& name) {
      QVector<double> v;
      for (auto it = bars[name]->data()->constBegin(); it != bars[name]->data()->constEnd(); ++it) v << it->value;
      return v;
    };
    const auto sds = [&](const QString& name) {
      QVector<double> v;
      QCPErrorBars* e = errors[bars[name]];
      for (int i = 0; i < e->dataCount(); ++i) v << e->data()->at(i).errorPlus;
      return v;
    };
    const auto near = [](const QVector<double>& a, const QVector<double>& b) {
      if (a.size() != b.size()) return false;
      for (int i = 0; i < a.size(); ++i)
        if (std::fabs(a[i] - b[i]) > 1e-9 * std::max(1.0, std::fabs(b[i]))) return false;
      return true;
    };
    QVERIFY(near(values("cpu"), {50}));
    QVERIFY(near(sds("cpu"), {4}));
    QVERIFY(near(values("cpu" + arch), {92, 400}));  // yolo-n: 0.8 s per batch of 2
    QVERIFY(near(sds("cpu" + arch), {10.7, 50}));
    QVERIFY(near(values("opencl" + arch), {2580}));
    QVERIFY(near(sds("opencl" + arch), {500}));
    // The legend names the series (the error bars stay out of it); the axis names the groups.
    QCOMPARE(plot.legend->itemCount(), 3);
    auto* ticker = dynamic_cast<QCPAxisTickerText*>(plot.yAxis->ticker().data());
    QVERIFY(ticker);
    QStringList ticks;
    for (const QString& s : ticker->ticks()) ticks << s;
    QCOMPARE(ticks, QStringList({"NUC\nssd_mobilenet.onnx 300x300", "vm\nmobilenet-ssd 300x300",
                                 "vm\nyolo-n 640x640, batch 2"}));
    // The values are written beside the bars, with n; the time axis leaves room for them.
    QStringList texts;
    for (int i = 0; i < plot.itemCount(); ++i)
      if (auto* t = qobject_cast<QCPItemText*>(plot.item(i))) texts << t->text();
    QVERIFY2(texts.contains(QString("92.0 ± 10.7, n = 20")), qPrintable(texts.join(" | ")));
    QVERIFY(texts.contains(QString("400.0 ± 50.0, n = 5")));
    QVERIFY(plot.xAxis->range().upper > 2580 + 500);
    QVERIFY(plot.yAxis->rangeReversed());  // the first run at the top
    // A template whose platforms have no run: no figure, a NoFigureData naming it.
    QCustomPlot empty;
    QJsonArray ignored;
    QVERIFY_THROWS_EXCEPTION(bs::ui::NoFigureData,
                             bs::ui::inference_figure(empty, inference_template({"Pi"}), runs(), {}, ignored));
  }

  // Through the paper template, as `benchscope-cli figures` and the GUI's Reproduce paper figures render it.
  void paper_template_draws_it_when_there_are_runs_and_skips_it_otherwise() {
    auto inference = bs::test::paper_figures_of_kind("inference");
    QCOMPARE(inference.size(), std::size_t{1});
    QVERIFY(inference[0].optional);
    bs::ui::FigureOptions o;
    o.formats = {"svg", "png"};
    bs::ui::FigureData d;
    d.inference_runs = runs();
    QTemporaryDir dir;
    const auto out = bs::ui::render_figures(inference, d, dir.path(), o, bs::CancelToken{});
    QVERIFY(out.files.contains(dir.filePath("inference.svg")) && out.files.contains(dir.filePath("inference.png")));
    const QByteArray svg = bs::test::bytes_of(dir.filePath("inference.svg"));
    for (const char* want : {"Time per image (ms)", "architecture timing: no detections", "yolo-n 640x640"})
      QVERIFY2(svg.contains(want), want);
    const QJsonObject f = bs::test::figures_manifest(dir)["files"].toArray()[0].toObject();
    QCOMPARE(f["figure"].toString(), QString("inference"));
    QCOMPARE(f["sources"].toArray().size(), 4);
    QCOMPARE(f["left_out"].toArray().size(), 1);
    QVERIFY2(out.contents.join('\n').contains("vm mobilenet-ssd 300x300 opencl (architecture timing) (measured)"),
             qPrintable(out.contents.join('\n')));

    QTemporaryDir none;
    const auto skipped = bs::ui::render_figures(inference, bs::ui::FigureData{}, none.path(), o, bs::CancelToken{});
    for (const QString& file : skipped.files) QVERIFY2(!file.contains("inference."), qPrintable(file));
    QVERIFY2(skipped.contents.join('\n').contains("inference: not drawn (optional figure): no bench dnn runs"),
             qPrintable(skipped.contents.join('\n')));
    QCOMPARE(bs::test::figures_manifest(none)["skipped"].toArray()[0].toObject()["figure"].toString(),
             QString("inference"));
    // Not optional (a user's template): the missing data is an error that names the figure.
    inference[0].optional = false;
    QTemporaryDir err;
    try {
      bs::ui::render_figures(inference, bs::ui::FigureData{}, err.path(), o, bs::CancelToken{});
      QFAIL("expected an error");
    } catch (const std::runtime_error& e) {
      QVERIFY2(QString(e.what()).startsWith("inference: no bench dnn runs"), e.what());
    }
  }
};

QTEST_MAIN(TestInferenceFigure)
#include "test_inference_figure.moc"
