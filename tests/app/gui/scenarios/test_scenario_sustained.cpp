// SPDX-License-Identifier: GPL-3.0-or-later
// Scenario (issue #53): will it hold its speed for a whole match? A person opens the Sustained tab.
//  - throttling_on_one_time_axis: a workspace holding a 30 s sustained run whose CPU clocks drop from 3.0 to 1.8 GHz
//    and whose package zone reaches its 95 °C trip point at 10 s, its rate falling with them. The tab names the
//    onset (10 s), what throttled and the stability (60 %: not stable), draws rate, clocks and temperatures on one
//    time axis with the throttled span shaded, re-judges at once when the stable threshold is lowered, and Ctrl+E
//    exports a figure that names every series and every axis. The Platforms tab's "Sustained:" requirement
//    (stability>=97%) fails the NUC by the same margin `benchscope-cli platforms --require-sustained` gives.
//  - a_run_here_comes_home: Load "flops:1" for 3 s every 0.5 s, Run: the intervals are drawn as they come, the run is
//    stored in the workspace and shown (this machine's clocks and temperatures, or what it does not expose).
//  - a_jetson_log_shows_its_clocks: a real tegrastats log imported (File > Import files…): the tab lists its clocks
//    and temperatures, and says throttling is unknown (tegrastats states no maximum clock and no trip point).
#include <qcustomplot.h>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>

#include "../../../support/cli_harness.h"
#include "../../../support/pdf_readback.h"
#include "../../../support/scenario_window.h"
#include "platform/platform_view.h"
#include "store/workspace.h"
#include "sustain/sustain_import.h"
#include "sustain/sustain_run_panel.h"
#include "sustain/sustain_view.h"

namespace {

// 30 intervals of 1 s on a two-CPU machine: full clocks and 50 GFLOPS until 10 s, then 1.8 GHz and 30 GFLOPS while
// the package zone sits at its 95 °C trip point.
bs::SustainRun throttled_run() {
  bs::SustainRun r;
  r.platform = "NUC";
  r.label = "flops for 30 s";
  r.load = "flops";
  r.rate_unit = "GFLOPS";
  r.interval_s = 1;
  bs::ClockSeries cpu0{"cpu0", 3.0e9, {}}, cpu1{"cpu1", 3.0e9, {}};
  bs::TemperatureSeries zone{"thermal_zone0 x86_pkg_temp", 95.0, {}};
  for (int i = 1; i <= 30; ++i) {
    const bool hot = i > 10;
    r.t_s.push_back(i);
    r.rate.push_back(hot ? 30.0 : 50.0);
    cpu0.hz.push_back(hot ? 1.8e9 : 3.0e9);
    cpu1.hz.push_back(hot ? 1.8e9 : 2.9e9);
    zone.celsius.push_back(hot ? 97.0 : 60.0 + 3.0 * i);
  }
  r.clocks = {cpu0, cpu1};
  r.temperatures = {zone};
  r.provenance.origin = bs::DataOrigin::Measured;
  r.provenance.tool = "benchscope-cli sustain";
  r.provenance.date = "2026-12-06T10:00:00Z";
  return r;
}

QStringList axis_labels(QCustomPlot& plot) {
  QStringList labels;
  for (QCPAxisRect* rect : plot.axisRects())
    for (QCPAxis* a : rect->axes())
      if (!a->label().isEmpty()) labels << a->label();
  return labels;
}

int bands(QCustomPlot& plot) {
  int n = 0;
  for (int i = 0; i < plot.itemCount(); ++i) n += qobject_cast<QCPItemRect*>(plot.item(i)) ? 1 : 0;
  return n;
}

}  // namespace

