// SPDX-License-Identifier: GPL-3.0-or-later
// `figures` on the paper's sample data: every figure in every format, valid and at the journal size (PDF page in
// mm, one page, fonts embedded; SVG parses and keeps its labels as text; PNG pixels = dpi x size), the series and
// labels each figure must show, the tables' published numbers, figures.json, cancellation and a template whose data is
// missing.
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QJsonArray>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <QXmlStreamReader>

#include <qcustomplot.h>
#include <set>

#include "../support/file_bytes.h"
#include "../support/paper_sample.h"
#include "device_palette.h"
#include "paper_figures.h"
#include "rendered_figures.h"
#include "workspace/registry.h"

namespace {

constexpr double kPtPerMm = 72.0 / 25.4;

// The first page's MediaBox [x0 y0 x1 y1] in points, and the number of page objects.
struct PdfInfo {
  QSizeF page_pt;
  int pages = 0;
  bool fonts_embedded = false;
};

PdfInfo pdf_info(const QByteArray& pdf) {
  PdfInfo info;
  const QString text = QString::fromLatin1(pdf);
  const auto box =
      QRegularExpression(R"(/MediaBox\s*\[\s*([-\d.]+)\s+([-\d.]+)\s+([-\d.]+)\s+([-\d.]+)\s*\])").match(text);
  if (box.hasMatch())
    info.page_pt = QSizeF(box.captured(3).toDouble() - box.captured(1).toDouble(),
                          box.captured(4).toDouble() - box.captured(2).toDouble());
  info.pages = static_cast<int>(text.count(QRegularExpression(R"(/Type\s*/Page\b(?!s))")));
  info.fonts_embedded = text.contains("/FontFile2") || text.contains("/FontFile3") || text.contains("/FontFile ");
  return info;
}

// All text of an SVG's <text> elements; empty string and `ok` false when it does not parse.
QString svg_text(const QByteArray& svg, bool& ok) {
  QXmlStreamReader xml(svg);
  QString all;
  bool in_text = false;
  while (!xml.atEnd()) {
    xml.readNext();
    if (xml.isStartElement() && xml.name() == QLatin1String("text")) in_text = true;
    if (xml.isEndElement() && xml.name() == QLatin1String("text")) in_text = false;
    if (xml.isCharacters() && in_text) all += xml.text().toString() + QLatin1Char(' ');
  }
  ok = !xml.hasError();
  return all;
}

bs::ui::FigureData paper_data() {
  const auto sample = bs::test::load_paper_sample();
  bs::ui::FigureData d;
  d.runs = sample.runs;
  d.traces = sample.traces;
  for (const auto& r : d.runs) d.colors.try_emplace({r.platform, r.device}, static_cast<int>(d.colors.size()));
  return d;
}

}  // namespace

class TestPaperFigures : public QObject {
  Q_OBJECT
  QTemporaryDir dir_;
  bs::ui::FigureOptions options_;
  QStringList files_;

  double listed_height_mm(const QString& id) {
    const QJsonObject doc = bs::test::figures_manifest(dir_);
    for (const auto& v : doc["files"].toArray())
      if (v.toObject()["file"].toString() == id + ".pdf") return v.toObject()["height_mm"].toDouble();
    return -1;
  }

 private slots:
  void initTestCase() {
    QVERIFY(dir_.isValid());
    options_.formats = {"pdf", "svg", "png"};
    const auto templates = bs::load_figure_templates(bs::ui::paper_template_path().toStdString());
    QCOMPARE(templates.size(), std::size_t{8});  // fig1a ... fig4, the optional inference and headroom figures
    int calls = 0;
    files_ = bs::ui::render_figures(templates, paper_data(), dir_.path(), options_, bs::CancelToken{},
                                    [&](int, int, const QString&) { ++calls; })
                 .files;
    QVERIFY(calls >= 7);
  }

