// SPDX-License-Identifier: GPL-3.0-or-later
// Issue #43.5, as a person meets it: the paper's workspace with this machine's sweeps beside it, Ctrl+E on every
// tab, the export dialog answered, the PDF read back with pdftotext. Every series the tab draws is named in the
// figure (in the legend, or whole in the note under it), every peak the FLOPS tab labels has its value in the
// figure, no words print over each other or run past the figure's edge, and the power figure's time axis spans the
// logs, not forty times more. A power-only log opens the Power tab in power, not in an empty current plot.
#include <qcustomplot.h>
#include <QApplication>
#include <QCoreApplication>
#include <QDateTime>
#include <QFile>
#include <QLineEdit>
#include <QMessageBox>
#include <QSettings>
#include <QStandardPaths>
#include <QTabBar>
#include <QTemporaryDir>
#include <QTest>

#include "../../support/pdf_readback.h"
#include "../../support/scenario_window.h"
#include "main_window.h"
#include "peaks/flops_plot.h"
#include "peaks/peak_overlay.h"
#include "platform/candidates_panel.h"
#include "platform/platform_view.h"
#include "power/power_view.h"

namespace {

// The value of a peak label without its flag mark ("5.25 TFLOPS ⚠[1]" -> "5.25 TFLOPS").
QString label_value(const QString& text) { return text.section(QStringLiteral(" \u26A0"), 0, 0).trimmed(); }

}  // namespace

class TestScenarioExports : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    QSettings().clear();  // the export dialog's remembered choices from an earlier run
    if (QStandardPaths::findExecutable("pdftotext").isEmpty())
      QSKIP("pdftotext (poppler-utils) is needed to read the exported figures back");
  }

  void ctrl_e_on_every_tab_names_what_it_draws() {
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    QVERIFY(w.open_workspace(dir.filePath("paper.bsw")));
    // The paper's sample and sweeps measured on a development machine: 21 FLOPS series, two current logs of 120 s,
    // the pipeline runs and the synthetic capture; and a board's tegrastats log of 50 minutes (power only, no
    // current: it draws nothing in the Power tab's current plot).
    const QString tegrastats = dir.filePath("orin-50min-tegrastats.log");
    {
      QFile in(BENCHSCOPE_TEST_DATA_DIR "/power/tegrastats-orin-jetpack5.log");
      QVERIFY(in.open(QIODevice::ReadOnly));
      const QByteArray line = in.readLine().trimmed().mid(20);  // after "11-22-2026 10:00:01 "
      QFile out(tegrastats);
      QVERIFY(out.open(QIODevice::WriteOnly));
      const QDateTime start(QDate(2026, 11, 22), QTime(10, 0, 0), Qt::UTC);
      for (int s = 0; s < 3000; ++s)
        out.write(start.addSecs(s).toString("MM-dd-yyyy HH:mm:ss ").toLatin1() + line + '\n');
    }
    w.import_paths_now({BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018",
                        BENCHSCOPE_SOURCE_DIR "/sample_data/measured-dev", tegrastats});
    w.resize(1600, 1000);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    w.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&w));
    QCOMPARE(w.flops_plot()->series_count(), 21);

    // Library candidates on the Platforms tab, typed as a person does: its figure is the tab's plot.
    QVERIFY(bs::test::type_library_candidates(w, "orin,pi5,xavier-nx"));

    QStringList problems;
    QTabWidget* tabs = bs::test::window_tabs(w);
    for (int t = 0; t < tabs->count(); ++t) {
      bs::test::click_tab(w, t);
      const QString tab = tabs->tabText(t).remove('&');
      QCustomPlot* plot = bs::test::exported_plot(w);
      const QStringList names = plot ? bs::test::legend_names(*plot) : QStringList();
      QStringList peaks;
      if (tabs->currentWidget()->isAncestorOf(w.flops_plot()))
        for (const QCPItemText* label : w.flops_plot()->overlay()->labels()) peaks << label_value(label->text());
      const QString stem = dir.filePath(tab.toLower());
      // A tab without a plot says so in a message box: the same timer answers it.
      QVERIFY2(bs::test::export_current_tab(w, stem), qPrintable(tab));
      if (!plot) {
        QVERIFY2(!QFile::exists(stem + ".pdf"), qPrintable(tab));
        continue;
      }
      QVERIFY2(QFile::exists(stem + ".pdf"), qPrintable(tab + ": no PDF written"));
      bs::test::keep_for_looking(stem + ".pdf", "export-" + tab.toLower() + ".pdf");
      const QString text = bs::test::pdf_flat_text(stem + ".pdf");
      for (const QString& name : names)
        if (!text.contains(name.simplified()))
          problems << QStringLiteral("%1: series '%2' is not named in the figure").arg(tab, name);
      for (const QString& peak : peaks)
        if (!text.contains(peak)) problems << QStringLiteral("%1: the peak '%2' is not in the figure").arg(tab, peak);
      const auto pages = bs::test::pdf_words(stem + ".pdf");
      QCOMPARE(pages.size(), std::size_t{1});
      for (const QString& p : bs::test::figure_layout_problems(pages.front()))
        problems << tab + QStringLiteral(": ") + p;
      if (tabs->currentWidget() == w.power_view() || tabs->currentWidget()->isAncestorOf(w.power_view())) {
        if (const double upper = w.power_view()->plot()->xAxis->range().upper; upper > 130)
          problems << QStringLiteral("Power: the view's time axis runs to %1 s for the 120 s current logs").arg(upper);
        // Time ticks: the logs are 120 s long; an axis to 3000 s leaves them a sliver of the figure.
        double widest_tick = 0;
        for (const auto& word : pages.front().words)
          if (bool ok = false; word.box.top() > pages.front().size.height() * 0.3 && (word.text.toDouble(&ok), ok))
            widest_tick = std::max(widest_tick, word.text.toDouble());
        if (widest_tick > 200)
          problems << QStringLiteral("Power: the time axis runs to %1 s for 120 s logs").arg(widest_tick);
      }
    }
    for (const QString& p : problems) qWarning("%s", qPrintable(p));  // every one, not only what QVERIFY2 shows
    QVERIFY2(problems.isEmpty(),
             qPrintable(QStringLiteral("%1 problem(s), the first: %2").arg(problems.size()).arg(problems.value(0))));
  }

  // A log with power only (tegrastats: the board's input rail in mW, no current) opens the Power tab in power.
  void power_only_log_opens_in_power() {
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    QVERIFY(w.open_workspace(dir.filePath("tegra.bsw")));
    w.import_paths_now({BENCHSCOPE_TEST_DATA_DIR "/power/tegrastats-orin-jetpack5.log"});
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    bs::test::click_tab(w, bs::test::tab_of(w, w.power_view()));
    bs::ui::PowerView* power = w.power_view();
    QCOMPARE(power->trace_count(), 1);
    QCOMPARE(power->quantity(), bs::ui::PowerView::Quantity::Power);
    QVERIFY(power->plot()->graph(0)->dataCount() > 0);
    QCOMPARE(power->plot()->yAxis->label(), QString("Power (W)"));
  }
};

QTEST_MAIN(TestScenarioExports)
#include "test_scenario_exports.moc"
