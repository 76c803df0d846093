// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The main window as a scenario test meets it (issue #43): started like `benchscope WORKSPACE` or
// `benchscope sample_data/paper-2018` starts it, shown at a person's screen size, its tabs and menus used with
// clicks and keys (tests/support/scenario.h), the status bar read as a person reads it.
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QStatusBar>
#include <QTabBar>
#include <QTabWidget>
#include <QTemporaryDir>

#include "main_window.h"
#include "scenario.h"
#include "vision/lens_view_3d.h"

namespace bs::test {

inline const QString kPaperData = QStringLiteral(BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018");
inline const QString kScenarioData = QStringLiteral(BENCHSCOPE_TEST_DATA_DIR "/scenarios");
inline const QString kPublicPower = QStringLiteral(BENCHSCOPE_PUBLIC_DATA_DIR "/tests/data/power/real");

// The central tab widget and one of its tabs brought to the front by a click on its tab, as a person does.
inline QTabWidget* tabs(bs::ui::MainWindow& w) { return static_cast<QTabWidget*>(w.centralWidget()); }
inline QWidget* open_tab(bs::ui::MainWindow& w, const QString& name) {
  QTabWidget* t = tabs(w);
  for (int i = 0; i < t->count(); ++i)
    if (plain(t->tabText(i)) == name) {
      click(t->tabBar(), Qt::LeftButton, {}, t->tabBar()->tabRect(i).center());
      wait_until([&] { return t->currentIndex() == i; }, 50);
      return t->widget(i);
    }
  return nullptr;
}

inline QString status(bs::ui::MainWindow& w) { return w.statusBar()->currentMessage(); }

// Waits for the message a finished import leaves in the status bar ("Imported 2 file(s) ..."), and returns it.
inline QString wait_for_import(bs::ui::MainWindow& w, int polls = 3000) {
  wait_until([&] { return status(w).startsWith(QStringLiteral("Imported")); }, polls);
  return status(w);
}

// A workspace file holding the paper's sample data, written the way `benchscope-cli import` would (the GUI's own
// command-line import, without questions: every paper file names its platform).
inline QString paper_workspace(QTemporaryDir& dir, const QString& name = QStringLiteral("paper.bsw")) {
  const QString path = dir.filePath(name);
  bs::ui::MainWindow w;
  if (!w.open_workspace(path)) return {};
  w.import_paths_now({kPaperData});
  return path;
}

// The window as a person sees it: shown at `width` x `height`, exposed, the event loop run once.
inline bool show_at(bs::ui::MainWindow& w, int width = 1600, int height = 1000) {
  w.resize(width, height);
  w.show();
  if (!QTest::qWaitForWindowExposed(&w)) return false;
  w.activateWindow();
  QTest::qWait(50);
  return true;
}

}  // namespace bs::test

// main() of a scenario test: VTK's views need their OpenGL format before the QApplication exists, as in
// app/gui/main.cpp; settings go to a test organisation so a developer's own window layout is never touched.
#define BENCHSCOPE_SCENARIO_MAIN(TestClass)                          \
  int main(int argc, char** argv) {                                  \
    bs::ui::set_vtk_default_surface_format();                        \
    QApplication app(argc, argv);                                    \
    QCoreApplication::setOrganizationName("BenchScopeScenarioTest"); \
    QCoreApplication::setApplicationName(#TestClass);                \
    TestClass test;                                                  \
    return QTest::qExec(&test, argc, argv);                          \
  }
