// SPDX-License-Identifier: GPL-3.0-or-later
// A few crafted damaged workspaces (tests/data/bad-workspaces, issue #37) opened in the main window, offscreen: the
// banner lists the damaged items, the workspace is read-only (title, refused writes, the file's bytes unchanged),
// and "Remove damaged items…" after its confirmation removes them and makes the workspace writable again.
#include <QApplication>
#include <QCoreApplication>
#include <QFile>
#include <QMessageBox>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QToolBar>

#include "../../support/bad_workspaces.h"
#include "main_window.h"
#include "workspace/damage_banner.h"

namespace {

QByteArray bytes_of(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

}  // namespace

class TestDamageBanner : public QObject {
  Q_OBJECT
  QTemporaryDir dir_;
  QString base_;

  std::string make(const std::string& name) {
    for (const auto& c : bs::test::load_bad_workspaces(BENCHSCOPE_TEST_DATA_DIR))
      if (c.name == name) return bs::test::make_bad_workspace(c, base_.toStdString(), dir_.path().toStdString());
    return {};
  }

 private slots:
  void initTestCase() {
    base_ = dir_.filePath("paper.bsw");
    {
      bs::ui::MainWindow w;  // closed at the end of the scope, so the file is complete without its WAL
      QVERIFY(w.open_workspace(base_));
      w.import_paths_now({BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018"});
    }
  }

  void sound_workspace_has_no_banner() {
    bs::ui::MainWindow w;
    QVERIFY(w.open_workspace(base_));
    auto* banner = w.findChild<bs::ui::DamageBanner*>("damageBanner");
    QVERIFY(banner);
    QVERIFY(!banner->isVisibleTo(&w));
    QVERIFY(!w.workspace()->read_only());
    QVERIFY(!w.windowTitle().contains("read-only"));
  }

  void damaged_items_are_listed_and_the_workspace_is_read_only_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("item");
    QTest::newRow("workers negated") << "run-samples-workers-negated"
                                     << "run #";
    QTest::newRow("samples huge") << "power-traces-samples-huge"
                                  << "power trace #";
    QTest::newRow("stage n zero") << "pipeline-stages-n-zero"
                                  << "pipeline run #";
  }

  void damaged_items_are_listed_and_the_workspace_is_read_only() {
    QFETCH(QString, name);
    QFETCH(QString, item);
    const QString path = QString::fromStdString(make(name.toStdString()));
    QVERIFY(!path.isEmpty());
    const QByteArray before = bytes_of(path);
    {
      bs::ui::MainWindow w;
      QVERIFY(w.open_workspace(path));
      w.show();
      auto* banner = w.findChild<bs::ui::DamageBanner*>("damageBanner");
      QVERIFY(banner && banner->isVisibleTo(&w));
      QVERIFY2(banner->text().contains("Read-only") && banner->text().contains(item), qPrintable(banner->text()));
      QVERIFY(w.workspace()->read_only());
      QVERIFY2(w.windowTitle().contains("(read-only)"), qPrintable(w.windowTitle()));
      // A write the GUI would make (a setting, as the Battery tab saves a preset) is refused.
      bool refused = false;
      try {
        const_cast<bs::Workspace*>(w.workspace())->set_setting("battery/x", "{}");
      } catch (const bs::WorkspaceError& e) {
        refused = QString::fromUtf8(e.what()).contains("damaged");
      }
      QVERIFY(refused);
    }
    QVERIFY2(bytes_of(path) == before, "opening a damaged workspace in the GUI wrote to it");
  }

  void remove_button_asks_then_removes() {
    const QString path = QString::fromStdString(make("run-samples-workers-negated"));
    bs::ui::MainWindow w;
    QVERIFY(w.open_workspace(path));
    w.show();
    auto* banner = w.findChild<bs::ui::DamageBanner*>("damageBanner");
    QVERIFY(banner && banner->isVisibleTo(&w));
    const std::size_t runs_before = w.workspace()->runs().size();
    // Cancel first: nothing happens.
    QTimer::singleShot(0, [] {
      auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
      QVERIFY(box);
      box->reject();
    });
    emit banner->remove_requested();
    QVERIFY(w.workspace()->read_only());
    // Then the destructive button.
    QTimer::singleShot(0, [] {
      auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
      QVERIFY(box);
      QVERIFY(box->detailedText().contains("run_samples.workers"));
      for (QAbstractButton* b : box->buttons())
        if (box->buttonRole(b) == QMessageBox::DestructiveRole) b->click();
    });
    emit banner->remove_requested();
    QVERIFY(!w.workspace()->read_only());
    QVERIFY(w.workspace()->damage().empty());
    QVERIFY(!banner->isVisibleTo(&w));
    QCOMPARE(w.workspace()->runs().size(), runs_before);  // the damaged run was already left out
    QVERIFY(!w.windowTitle().contains("read-only"));
  }
};

QTEST_MAIN(TestDamageBanner)
#include "test_damage_banner.moc"
