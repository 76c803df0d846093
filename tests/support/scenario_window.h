// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The main window as a scenario test meets it (issue #43): started like `benchscope WORKSPACE` or
// `benchscope sample_data/paper-2018` starts it, shown at a person's screen size, its tabs and menus used with
// clicks and keys (tests/support/scenario.h), the status bar read as a person reads it; keys pressed on the window,
// modal dialogs answered through the running event loop (a timer looks for QApplication::activeModalWidget() while
// the dialog's exec() runs), never by calling the slots behind them.
#include <qcustomplot.h>
#include <QAbstractButton>
#include <QApplication>
#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QTabBar>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <functional>
#include <memory>

#include "export_figure_dialog.h"
#include "main_window.h"
#include "paper_dir.h"
#include "platform/candidates_panel.h"
#include "platform/platform_view.h"
#include "plot_export.h"
#include "scenario.h"
#include "test_registration.h"
#include "vision/lens_view_3d.h"

namespace bs::test {

// With BENCHSCOPE_LOOK_DIR set, a copy of `file` goes there under `name` (exports and reports to look at by eye).
inline void keep_for_looking(const QString& file, const QString& name) {
  const QString dir = qEnvironmentVariable("BENCHSCOPE_LOOK_DIR");
  if (dir.isEmpty() || !QFile::exists(file)) return;
  QDir().mkpath(dir);
  QFile::remove(QDir(dir).filePath(name));
  QFile::copy(file, QDir(dir).filePath(name));
}

// Calls `answer` with the first modal widget that opens from now on (polled every 20 ms, also inside a dialog's own
// event loop), once. Returns a flag that says whether it was answered.
inline std::shared_ptr<bool> answer_next_modal(QObject* context, std::function<void(QWidget*)> answer,
                                               int timeout_ms = 30000) {
  auto answered = std::make_shared<bool>(false);
  auto* timer = new QTimer(context);
  auto waited = std::make_shared<int>(0);
  QObject::connect(timer, &QTimer::timeout, context, [timer, answer, answered, waited, timeout_ms] {
    *waited += timer->interval();
    QWidget* modal = QApplication::activeModalWidget();
    if (modal && modal->isVisible()) {
      timer->stop();
      timer->deleteLater();
      *answered = true;
      answer(modal);
    } else if (*waited > timeout_ms) {
      timer->stop();
      timer->deleteLater();
    }
  });
  timer->start(20);
  return answered;
}

// Clicks the dialog's button `which` (Ok, Save, Open, Close ...) as a person would, once it is shown and enabled (a
// file dialog enables Save only after it has taken in the typed name); false when it never is (5 s).
inline bool click_dialog_button(QWidget* dialog, QDialogButtonBox::StandardButton which) {
  QPushButton* button = nullptr;
  const bool ready = QTest::qWaitFor(
      [&] {
        for (QDialogButtonBox* box : dialog->findChildren<QDialogButtonBox*>())
          if (QPushButton* b = box->button(which); b && b->isVisible() && b->isEnabled()) button = b;
        return button != nullptr;
      },
      5000);
  if (!ready) {
    qWarning("%s: its button %d never became clickable", dialog->metaObject()->className(), int(which));
    return false;
  }
  QTest::mouseClick(button, Qt::LeftButton);
  return true;
}

// Answers a file dialog as a person does: the path pasted into its file name field, then Save (or Open) clicked once
// the dialog has taken the name in. The field is filled again while the button stays disabled (the dialog reads the
// folder on a thread of its own and may not have it yet).
inline bool answer_file_dialog(QWidget* modal, const QString& path, const QString& filter = {}) {
  auto* files = qobject_cast<QFileDialog*>(modal);
  if (!files) {
    modal->close();
    return false;
  }
  if (!filter.isEmpty()) files->selectNameFilter(filter);
  auto* name = files->findChild<QLineEdit*>("fileNameEdit");
  const auto which = files->acceptMode() == QFileDialog::AcceptSave ? QDialogButtonBox::Save : QDialogButtonBox::Open;
  for (int attempt = 0; attempt < 10; ++attempt) {
    if (name) {
      name->setText(path);  // pasted: typed keys would open the field's completer, which takes the next click
      emit name->textEdited(path);
    } else {
      files->selectFile(path);
    }
    QPushButton* button = nullptr;
    for (QDialogButtonBox* box : files->findChildren<QDialogButtonBox*>())
      if (QPushButton* b = box->button(which)) button = b;
    if (button && QTest::qWaitFor([button] { return button->isEnabled(); }, 500)) {
      QTest::mouseClick(button, Qt::LeftButton);
      return true;
    }
  }
  qWarning("the file dialog never took '%s'", qPrintable(path));
  files->reject();
  return false;
}

// Answers File > Export report's dialog (app/gui/report_dialog.h) as a person does: the path pasted into its File
// field, then Export clicked. False when `modal` is not that dialog (it is closed then).
inline bool answer_report_dialog(QWidget* modal, const QString& path) {
  auto* file = modal->findChild<QLineEdit*>("reportPath");
  if (modal->windowTitle() != "Export report" || qobject_cast<QFileDialog*>(modal) || !file) {
    modal->close();
    return false;
  }
  file->setText(path);
  emit file->textEdited(path);
  QPushButton* ok = nullptr;
  for (QDialogButtonBox* box : modal->findChildren<QDialogButtonBox*>())
    for (QAbstractButton* b : box->buttons())
      if (box->buttonRole(b) == QDialogButtonBox::AcceptRole) ok = qobject_cast<QPushButton*>(b);
  if (!ok || !QTest::qWaitFor([ok] { return ok->isEnabled(); }, 5000)) {
    qWarning("the report dialog's Export button never became clickable");
    return false;
  }
  QTest::mouseClick(ok, Qt::LeftButton);
  return true;
}

// The window's tab widget and the plot File > Export figure would take from the current tab (its first visible
// one), or null.
inline QTabWidget* window_tabs(ui::MainWindow& w) { return qobject_cast<QTabWidget*>(w.centralWidget()); }
// Clicks tab `index` of the window's views, as a person does.
inline void click_tab(ui::MainWindow& w, int index) {
  QTabBar* bar = window_tabs(w)->tabBar();
  QTest::mouseClick(bar, Qt::LeftButton, {}, bar->tabRect(index).center());
  for (int k = 0; k < 5; ++k) QCoreApplication::processEvents();
}
// The tab that shows `view`: its page is the view or holds it (a tab may wrap its view, e.g. with a bar choosing logs).
inline int tab_of(ui::MainWindow& w, const QWidget* view) {
  QTabWidget* tabs = window_tabs(w);
  for (int t = 0; t < tabs->count(); ++t)
    if (tabs->widget(t) == view || tabs->widget(t)->isAncestorOf(view)) return t;
  return -1;
}
// Library candidates typed into the Platforms tab's field and entered, as a person does; false without the field.
inline bool type_library_candidates(ui::MainWindow& w, const QString& text) {
  click_tab(w, tab_of(w, w.platform_view()));
  auto* spec = w.platform_view()->candidates()->findChild<QLineEdit*>("library_selection");
  if (!spec) return false;
  spec->setFocus();
  QTest::keyClicks(spec, text);
  QTest::keyClick(spec, Qt::Key_Return);
  return true;
}
inline QCustomPlot* exported_plot(ui::MainWindow& w) {
  for (QCustomPlot* p : window_tabs(w)->currentWidget()->findChildren<QCustomPlot*>())
    if (p->isVisible()) return p;
  return nullptr;
}

// The names of the series a plot draws: its legend's entries (helper graphs such as bands and peak markers stay
// out of legends).
inline QStringList legend_names(QCustomPlot& plot) {
  QStringList names;
  for (int i = 0; i < plot.legend->itemCount(); ++i)
    if (auto* item = qobject_cast<QCPPlottableLegendItem*>(plot.legend->item(i)); item && item->plottable()->visible())
      // A series may carry its own name for paper (set_figure_name: no "hover" hint where nothing can be hovered).
      names << ui::figure_name(item->plottable());
  return names;
}

// Presses `key` on the window (its shortcut map routes it to the menu action). The window is made active first, as
// a window manager does when a dialog closes (the offscreen platform leaves no window active then).
inline void press(ui::MainWindow& w, int key, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
  if (QApplication::activeWindow() != &w) {
    w.activateWindow();
    if (!QTest::qWaitForWindowActive(&w)) qWarning("the main window did not become active");
  }
  QWidget* target = QApplication::focusWidget() && QApplication::focusWidget()->window() == &w
                        ? QApplication::focusWidget()
                        : static_cast<QWidget*>(&w);
  QTest::keyClick(target, static_cast<Qt::Key>(key), modifiers);
}

// Ctrl+E on the current tab, the export dialog answered: `stem` as the file, PDF only, at `preset` ("lncs",
// "ieee" ...), then Export clicked. Returns whether the dialog came and was answered.
inline bool export_current_tab(ui::MainWindow& w, const QString& stem, const QString& preset = "lncs") {
  const auto answered = answer_next_modal(&w, [stem, preset](QWidget* modal) {
    auto* dialog = qobject_cast<ui::ExportFigureDialog*>(modal);
    if (!dialog) {
      modal->close();
      return;
    }
    dialog->set_destination(stem);
    dialog->set_preset(preset);
    for (QCheckBox* box : dialog->findChildren<QCheckBox*>()) {
      const bool want = box->text() == "PDF";
      if (box->isChecked() != want) QTest::mouseClick(box, Qt::LeftButton);
    }
    click_dialog_button(dialog, QDialogButtonBox::Ok);
  });
  press(w, Qt::Key_E, Qt::ControlModifier);
  return *answered;
}

inline const QString kScenarioData = QStringLiteral(BENCHSCOPE_TEST_DATA_DIR "/scenarios");
inline const QString kPublicPower = QStringLiteral(BENCHSCOPE_PUBLIC_DATA_DIR "/tests/data/power/real");

// One of the central tabs brought to the front by a click on its tab, as a person does.
inline QWidget* open_tab(bs::ui::MainWindow& w, const QString& name) {
  QTabWidget* t = window_tabs(w);
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
  w.import_paths_now({kPaper});
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

// The window on a new paper workspace in `dir` (paper_workspace), shown as a person sees it (show_at): what most
// scenarios start from. "" when it worked, else which step failed.
inline QString open_paper_window(bs::ui::MainWindow& w, QTemporaryDir& dir) {
  const QString ws = paper_workspace(dir);
  if (ws.isEmpty()) return QStringLiteral("the paper workspace could not be written");
  if (!w.open_workspace(ws)) return QStringLiteral("the window could not open ") + ws;
  if (!show_at(w)) return QStringLiteral("the window was not exposed");
  return {};
}

// File > Export report (Ctrl+Shift+R) as a person does it: the report dialog answered from the event loop, the PDF
// path typed, Export. "" when `pdf` was written and no other dialog came, else what the person saw (the dialogs met
// and missed). `shown_decision` (may be null) receives the decision the dialog showed before the export.
inline QString export_report(bs::ui::MainWindow& w, const QString& pdf, QString* shown_decision = nullptr) {
  ModalAnswerer person;
  person.expect(
      "Export report (the report dialog)",
      [](QWidget* d) { return d->windowTitle() == "Export report" && !qobject_cast<QFileDialog*>(d); },
      [&pdf, shown_decision](QWidget* d) {
        if (auto* decision = d->findChild<QLabel*>("reportDecision"); decision && shown_decision)
          *shown_decision = decision->text();
        if (auto* path = d->findChild<QLineEdit*>("reportPath")) retype(path, pdf);
        if (QAbstractButton* ok = button(d, "Export")) click(ok);
      });
  key(&w, Qt::Key_R, Qt::ControlModifier | Qt::ShiftModifier);
  if (wait_until([&] { return person.done() && QFile::exists(pdf); }, 3000) && person.unexpected.isEmpty()) return {};
  return person.report();
}

}  // namespace bs::test

// main() of a scenario test: VTK's views need their OpenGL format before the QApplication exists, as in
// app/gui/main.cpp; settings go to a test organisation so a developer's own window layout is never touched. The
// function is registered under the test's file name (test_registration.h): the tests of tests/app/gui share one
// program, each run in its own process.
#define BENCHSCOPE_SCENARIO_MAIN(TestClass)                            \
  namespace {                                                          \
  int benchscope_scenario_main(int argc, char** argv) {                \
    bs::ui::set_vtk_default_surface_format();                          \
    QApplication app(argc, argv);                                      \
    QCoreApplication::setOrganizationName("BenchScopeScenarioTest");   \
    QCoreApplication::setApplicationName(#TestClass);                  \
    QSettings().clear(); /* each run starts as a fresh machine does */ \
    TestClass test;                                                    \
    return bs::test::test_exit_code(QTest::qExec(&test, argc, argv));  \
  }                                                                    \
  }                                                                    \
  BENCHSCOPE_TEST_CUSTOM_MAIN(benchscope_scenario_main)
