// SPDX-License-Identifier: GPL-3.0-or-later
// Scenario (issue #43.1): a lab imports its own power logs into a workspace that already has several platforms.
// Each log names no platform, so the import asks "Platform of ..." for each. A person answers in the dialog with
// the keyboard; nothing may cover the question (on main the modal "Import ... %" progress dialog opened over it and
// took every click and key, and only Cancel got out: "Imported 0 file(s) (cancelled)"). Latency files (#45's
// cyclictest, rttest) rarely name their machine either and are asked about the same way (#46: never attached to a
// platform without the question).
#include <QComboBox>
#include <QFileInfo>
#include <QInputDialog>
#include <QTest>
#include <map>

#include "../../../support/scenario_window.h"

using bs::test::ModalAnswerer;

namespace {

// The person's answer to "Platform of <log>": the platform typed over the guess in the dialog's field, then Enter.
ModalAnswerer::Answer platform_answer(const QString& platform) {
  return [platform](QWidget* dialog) {
    auto* combo = dialog->findChild<QComboBox*>();
    if (!combo) return;
    bs::test::retype(combo, platform);
    bs::test::key(combo, Qt::Key_Return);
  };
}

std::map<QString, QString> log_platforms(const bs::ui::MainWindow& w) {
  std::map<QString, QString> out;
  for (const bs::StoredPowerTrace& t : w.workspace()->power_trace_summaries())
    out[QString::fromStdString(t.trace.label)] = QString::fromStdString(t.trace.platform);
  return out;
}

}  // namespace

class TestScenarioImportQuestion : public QObject {
  Q_OBJECT
 private slots:
  void importing_logs_with_ctrl_i_asks_each_platform_over_the_progress() {
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    BS_STEP(bs::test::open_paper_window(w, dir));
    // The person's own logs, in one folder: a meter CSV, a current-only CSV and one cut off mid-number.
    const QStringList names{"meter-no-platform.csv", "current-only.csv", "meter-cut-last-line.csv"};
    ModalAnswerer person;
    person.expect("Import files (file dialog)", ModalAnswerer::titled("Import files"),
                  [&names](QWidget* d) { bs::test::choose_files(d, bs::test::kScenarioData, names); });
    person.expect("Platform of meter-no-platform.csv", ModalAnswerer::titled("Platform of meter-no-platform.csv"),
                  platform_answer("NUC"));
    person.expect("Platform of current-only.csv", ModalAnswerer::titled("Platform of current-only.csv"),
                  platform_answer("Jetson TX2"));
    person.expect("Platform of meter-cut-last-line.csv", ModalAnswerer::titled("Platform of meter-cut-last-line.csv"),
                  platform_answer("Lab bench PC"));
    bs::test::key(&w, Qt::Key_I, Qt::ControlModifier);  // File > Import files…
    const QString message = bs::test::wait_for_import(w);
    QVERIFY2(bs::test::wait_until([&] { return person.done(); }, 100), qPrintable(person.report()));
    QVERIFY2(person.blocked.isEmpty() && person.gave_up.isEmpty(), qPrintable(person.report()));
    QVERIFY2(message.startsWith("Imported 3 file(s)") && !message.contains("cancelled"), qPrintable(message));
    const auto platforms = log_platforms(w);
    QCOMPARE(platforms.at("meter-no-platform.csv"), QString("NUC"));
    QCOMPARE(platforms.at("current-only.csv"), QString("Jetson TX2"));
    QCOMPARE(platforms.at("meter-cut-last-line.csv"), QString("Lab bench PC"));
    bs::test::screenshot(&w, "import-question-done");
  }