  void every_figure_in_every_format() {
    for (const char* id : {"fig1a", "fig1b", "fig2a", "fig2b", "fig3", "fig4"})
      for (const char* ext : {"pdf", "svg", "png"}) {
        const QString path = dir_.filePath(QString("%1.%2").arg(id, ext));
        QVERIFY2(files_.contains(path), qPrintable(path));
        QVERIFY2(QFileInfo(path).size() > 1000, qPrintable(path));
      }
    for (const char* name :
         {"table1.tex", "table1.csv", "table2.tex", "table2.csv", "platforms.tex", "platforms.csv", "figures.json"})
      QVERIFY2(files_.contains(dir_.filePath(name)), name);
  }

  void pdf_pages_at_lncs_width_with_embedded_fonts() {
    for (const char* id : {"fig1a", "fig1b", "fig2a", "fig2b", "fig3", "fig4"}) {
      const QByteArray pdf = bs::test::bytes_of(dir_.filePath(QString(id) + ".pdf"));
      QVERIFY(pdf.startsWith("%PDF-"));
      const PdfInfo info = pdf_info(pdf);
      QCOMPARE(info.pages, 1);
      QVERIFY2(std::abs(info.page_pt.width() / kPtPerMm - 122.0) < 0.6,
               qPrintable(QString::number(info.page_pt.width())));
      QVERIFY(info.page_pt.height() > 20 * kPtPerMm && info.page_pt.height() < 122 * kPtPerMm);
      QVERIFY(std::abs(info.page_pt.height() / kPtPerMm - listed_height_mm(id)) < 0.6);  // as figures.json says
      QVERIFY2(info.fonts_embedded, id);  // text stays text, in an embedded font
    }
  }

  void svg_parses_and_keeps_labels_as_text() {
    const auto expect = [this](const char* id, const QStringList& needles) {
      bool ok = false;
      const QString text = svg_text(bs::test::bytes_of(dir_.filePath(QString(id) + ".svg")), ok);
      QVERIFY2(ok, id);
      for (const QString& n : needles) QVERIFY2(text.contains(n), qPrintable(QString("%1 lacks '%2'").arg(id, n)));
    };
    expect("fig1a", {"Workers W", "FLOPS (TFLOPS)", "GTX1080Ti, CUDA", "GTX1080Ti, OpenCL", "Jetson GPU, CUDA"});
    expect("fig1b", {"D = 1", "D = 2", "D = 4", "Jetson"});
    expect("fig2a", {"Tasks", "FLOPS (GFLOPS)"});
    expect("fig4", {"Time (s)", "Current (A)", "NUC", "Jetson TX2"});
    expect("fig3", {"raw Bayer mosaic", "demosaiced", "reprojected"});
  }

  void png_pixels_match_dpi_and_size() {
    for (const char* id : {"fig1a", "fig4", "fig3"}) {
      const QImage img(dir_.filePath(QString(id) + ".png"));
      QVERIFY(!img.isNull());
      const double expected_w = 122.0 / 25.4 * options_.dpi;
      QVERIFY2(std::abs(img.width() - expected_w) <= 3, qPrintable(QString("%1: %2 px").arg(id).arg(img.width())));
      QVERIFY(std::abs(img.dotsPerMeterX() * 0.0254 - options_.dpi) < 1);
    }
    const QImage fig1a(dir_.filePath("fig1a.png"));
    QVERIFY(std::abs(fig1a.height() - listed_height_mm("fig1a") / 25.4 * options_.dpi) <= 3);
    QVERIFY(fig1a.height() > 122.0 * 0.62 / 25.4 * options_.dpi);  // axes at 0.62 x width, plus the legend below
  }

  void fig1b_shows_only_the_two_robot_gpus() {
    bool ok = false;
    const QString text = svg_text(bs::test::bytes_of(dir_.filePath("fig1b.svg")), ok);
    QVERIFY(!text.contains("GTX"));
    QVERIFY(!text.contains("HD 630") && !text.contains("HD630"));
  }