class TestScenarioSustained : public QObject {
  Q_OBJECT
 private slots:
  void throttling_on_one_time_axis() {
    QTemporaryDir dir;
    // The paper's workspace (the NUC and the Jetson TX2 with their runs and power logs) and the NUC's sustained run.
    const QString ws = bs::test::paper_workspace(dir);
    QVERIFY(!ws.isEmpty());
    {
      bs::Workspace store(ws.toStdString());
      const auto home = bs::sustain::sustain_import(throttled_run(), std::nullopt, "benchscope-cli sustain");
      store.add_import(home.batch, home.content_hash);
    }
    bs::ui::MainWindow w;
    QVERIFY(w.open_workspace(ws));
    QVERIFY(bs::test::show_at(w));
    QWidget* tab = bs::test::open_tab(w, "Sustained");
    QVERIFY2(tab, "no Sustained tab");
    bs::ui::SustainView* view = w.sustain_view();
    QCOMPARE(view->chooser()->count(), 1);
    QVERIFY2(view->chooser()->currentText().startsWith("NUC"), qPrintable(view->chooser()->currentText()));
    const QString summary = view->summary()->text();
    QVERIFY2(summary.contains("DETECTED from 10.0 s"), qPrintable(summary));
    QVERIFY2(summary.contains("cpu0"), qPrintable(summary));
    QVERIFY2(summary.contains("60.0 %") && summary.contains("NOT stable"), qPrintable(summary));
    QVERIFY2(view->source()->text().contains("benchscope-cli sustain"), qPrintable(view->source()->text()));
    QCustomPlot* plot = view->plot();
    QCOMPARE(plot->axisRectCount(), 3);  // rate, clocks, temperatures: no power was recorded
    const QStringList labels = axis_labels(*plot);
    for (const QString& l : {QStringLiteral("rate\n(GFLOPS)"), QStringLiteral("clock\n(% of max)"),
                             QStringLiteral("temperature\n(°C)"), QStringLiteral("time since start (s)")})
      QVERIFY2(labels.contains(l), qPrintable(labels.join(" | ")));
    QCOMPARE(bands(*plot), 3);  // the throttled span, shaded in each panel
    const QStringList names = bs::test::legend_names(*plot);
    for (const QString& n : {QStringLiteral("rate per interval"), QStringLiteral("CPUs, lowest of 2"),
                             QStringLiteral("thermal_zone0 x86_pkg_temp"), QStringLiteral("trip point 95 °C")})
      QVERIFY2(names.contains(n), qPrintable(names.join(" | ")));
    // Panning one panel moves the others: one time axis.
    plot->axisRect(0)->axis(QCPAxis::atBottom)->setRange(5, 15);
    QCOMPARE(plot->axisRects().last()->axis(QCPAxis::atBottom)->range().lower, 5.0);
    plot->axisRect(0)->axis(QCPAxis::atBottom)->setRange(0, 30);
    bs::test::screenshot(&w, "sustained-tab-1600x1000");
    w.resize(1280, 800);
    QTest::qWait(50);
    QVERIFY2(w.width() <= 1280, qPrintable(QStringLiteral("the window is %1 px wide at 1280x800").arg(w.width())));
    bs::test::screenshot(&w, "sustained-tab-1280x800");

    // A lower stable threshold re-judges at once, as typed.
    view->stable_percent()->selectAll();
    QTest::keyClicks(view->stable_percent(), "55");
    QTest::keyClick(view->stable_percent(), Qt::Key_Enter);
    QVERIFY2(view->summary()->text().contains("stable (threshold 55.0 %)"), qPrintable(view->summary()->text()));

    // The Platforms tab's sustained requirement, as typed: the NUC fails it with its margin, and the CLI beside the
    // window says the same of the same workspace.
    QVERIFY(bs::test::open_tab(w, "Platforms"));
    bs::ui::PlatformView* platforms = w.platform_view();
    QTest::mouseClick(platforms->sustained_check(), Qt::LeftButton);
    platforms->sustained_edit()->selectAll();
    QTest::keyClicks(platforms->sustained_edit(), "stability>=97%");
    QTest::keyClick(platforms->sustained_edit(), Qt::Key_Return);
    // The NUC's first (failing ranks before unknown), then every other platform of the paper: unknown, no record.
    const std::vector<bs::sustain::SustainVerdict>& verdicts = platforms->sustained_verdicts();
    QVERIFY(verdicts.size() >= 2);
    const bs::sustain::SustainVerdict& v = verdicts.front();
    QCOMPARE(v.platform, std::string("NUC"));
    QCOMPARE(v.status, bs::RequirementStatus::Fail);
    for (std::size_t i = 1; i < verdicts.size(); ++i) QCOMPARE(verdicts[i].status, bs::RequirementStatus::Unknown);
    QVERIFY2(platforms->summary_text().contains("Sustained"), "the summary does not name the requirement");
    QVERIFY2(v.margin.find("60.0 %") != std::string::npos, v.margin.c_str());
    const bs::test::CliResult cli = bs::test::cli({"platforms", ws, "--require-sustained", "stability>=97%", "--json"});
    QVERIFY2(cli.code == 0, cli.err.constData());
    const QJsonObject doc = QJsonDocument::fromJson(cli.out).object();
    const QJsonArray listed = doc.value("sustained").toObject().value("platforms").toArray();
    QCOMPARE(listed.size(), static_cast<qsizetype>(verdicts.size()));
    QCOMPARE(listed[0].toObject().value("platform").toString(), QStringLiteral("NUC"));
    QCOMPARE(listed[0].toObject().value("status").toString(), QStringLiteral("FAILS"));
    QCOMPARE(listed[0].toObject().value("margin").toString(), QString::fromStdString(v.margin));
    QCOMPARE(listed[1].toObject().value("status").toString(), QStringLiteral("unknown"));
    bs::test::screenshot(&w, "sustained-requirement-platforms-1280x800");
    QVERIFY(bs::test::open_tab(w, "Sustained"));
    // Back on the Sustained tab the person clicks the plot: the requirement's field, hidden now, would keep the keys
    // (Ctrl+E is a line edit's "end of line").
    if (QWidget* typed_in = QApplication::focusWidget()) typed_in->clearFocus();

    if (QStandardPaths::findExecutable("pdftotext").isEmpty()) QSKIP("pdftotext (poppler-utils) reads the export back");
    const QString stem = dir.filePath("sustained");
    QVERIFY(bs::test::export_current_tab(w, stem, "ieee"));
    bs::test::keep_for_looking(stem + ".pdf", "export-sustained.pdf");
    const QString text = bs::test::pdf_flat_text(stem + ".pdf");
    QStringList problems;
    for (const QString& s : bs::test::legend_names(*plot) + labels)  // the legend as the threshold left it
      if (!text.contains(s.simplified())) problems << QStringLiteral("'%1' is not in the figure").arg(s);
    const auto pages = bs::test::pdf_words(stem + ".pdf");
    QCOMPARE(pages.size(), std::size_t{1});
    problems << bs::test::figure_layout_problems(pages.front());
    for (const QString& p : problems) qWarning("%s", qPrintable(p));
    QVERIFY2(problems.isEmpty(), qPrintable(problems.value(0)));
  }