  // cyclictest and rttest results go through the same question as a power log, over the progress, never under it.
  void importing_latency_files_asks_each_platform_over_the_progress() {
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    BS_STEP(bs::test::open_paper_window(w, dir));
    const QString folder = QStringLiteral(BENCHSCOPE_TEST_DATA_DIR "/headroom");
    const QStringList names{"cyclictest-2.6-H20-2thr-overflows.txt", "rttest-log-1khz-misses.txt"};
    ModalAnswerer person;
    person.expect("Import files (file dialog)", ModalAnswerer::titled("Import files"),
                  [&](QWidget* d) { bs::test::choose_files(d, folder, names); });
    person.expect("Platform of the cyclictest result", ModalAnswerer::titled("Platform of cyclictest"),
                  platform_answer("Jetson TX2"));
    person.expect("Platform of the rttest result", ModalAnswerer::titled("Platform of rttest"), platform_answer("NUC"));
    bs::test::key(&w, Qt::Key_I, Qt::ControlModifier);  // File > Import files…
    const QString message = bs::test::wait_for_import(w);
    QVERIFY2(bs::test::wait_until([&] { return person.done(); }, 100), qPrintable(person.report()));
    QVERIFY2(person.blocked.isEmpty() && person.gave_up.isEmpty(), qPrintable(person.report()));
    QVERIFY2(message.startsWith("Imported 2 file(s)") && !message.contains("cancelled"), qPrintable(message));
    std::map<QString, QString> platforms;
    for (const bs::StoredHeadroom& h : w.workspace()->headroom_measurements())
      platforms[QString::fromStdString(h.measurement.tool)] = QString::fromStdString(h.measurement.platform);
    QCOMPARE(platforms.size(), std::size_t{2});
    QCOMPARE(platforms.at("cyclictest"), QString("Jetson TX2"));
    QCOMPARE(platforms.at("rttest"), QString("NUC"));
  }

  void import_folder_with_an_mlperf_log_asks_too() {
    const QString spl = bs::test::kPublicPower + "/ptd-krai-xavier-run1-spl.txt";
    if (!QFileInfo::exists(spl))
      QSKIP(qPrintable("needs the public data folder " + bs::test::kPublicPower + " (BENCHSCOPE_PUBLIC_DATA_DIR)"));
    QTemporaryDir dir;
    const QString ws = bs::test::paper_workspace(dir);
    QVERIFY(!ws.isEmpty());
    // A folder as a lab hands it over: an MLPerf PTDaemon log and a meter CSV.
    const QString folder = dir.filePath("from-the-lab");
    QVERIFY(QDir().mkpath(folder));
    QVERIFY(QFile::copy(spl, folder + "/spl.txt"));
    QVERIFY(QFile::copy(bs::test::kScenarioData + "/meter-no-platform.csv", folder + "/meter.csv"));
    bs::ui::MainWindow w;
    QVERIFY(w.open_workspace(ws));
    QVERIFY(bs::test::show_at(w));
    ModalAnswerer person;
    person.expect("Import folder (file dialog)", ModalAnswerer::titled("Import folder"),
                  [&folder](QWidget* d) { bs::test::choose_file(d, folder); });
    // Files of a folder are imported in name order: meter.csv, then spl.txt.
    person.expect("Platform of meter.csv", ModalAnswerer::titled("Platform of meter.csv"), platform_answer("NUC"));
    person.expect("Platform of spl.txt", ModalAnswerer::titled("Platform of spl.txt"),
                  platform_answer("Jetson AGX Xavier"));
    bs::test::key(&w, Qt::Key_I, Qt::ControlModifier | Qt::ShiftModifier);  // File > Import folder…
    const QString message = bs::test::wait_for_import(w);
    QVERIFY2(bs::test::wait_until([&] { return person.done(); }, 100), qPrintable(person.report()));
    QVERIFY2(person.blocked.isEmpty() && person.gave_up.isEmpty(), qPrintable(person.report()));
    QVERIFY2(message.startsWith("Imported 2 file(s)") && !message.contains("cancelled"), qPrintable(message));
    const auto platforms = log_platforms(w);
    QCOMPARE(platforms.at("meter.csv"), QString("NUC"));
    QCOMPARE(platforms.at("spl.txt"), QString("Jetson AGX Xavier"));
  }
};

BENCHSCOPE_SCENARIO_MAIN(TestScenarioImportQuestion)
#include "test_scenario_import_question.moc"