  void tables_hold_the_published_numbers() {
    const QString t1 = QString::fromUtf8(bs::test::bytes_of(dir_.filePath("table1.tex")));
    QVERIFY(t1.contains("\\toprule") && t1.contains("\\bottomrule"));
    for (const char* n : {"9.14", "9.34", "5.25", "2.40", "0.49"}) QVERIFY2(t1.contains(n), n);
    const QString t2 = QString::fromUtf8(bs::test::bytes_of(dir_.filePath("table2.tex")));
    for (const char* n : {"49.68", "29.33", "15.54", "4.69"}) QVERIFY2(t2.contains(n), n);
    const QString platforms = QString::fromUtf8(bs::test::bytes_of(dir_.filePath("platforms.csv")));
    for (const char* n : {"40.52", "9.48", "104.64", "41.26", "84.36", "360.48"}) QVERIFY2(platforms.contains(n), n);
  }

  // Issue #23.5: a run measured on this machine and a third platform's power log are in the workspace. "Paper data
  // only" keeps the measured run out of fig2a; fig4 names the log it leaves out and why; figures.json records the
  // choice, and the output says what each figure shows.
  void data_choice_and_what_was_left_out() {
    bs::ui::FigureData d = paper_data();
    bs::FlopsRun measured = d.runs.front();
    for (const auto& r : d.runs)
      if (r.device_kind == bs::DeviceKind::Cpu) measured = r;
    measured.platform = "this machine";
    measured.device = "AMD EPYC";
    measured.provenance.origin = bs::DataOrigin::Measured;
    d.runs.push_back(measured);
    bs::PowerTrace robot = d.traces.front();
    robot.platform = "RobotPC";
    robot.provenance.origin = bs::DataOrigin::Reconstructed;
    d.traces.push_back(robot);
    const auto templates = bs::load_figure_templates(bs::ui::paper_template_path().toStdString());
    for (const auto choice : {bs::ui::FigureDataChoice::All, bs::ui::FigureDataChoice::PaperOnly}) {
      QTemporaryDir out;
      bs::ui::FigureOptions o;
      o.formats = {"svg"};
      const auto result =
          bs::ui::render_figures(templates, bs::ui::select_figure_data(d, choice), out.path(), o, bs::CancelToken{});
      const QString contents = result.contents.join('\n');
      QVERIFY(contents.contains("RobotPC (not one of the figure's platforms"));
      QCOMPARE(contents.contains("AMD EPYC"), choice == bs::ui::FigureDataChoice::All);
      const QJsonObject doc = bs::test::figures_manifest(out);
      QCOMPARE(doc["data"].toString().startsWith("paper data only"), choice == bs::ui::FigureDataChoice::PaperOnly);
      bool fig4_left_out = false;
      for (const auto& v : doc["files"].toArray())
        if (v.toObject()["figure"].toString() == "fig4")
          for (const auto& l : v.toObject()["left_out"].toArray())
            fig4_left_out |= l.toObject()["platform"].toString() == "RobotPC";
      QVERIFY(fig4_left_out);
    }
  }

  void figure_list_names_files_and_provenance() {
    const QJsonObject doc = bs::test::figures_manifest(dir_);
    QCOMPARE(doc["format"].toString(), QString("benchscope-figure-list"));
    const QJsonArray files = doc["files"].toArray();
    QCOMPARE(files.size(), 6 * 3 + 6);
    // The optional inference-time and headroom figures are skipped for data without bench dnn runs or headroom
    // measurements, and said so.
    QCOMPARE(doc["skipped"].toArray().size(), 2);
    QCOMPARE(doc["skipped"].toArray()[0].toObject()["figure"].toString(), QString("inference"));
    QCOMPARE(doc["skipped"].toArray()[1].toObject()["figure"].toString(), QString("headroom"));
    bool fig4_reconstructed = false;
    for (const auto& v : files) {
      const QJsonObject f = v.toObject();
      QVERIFY2(QFile::exists(dir_.filePath(f["file"].toString())), qPrintable(f["file"].toString()));
      QVERIFY2(!f["sources"].toArray().isEmpty(), qPrintable(f["file"].toString()));
      if (f["figure"].toString() == "fig4")
        for (const auto& s : f["sources"].toArray())
          fig4_reconstructed |= s.toObject()["origin"].toString() == "reconstructed";
    }
    QVERIFY(fig4_reconstructed);
  }

