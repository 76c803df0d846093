// SPDX-License-Identifier: GPL-3.0-or-later
// The Headroom tab in the real main window, as a person uses it: set a short idle-only run (normal thread), press
// Run, wait for it to finish, see the measurement stored and drawn with its deadline line and flagged
// non-real-time; Ctrl+E opens the figure export for the histogram (answered through the event loop); a long run
// cancelled stores nothing. Screenshots at 1280x800 and 1600x1000 when BENCHSCOPE_SCREENSHOT_DIR is set.
#include <qcustomplot.h>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include "export_figure_dialog.h"
#include "headroom/headroom_run_panel.h"
#include "headroom/headroom_view.h"
#include "main_window.h"
#include "platform/platform_view.h"
#include "power/power_sensor_box.h"

class TestHeadroomTab : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() { QSettings().clear(); }  // each run starts as a fresh machine: nothing remembered

  void run_store_show_export_cancel() {
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    QVERIFY(w.open_workspace(dir.filePath("h.bsw")));
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    auto* tabs = qobject_cast<QTabWidget*>(w.centralWidget());
    bs::ui::HeadroomView* view = w.headroom_view();
    tabs->setCurrentWidget(view);
    bs::ui::HeadroomRunPanel* panel = view->run_panel();
    panel->rate()->setValue(500);
    panel->seconds()->setValue(0.5);
    panel->realtime()->setChecked(false);
    panel->loads()->clear();
    panel->command()->clear();
    panel->controls().power->choose("");
    QTest::mouseClick(panel->controls().run, Qt::LeftButton);
    QVERIFY(panel->controls().running());
    // Waits for the work (Run comes back when the result has been handed over); asserts nothing about its time.
    QTRY_VERIFY_WITH_TIMEOUT(panel->controls().run->isEnabled(), 120000);
    QVERIFY2(panel->controls().status->text().contains("NON-REAL-TIME"), qPrintable(panel->controls().status->text()));
    QCOMPARE(w.workspace()->headroom_measurements().size(), std::size_t{1});
    QCOMPARE(view->chooser()->count(), 1);
    QCOMPARE(view->plot()->graphCount(), 1);
    QVERIFY(view->plot()->graph(0)->name().startsWith("idle, max "));
    QCOMPARE(view->deadline()->value(), 2000);  // the period at 500 Hz
    QVERIFY(view->plot()->itemCount() >= 2);    // the deadline line and its label
    QCOMPARE(view->table()->rowCount(), 1);
    QVERIFY(view->flags_label()->text().contains("non-real-time"));

    // Ctrl+E: the figure export dialog for the tab's histogram, answered (cancelled) like a person would.
    bool asked = false;
    QTimer::singleShot(0, this, [&] {
      auto* d = qobject_cast<bs::ui::ExportFigureDialog*>(QApplication::activeModalWidget());
      asked = d != nullptr;
      if (d) d->reject();
    });
    QTest::keyClick(&w, Qt::Key_E, Qt::ControlModifier);
    QTRY_VERIFY(asked);

    // The window still fits the smallest screen the project supports with the tab (and the Platforms tab's
    // control-loop row) in it.
    w.resize(1280, 800);
    QTRY_COMPARE(w.width(), 1280);
    if (const QByteArray shots = qgetenv("BENCHSCOPE_SCREENSHOT_DIR"); !shots.isEmpty()) {
      for (const QSize size : {QSize(1280, 800), QSize(1600, 1000)}) {
        w.resize(size);
        QTest::qWait(50);
        QVERIFY(w.grab().save(QStringLiteral("%1/headroom-tab-%2x%3.png")
                                  .arg(QString::fromLocal8Bit(shots))
                                  .arg(size.width())
                                  .arg(size.height())));
      }
      tabs->setCurrentWidget(w.platform_view()->parentWidget());  // the tab page: the log choice above the view
      w.resize(1280, 800);
      QTest::qWait(50);
      QVERIFY(w.grab().save(QString::fromLocal8Bit(shots) + "/platforms-tab-loop-1280x800.png"));
      tabs->setCurrentWidget(view);
    }

    // A long run, cancelled once it measures: nothing more is stored.
    panel->seconds()->setValue(3600);
    QTest::mouseClick(panel->controls().run, Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(panel->controls().status->text().startsWith("Measuring"), 60000);
    QTest::mouseClick(panel->controls().cancel, Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(panel->controls().run->isEnabled(), 60000);
    QCOMPARE(panel->controls().status->text(), QString("Cancelled; nothing stored"));
    QCOMPARE(w.workspace()->headroom_measurements().size(), std::size_t{1});
  }
};

QTEST_MAIN(TestHeadroomTab)
#include "test_headroom_tab.moc"
