// SPDX-License-Identifier: GPL-3.0-or-later
// Imported latency files in the real main window, as a person brings them: cyclictest, rttest and performance_test
// files dropped on the window, the platform question answered in its dialog (through the event loop), then the
// Headroom tab listing each result by kind beside any measured here: a cyclictest histogram drawn per thread with
// its overflows, a performance_test summary drawn as nothing (no histogram) with dashes for what it does not know.
// Screenshots at 1280x800 and 1600x1000 when BENCHSCOPE_SCREENSHOT_DIR is set.
#include <qcustomplot.h>
#include <QApplication>
#include <QComboBox>
#include <QInputDialog>
#include <QLabel>
#include <QMimeData>
#include <QSettings>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUrl>

#include "headroom/headroom_view.h"
#include "main_window.h"

namespace {

const QString kFixtures = BENCHSCOPE_TEST_DATA_DIR "/headroom/";

int find_entry(const QComboBox* chooser, const QString& text) {
  for (int i = 0; i < chooser->count(); ++i)
    if (chooser->itemText(i).contains(text)) return i;
  return -1;
}

int column_of(const QTableWidget* t, const QString& header) {
  for (int c = 0; c < t->columnCount(); ++c)
    if (t->horizontalHeaderItem(c) && t->horizontalHeaderItem(c)->text() == header) return c;
  return -1;
}

}  // namespace

class TestHeadroomImportTab : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() { QSettings().clear(); }  // each run starts as a fresh machine: nothing remembered

  void dropped_files_appear_in_the_headroom_tab() {
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    QVERIFY(w.open_workspace(dir.filePath("imports.bsw")));
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));

    // Every platform question is answered like a person would: the dialog's text set to "rpi4", then OK.
    int asked = 0;
    QTimer answer;
    // The import's progress dialog may stand above the question, so the question is found among the windows.
    connect(&answer, &QTimer::timeout, this, [&] {
      for (QWidget* top : QApplication::topLevelWidgets())
        if (auto* d = qobject_cast<QInputDialog*>(top); d && d->isVisible()) {
          ++asked;
          d->setTextValue("rpi4");
          d->accept();
        }
    });
    answer.start(20);

    auto* mime = new QMimeData;
    mime->setUrls({QUrl::fromLocalFile(kFixtures + "cyclictest-2.6-H20-2thr-overflows.txt"),
                   QUrl::fromLocalFile(kFixtures + "rttest-log-1khz-misses.txt"),
                   QUrl::fromLocalFile(kFixtures + "perftest-2x-per-interval.csv")});
    // As a drag does: the window is entered (and accepts), then the files are let go over it.
    QDragEnterEvent enter(QPoint(200, 200), Qt::CopyAction, mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(&w, &enter);
    QVERIFY(enter.isAccepted());
    QDropEvent drop(QPointF(200, 200), Qt::CopyAction, mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(&w, &drop);
    // The window reloads its views when the import has finished; until then the test reads only what the window
    // shows (the workspace is being written on the importing thread).
    auto* tabs = qobject_cast<QTabWidget*>(w.centralWidget());
    bs::ui::HeadroomView* view = w.headroom_view();
    tabs->setCurrentWidget(view);
    QTRY_COMPARE_WITH_TIMEOUT(view->chooser()->count(), 3, 120000);
    QCOMPARE(asked, 3);  // none of the three files names its machine
    answer.stop();
    for (const auto& s : w.workspace()->headroom_measurements()) QCOMPARE(s.measurement.platform, std::string("rpi4"));

    // cyclictest: system wake-up latency, one step line per thread, the overflows in the legend.
    const int cyclictest = find_entry(view->chooser(), "cyclictest");
    QVERIFY(cyclictest >= 0);
    QVERIFY2(view->chooser()->itemText(cyclictest).contains("system wake-up latency"),
             qPrintable(view->chooser()->itemText(cyclictest)));
    view->chooser()->setCurrentIndex(cyclictest);
    QCOMPARE(view->plot()->graphCount(), 2);
    QVERIFY2(view->plot()->graph(1)->name().contains("3 beyond 20"), qPrintable(view->plot()->graph(1)->name()));
    QCOMPARE(view->table()->rowCount(), 2);
    QVERIFY(view->flags_label()->text().contains("20 us histogram"));
    shoot(w, "headroom-import-cyclictest");

    // rttest: an application loop with its misses counted iteration by iteration; its policy is not in the file.
    view->chooser()->setCurrentIndex(find_entry(view->chooser(), "rttest"));
    QCOMPARE(view->plot()->graphCount(), 1);
    QCOMPARE(view->table()->item(0, column_of(view->table(), "Longest miss run"))->text(), QString("2"));
    QVERIFY(view->flags_label()->text().contains("policy unknown"));

    // performance_test: message latency, summary only: nothing to draw, "not in the file" where a histogram would
    // answer (#51).
    view->chooser()->setCurrentIndex(find_entry(view->chooser(), "performance_test"));
    QVERIFY(view->chooser()->currentText().contains("message latency"));
    QCOMPARE(view->plot()->graphCount(), 0);
    QCOMPARE(view->table()->item(0, column_of(view->table(), "p99"))->text(), QString("not in the file"));
    QCOMPARE(view->table()->item(0, column_of(view->table(), "Max"))->text(), QString("241 us"));
    QCOMPARE(view->table()->item(0, column_of(view->table(), "n"))->text(), QString("299"));
    QVERIFY(view->flags_label()->text().contains("summary only"));
    shoot(w, "headroom-import-perftest");
  }

 private:
  void shoot(bs::ui::MainWindow& w, const QString& name) {
    const QByteArray shots = qgetenv("BENCHSCOPE_SCREENSHOT_DIR");
    if (shots.isEmpty()) return;
    for (const QSize size : {QSize(1280, 800), QSize(1600, 1000)}) {
      w.resize(size);
      QTest::qWait(50);
      QVERIFY(w.grab().save(QStringLiteral("%1/%2-%3x%4.png")
                                .arg(QString::fromLocal8Bit(shots), name)
                                .arg(size.width())
                                .arg(size.height())));
    }
  }
};

QTEST_MAIN(TestHeadroomImportTab)
#include "test_headroom_import_tab.moc"
