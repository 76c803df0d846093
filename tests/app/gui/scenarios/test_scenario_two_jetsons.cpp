// SPDX-License-Identifier: GPL-3.0-or-later
// Scenario (issue #43.3): a lab with a Jetson TX2 and a Jetson AGX Orin imports one tegrastats log of each. A
// tegrastats log names its board family (by its format) but not the board: the import must ask which platform each
// log measured (on main both became one platform "Jetson", without a question, and the Platforms tab compared one
// "Jetson" column).
#include <QComboBox>
#include <QFileInfo>
#include <QTableWidget>
#include <QTest>
#include <set>

#include "../../../support/scenario_window.h"
#include "platform/platform_view.h"

using bs::test::ModalAnswerer;

class TestScenarioTwoJetsons : public QObject {
  Q_OBJECT
 private slots:
  void tegrastats_of_a_tx2_and_an_orin_stay_two_platforms() {
    const QStringList logs{"tegrastats-agx-orin-jetpack6.log", "tegrastats-tx2-jetpack3.log"};
    for (const QString& log : logs)
      if (!QFileInfo::exists(bs::test::kPublicPower + '/' + log))
        QSKIP(qPrintable("needs the public data folder " + bs::test::kPublicPower + " (BENCHSCOPE_PUBLIC_DATA_DIR)"));
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    BS_STEP(bs::test::open_paper_window(w, dir));
    const auto answer = [](const QString& platform) {
      return [platform](QWidget* dialog) {
        auto* combo = dialog->findChild<QComboBox*>();
        if (!combo) return;
        bs::test::retype(combo, platform);
        bs::test::key(combo, Qt::Key_Return);
      };
    };
    ModalAnswerer person;
    person.expect("Import files (file dialog)", ModalAnswerer::titled("Import files"),
                  [&logs](QWidget* d) { bs::test::choose_files(d, bs::test::kPublicPower, logs); });
    // The paper workspace already has a "Jetson TX2": the person picks it for the TX2's log, and names the Orin.
    person.expect("Platform of the AGX Orin log", ModalAnswerer::titled("Platform of tegrastats-agx-orin"),
                  answer("Jetson AGX Orin"));
    person.expect("Platform of the TX2 log", ModalAnswerer::titled("Platform of tegrastats-tx2"), answer("Jetson TX2"));
    bs::test::key(&w, Qt::Key_I, Qt::ControlModifier);
    const QString message = bs::test::wait_for_import(w);
    QVERIFY2(message.startsWith("Imported 2 file(s)"), qPrintable(message));
    QVERIFY2(bs::test::wait_until([&] { return person.done(); }, 100), qPrintable(person.report()));

    std::set<QString> platforms;
    for (const bs::StoredPowerTrace& t : w.workspace()->power_trace_summaries())
      if (QString::fromStdString(t.trace.label).startsWith("tegrastats"))
        platforms.insert(QString::fromStdString(t.trace.platform));
    QCOMPARE(platforms, (std::set<QString>{"Jetson AGX Orin", "Jetson TX2"}));
    // The Platforms tab compares both boards, and no platform is called by the family alone.
    bs::test::open_tab(w, "Platforms");
    QTableWidget* table = w.platform_view()->table();
    QStringList rows;
    for (int r = 0; r < table->rowCount(); ++r) rows << table->item(r, 0)->text();
    QVERIFY2(!rows.contains("Jetson"), qPrintable(rows.join(", ")));
    bool orin = false;
    for (const QString& r : rows) orin = orin || r.startsWith("Jetson AGX Orin");
    QVERIFY2(orin, qPrintable(rows.join(", ")));
    bs::test::screenshot(&w, "two-jetsons-platforms");
  }
};

BENCHSCOPE_SCENARIO_MAIN(TestScenarioTwoJetsons)
#include "test_scenario_two_jetsons.moc"