  void fig3_uses_the_workspace_capture() {
    auto batch =
        bs::import_file(BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018/frames/paper-capture.raw", bs::CancelToken{});
    QCOMPARE(batch.frames.size(), std::size_t{1});
    bs::ui::FigureData d = paper_data();
    d.frame = batch.frames.front();
    QTemporaryDir dir;
    bs::ui::FigureOptions o;
    o.formats = {"png"};
    const auto templates = bs::parse_figure_templates(
        R"({"format":"benchscope-figures","version":1,"figures":[{"id":"fig3","kind":"triptych"}]})", "t.json");
    bs::ui::render_figures(templates, d, dir.path(), o, bs::CancelToken{});
    const QJsonObject doc = bs::test::figures_manifest(dir);
    const QJsonObject source = doc["files"].toArray()[0].toObject()["sources"].toArray()[0].toObject();
    QVERIFY2(source["file"].toString().endsWith("paper-capture.raw"), qPrintable(source["file"].toString()));
    QCOMPARE(source["origin"].toString(), QString("synthetic"));  // the sample capture is labelled synthetic
    QVERIFY(source["how"].toString().contains("1280x1024"));
    const QImage img(dir.filePath("fig3.png"));
    QVERIFY(!img.isNull());
    // Panel (c) of a 1280x1024 frame is 5:4, as in the paper; the panels' centre is not blank.
    QVERIFY(img.pixelColor(img.width() / 2, img.height() / 3) != QColor(Qt::white));
  }

  void cancel_leaves_nothing() {
    QTemporaryDir dir;
    bs::CancelToken cancel;
    const auto templates = bs::load_figure_templates(bs::ui::paper_template_path().toStdString());
    QVERIFY_THROWS_EXCEPTION(bs::Cancelled, bs::ui::render_figures(templates, paper_data(), dir.path(), options_,
                                                                   cancel, [&](int done, int, const QString&) {
                                                                     if (done == 2) cancel.cancel();
                                                                   }));
    QVERIFY(QDir(dir.path()).entryList(QDir::Files).isEmpty());
  }

  // Cancelling stops the export at its next step and leaves nothing behind, wherever the cancel comes. Deterministic:
  // the cancel is given at each step the export reports (from its progress callback, where the GUI's Cancel button
  // lands between two steps), and what happens after it is counted in steps begun, never timed.
  void cancel_is_prompt() {
    auto batch =
        bs::import_file(BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018/frames/paper-capture.raw", bs::CancelToken{});
    bs::ui::FigureData d = paper_data();
    d.frame = batch.frames.front();
    const auto templates = bs::load_figure_templates(bs::ui::paper_template_path().toStdString());
    // One step per figure, then "tables" and "done": a cancel at a figure's step must stop the export.
    const int figure_steps = static_cast<int>(templates.size());
    QVERIFY(figure_steps >= 3);
    for (int k = 0; k < figure_steps; ++k) {
      QTemporaryDir dir;
      bs::CancelToken cancel;
      int steps = 0, steps_after_cancel = 0;
      bool stopped = false;
      try {
        bs::ui::render_figures(templates, d, dir.path(), options_, cancel, [&](int, int, const QString&) {
          if (steps > k) ++steps_after_cancel;
          if (steps++ == k) cancel.cancel();
        });
      } catch (const bs::Cancelled&) {
        stopped = true;
      }
      const QString at = QString("cancel at step %1 of %2").arg(k).arg(figure_steps);
      QVERIFY2(stopped, qPrintable(at + ": the export ran to its end"));
      QVERIFY2(steps_after_cancel == 0, qPrintable(at + QString(": %1 more steps ran").arg(steps_after_cancel)));
      QVERIFY2(QDir(dir.path()).entryList(QDir::Files).isEmpty(), qPrintable(at + ": files left behind"));
    }
  }

  // Issue #43.5: one platform, one colour in every figure. A second log of the NUC (a meter beside the paper's)
  // keeps the NUC's colour, told apart by its line and its name, never taking another platform's colour; the colour
  // is the one the Power tab and the report's chart give the NUC (device_palette.h, platform_color_indices).
  void fig4_draws_each_platform_in_its_own_colour() {
    bs::ui::FigureData d = paper_data();
    const auto nuc = std::find_if(d.traces.begin(), d.traces.end(), [](const auto& t) { return t.platform == "NUC"; });
    QVERIFY(nuc != d.traces.end());
    bs::PowerTrace meter = *nuc;
    meter.label = "nuc-meter";
    meter.provenance.source_file = "nuc-meter.csv";
    meter.provenance.date = "2026-11-20T10:00:00Z";
    d.traces.push_back(meter);
    std::vector<std::pair<std::string, int>> device_colors;
    for (const auto& [key, index] : d.colors) device_colors.emplace_back(key.first, index);
    std::map<std::string, int> platform_color;
    for (const auto& [platform, index] : bs::ui::platform_color_indices(device_colors, {"NUC", "Jetson TX2"}))
      platform_color[platform] = index;
    const auto templates = bs::load_figure_templates(bs::ui::paper_template_path().toStdString());
    const auto fig4 = std::find_if(templates.begin(), templates.end(), [](const auto& t) { return t.id == "fig4"; });
    QVERIFY(fig4 != templates.end());
    QCustomPlot plot;
    QJsonArray left_out;
    bs::ui::figure_plot(plot, *fig4, d, options_, left_out);
    QCOMPARE(plot.graphCount(), 3);
    std::set<int> nuc_styles;
    for (int g = 0; g < plot.graphCount(); ++g) {
      const QString name = plot.graph(g)->name();
      const std::string platform = name.startsWith("NUC") ? "NUC" : "Jetson TX2";
      QVERIFY2(name.startsWith("NUC") || name.startsWith("Jetson TX2"), qPrintable(name));
      QCOMPARE(plot.graph(g)->pen().color().name(), bs::ui::device_color(platform_color.at(platform)).name());
      if (platform == "NUC") nuc_styles.insert(static_cast<int>(plot.graph(g)->pen().style()));
    }
    QCOMPARE(nuc_styles.size(), std::size_t{2});  // the NUC's two logs look apart
  }

  void template_without_matching_data_is_a_clear_error() {
    QTemporaryDir dir;
    const auto templates = bs::parse_figure_templates(
        R"({"format":"benchscope-figures","version":1,"figures":[
             {"id":"ok","kind":"flops","device_kind":"cpu","x_label":"Tasks","y_label":"GFLOPS","y_scale":1e9},
             {"id":"none","kind":"flops","platforms":["Raspberry Pi"],"x_label":"W","y_label":"F"}]})",
        "mine.json");
    try {
      bs::ui::render_figures(templates, paper_data(), dir.path(), options_, bs::CancelToken{});
      QFAIL("expected an error");
    } catch (const std::runtime_error& e) {
      QVERIFY2(QString(e.what()).contains("none"), e.what());
    }
    QVERIFY(QDir(dir.path()).entryList(QDir::Files).isEmpty());  // "ok" was removed again
  }
};

QTEST_MAIN(TestPaperFigures)
#include "test_paper_figures.moc"
