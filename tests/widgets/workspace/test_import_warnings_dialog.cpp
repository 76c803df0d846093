// SPDX-License-Identifier: GPL-3.0-or-later
// The import's warnings listed in a window, each whole (issue #51), not a count in the status bar: a hand-made
// report, and a real folder of loose MLPerf files whose power log has no detail log beside it.
#include <QListWidget>
#include <QTemporaryDir>
#include <QTest>

#include <filesystem>

#include "workspace/import_controller.h"
#include "workspace/import_warnings_dialog.h"

#include "../../support/public_data.h"

class TestImportWarningsDialog : public QObject {
  Q_OBJECT
 private slots:
  void lists_every_warning_and_skip() {
    bs::ui::ImportReport r;
    r.imported = 2;
    r.warnings << "a_summary.txt: no system description beside it"
               << "a_spl.txt: its mean is over the whole log";
    r.skipped << "a_detail.txt: read with its LoadGen summary a_summary.txt, not on its own";
    bs::ui::ImportWarningsDialog d;
    d.set_report(r);
    QVERIFY(!d.isModal());
    QCOMPARE(d.list()->count(), 3);
    QCOMPARE(d.list()->item(1)->text(), QString("warning: a_spl.txt: its mean is over the whole log"));
    QVERIFY2(d.text().startsWith("Imported 2 file(s), skipped 1, 2 warning(s)"), qPrintable(d.text()));
    // The next import replaces the list.
    r.warnings.clear();
    r.skipped.clear();
    r.warnings << "one";
    d.set_report(r);
    QCOMPARE(d.list()->count(), 1);
  }

  void a_real_loose_folder_says_why() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA("resources/library/sources");
    namespace fs = std::filesystem;
    const fs::path run = bs::test::public_data(
        "resources/library/sources/mlcommons+inference_results_v3.0/closed/NVIDIA/results/Orin_TRT_MaxQ/resnet50/"
        "Offline/performance/run_1");
    QTemporaryDir dir, ws;
    const fs::path d = dir.path().toStdString();
    // A lab's names, and no detail log: the power log's mean is the whole log's, which a warning says.
    fs::copy_file(run / "mlperf_log_summary.txt", d / "Orin_TRT_MaxQ_resnet50_Offline_summary.txt");
    fs::copy_file(run / "spl.txt", d / "Orin_TRT_MaxQ_resnet50_Offline_spl.txt");
    const bs::ui::ImportReport r = bs::ui::ImportController::import_now(
        ws.filePath("w.bsw"), {QString::fromStdString(d.string())}, bs::CancelToken{});
    QCOMPARE(r.imported, 1);
    bs::ui::ImportWarningsDialog dlg;
    dlg.set_report(r);
    QVERIFY2(dlg.text().contains("Orin_TRT_MaxQ_resnet50_Offline_spl.txt: a power log without LoadGen's"),
             qPrintable(dlg.text()));
    QVERIFY(dlg.text().contains("read with its LoadGen summary"));
  }
};

QTEST_MAIN(TestImportWarningsDialog)
#include "test_import_warnings_dialog.moc"
