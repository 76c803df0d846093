// SPDX-License-Identifier: GPL-3.0-or-later
// Scenario (issue #50.5, item 1): a lab with the paper's workspace imports a tegrastats log of its Jetson TX2 and one
// of a Jetson AGX Orin it has not benchmarked yet, and picks the TX2's tegrastats log for the comparisons. On main
// the Efficiency tab then dropped the TX2 without a word (a tegrastats log has power, no supply current), and never
// listed the Orin, the desktop or the laptop. Now every platform of the Platforms tab has a row in the Efficiency
// tab: the TX2's with its mean-power figures and, in the paper's column, why it has no paper figure; the others
// with the reason they have none, in the row itself.
#include <QComboBox>
#include <QHeaderView>
#include <QTableWidget>
#include <QTest>

#include "../../../support/scenario_window.h"
#include "platform/efficiency_view.h"
#include "platform/platform_view.h"

using bs::test::ModalAnswerer;

namespace {

const QString kFixturePower = QStringLiteral(BENCHSCOPE_TEST_DATA_DIR "/power");

int column(const QTableWidget* t, const QString& header_start) {
  for (int c = 0; c < t->columnCount(); ++c)
    if (t->horizontalHeaderItem(c)->text().startsWith(header_start)) return c;
  return -1;
}

int row_of(const QTableWidget* t, const QString& platform) {
  for (int r = 0; r < t->rowCount(); ++r)
    if (t->item(r, 0) && t->item(r, 0)->text() == platform) return r;
  return -1;
}

QString cell(const QTableWidget* t, int row, int col) {
  const QTableWidgetItem* item = row >= 0 && col >= 0 ? t->item(row, col) : nullptr;
  return item ? item->text() : QString();
}

// Ctrl+I, the file chosen in the file dialog, the platform question answered with `platform`.
bool import_log(bs::ui::MainWindow& w, const QString& file, const QString& platform) {
  ModalAnswerer person;
  person.expect("Import files (file dialog)", ModalAnswerer::titled("Import files"),
                [file](QWidget* d) { bs::test::choose_file(d, kFixturePower + '/' + file); });
  person.expect("Platform of " + file, ModalAnswerer::titled("Platform of " + file.section('.', 0, 0)),
                [platform](QWidget* d) {
                  auto* combo = d->findChild<QComboBox*>();
                  if (!combo) return;
                  bs::test::retype(combo, platform);
                  bs::test::key(combo, Qt::Key_Return);
                });
  bs::test::key(&w, Qt::Key_I, Qt::ControlModifier);
  const QString message = bs::test::wait_for_import(w);
  const bool done = bs::test::wait_until([&] { return person.done(); }, 100);
  if (!message.startsWith("Imported 1 file(s)") || !done)
    qWarning("%s: %s; %s", qPrintable(file), qPrintable(message), qPrintable(person.report()));
  return message.startsWith("Imported 1 file(s)") && done;
}

}  // namespace

class TestScenarioEfficiencyPlatforms : public QObject {
  Q_OBJECT
 private slots:
  void every_platform_has_a_row_in_the_efficiency_tab() {
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    BS_STEP(bs::test::open_paper_window(w, dir));
    QVERIFY(import_log(w, "tegrastats-tx2-jetpack4.log", "Jetson TX2"));
    QVERIFY(import_log(w, "tegrastats-orin-jetpack6.log", "Jetson AGX Orin"));

    // The person picks the TX2's tegrastats log above the Efficiency tab, as logs_apart picks the NUC's.
    QWidget* tab = bs::test::open_tab(w, "Efficiency");
    auto* choice = bs::test::field<QComboBox>(tab, "Power log of Jetson TX2:");
    QVERIFY2(choice, "the Efficiency tab offers no choice of the Jetson TX2's two logs");
    QCOMPARE(choice->currentText(), QString("jetson-current.csv"));
    BS_STEP(bs::test::pick_next_entry(choice));
    QVERIFY(bs::test::wait_until(
        [&] {
          auto* c = bs::test::field<QComboBox>(bs::test::window_tabs(w)->currentWidget(), "Power log of Jetson TX2:");
          return c && c->currentText().startsWith("tegrastats-tx2");
        },
        200));

    // Every platform the Platforms tab compares is in the Efficiency tab, computed or with its reason.
    QTableWidget* efficiency = w.efficiency_view()->table();
    QTableWidget* platforms = w.platform_view()->table();
    QStringList missing;
    for (int r = 0; r < platforms->rowCount(); ++r) {
      const QString platform = platforms->item(r, 0)->text();
      bool found = false;
      for (int e = 0; e < efficiency->rowCount(); ++e)
        found = found || (efficiency->item(e, 0) && platform.startsWith(efficiency->item(e, 0)->text()));
      if (!found) missing << platform;
    }
    QVERIFY2(missing.isEmpty(), qPrintable("not in the Efficiency tab: " + missing.join(", ")));

    // The TX2 from its tegrastats log: GFLOPS/W at mean power, and the paper's column says why it has none.
    const int tx2 = row_of(efficiency, "Jetson TX2");
    QVERIFY2(tx2 >= 0, "the Jetson TX2 (power from tegrastats) has no row in the Efficiency tab");
    const QString at_mean = cell(efficiency, tx2, column(efficiency, "GFLOPS/W\npeak / mean"));
    QVERIFY2(at_mean.toDouble() > 0, qPrintable(at_mean));
    const QString paper = cell(efficiency, tx2, column(efficiency, "GFLOPS/W paper"));
    QCOMPARE(paper, QString("none: no supply current"));
    // The others: the reason in the row, across its columns, as a person reads it without hovering.
    const QString orin = cell(efficiency, row_of(efficiency, "Jetson AGX Orin"), 1);
    QVERIFY2(orin.startsWith("No efficiency figure: no FLOPS run of this platform"), qPrintable(orin));
    for (const QString& platform :
         {QStringLiteral("Desktop (Alienware Area-51)"), QStringLiteral("Laptop (MacBook Pro 14,3)")}) {
      const QString why = cell(efficiency, row_of(efficiency, platform), 1);
      QVERIFY2(why == "No efficiency figure: no power log of this platform", qPrintable(platform + ": " + why));
    }
    bs::test::screenshot(&w, "efficiency-every-platform-1600x1000");
    w.resize(1280, 800);
    QTest::qWait(100);
    bs::test::screenshot(&w, "efficiency-every-platform-1280x800");
  }
};

BENCHSCOPE_SCENARIO_MAIN(TestScenarioEfficiencyPlatforms)
#include "test_scenario_efficiency_platforms.moc"
