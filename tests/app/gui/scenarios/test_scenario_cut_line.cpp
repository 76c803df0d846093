// SPDX-License-Identifier: GPL-3.0-or-later
// Scenario (issue #43.7): a logger was killed while writing, so the CSV's last line stops inside its number
// ("162.4,3." of 162.4 s, 3.0611 A) and has no line ending. On main it imported silently as 3.0 A. The import must
// say that the line may be cut, naming the file and the line, and the cut number must not be taken as a sample.
#include <QTest>
#include <cmath>

#include "../../../support/scenario_window.h"

using bs::test::ModalAnswerer;

class TestScenarioCutLine : public QObject {
  Q_OBJECT
 private slots:
  void a_cut_last_line_is_named_and_left_out() {
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    BS_STEP(bs::test::open_paper_window(w, dir));
    ModalAnswerer person;
    person.expect("Import files (file dialog)", ModalAnswerer::titled("Import files"),
                  [](QWidget* d) { bs::test::choose_file(d, bs::test::kScenarioData + "/nuc-cut-last-line.csv"); });
    bs::test::key(&w, Qt::Key_I, Qt::ControlModifier);
    const QString message = bs::test::wait_for_import(w);
    QVERIFY2(bs::test::wait_until([&] { return person.done(); }, 100), qPrintable(person.report()));
    // The file names its platform: nothing to ask. What the person reads in the status bar names the line.
    QVERIFY2(message.startsWith("Imported 1 file(s)"), qPrintable(message));
    QVERIFY2(message.contains("nuc-cut-last-line.csv:816") && message.contains("cut off"), qPrintable(message));
    // The 812 complete rows are in; "162.4,3." is not a sample.
    bool found = false;
    for (const bs::StoredPowerTrace& t : w.workspace()->power_traces()) {
      if (t.trace.label != "nuc-cut-last-line.csv") continue;
      found = true;
      QCOMPARE(t.trace.time_s.size(), std::size_t{812});
      QVERIFY(std::abs(t.trace.time_s.back() - 162.2) < 1e-9);
    }
    QVERIFY(found);
    bs::test::screenshot(&w, "cut-line-status");
  }
};

BENCHSCOPE_SCENARIO_MAIN(TestScenarioCutLine)
#include "test_scenario_cut_line.moc"