  void a_run_here_comes_home() {
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    QVERIFY(w.open_workspace(dir.filePath("here.bsw")));
    QVERIFY(bs::test::show_at(w));
    QVERIFY(bs::test::open_tab(w, "Sustained"));
    bs::ui::SustainRunPanel* panel = w.sustain_view()->run_panel();
    panel->load()->selectAll();
    QTest::keyClicks(panel->load(), "flops:1");
    panel->seconds()->setValue(3);
    panel->interval()->setValue(0.5);
    QSignalSpy stopped(panel, &bs::ui::SustainRunPanel::stopped);
    QTest::mouseClick(panel->controls().run, Qt::LeftButton);
    QVERIFY(panel->controls().running());
    QVERIFY(panel->controls().cancel->isEnabled());
    bool live = false;
    // Until the panel has said how the run ended (the worker's end reaches the window a moment after it returns).
    for (int i = 0; i < 3000 && stopped.isEmpty(); ++i) {
      if (!live && w.sustain_view()->source()->text().contains("the run going on")) {
        live = true;
        // The time axis spans the 3 s asked for while the first intervals come in.
        QCOMPARE(w.sustain_view()->plot()->axisRect(0)->axis(QCPAxis::atBottom)->range().upper, 3.0);
        bs::test::screenshot(&w, "sustained-running");
      }
      QTest::qWait(20);
    }
    QVERIFY2(!stopped.isEmpty(), "the 3 s run did not end");
    QTest::qWait(50);  // the measured run is stored right after the panel stops
    QVERIFY2(live, "the intervals were not drawn as they came");
    QVERIFY2(panel->controls().status->text().startsWith("Measured 6 interval(s)"),
             qPrintable(panel->controls().status->text()));
    const auto stored = w.workspace()->sustain_runs();
    QCOMPARE(stored.size(), std::size_t{1});
    QCOMPARE(stored[0].run.rate.size(), std::size_t{6});
    QCOMPARE(stored[0].run.rate_unit, std::string("GFLOPS"));
    QCOMPARE(w.sustain_view()->chooser()->count(), 1);
    const QString summary = w.sustain_view()->summary()->text();
    QVERIFY2(summary.contains("stability"), qPrintable(summary));
    // This machine's clocks and zones, or what it does not expose: never a silent "no throttling".
    QVERIFY2(summary.contains("throttling"), qPrintable(summary));
    if (stored[0].run.clocks.empty() && stored[0].run.temperatures.empty())
      QVERIFY2(summary.contains("unknown"), qPrintable(summary));
  }

  void a_jetson_log_shows_its_clocks() {
    const QString log = bs::test::kPublicPower + "/tegrastats-xavier-nx-jetpack5.log";
    if (!QFileInfo::exists(log)) QSKIP("the shared public tegrastats logs are not here (docs/third-party-data.md)");
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    QVERIFY(w.open_workspace(dir.filePath("jetson.bsw")));
    w.import_paths_now({log});
    QVERIFY(bs::test::show_at(w));
    QVERIFY(bs::test::open_tab(w, "Sustained"));
    bs::ui::SustainView* view = w.sustain_view();
    QCOMPARE(view->chooser()->count(), 1);
    QVERIFY2(view->chooser()->currentText().contains("clocks and temperatures of"),
             qPrintable(view->chooser()->currentText()));
    const QString summary = view->summary()->text();
    QVERIFY2(summary.contains("unknown"), qPrintable(summary));
    QVERIFY2(view->plot()->axisRectCount() >= 2, "clocks and temperatures are not drawn");
    QVERIFY2(view->source()->text().contains("tegrastats-xavier-nx-jetpack5.log"), qPrintable(view->source()->text()));
  }
};

BENCHSCOPE_SCENARIO_MAIN(TestScenarioSustained)
#include "test_scenario_sustained.moc"
