// SPDX-License-Identifier: GPL-3.0-or-later
// The window's menus and actions, apart from main_window.cpp so the window itself stays about wiring views.
#include <qcustomplot.h>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QFileDialog>
#include <QMenuBar>
#include <QMessageBox>
#include <QScreen>
#include <QTabWidget>
#include <QTextBrowser>
#include <QUndoStack>
#include <QVBoxLayout>
#include <algorithm>

#include "main_window.h"
#include "peaks/flops_plot.h"
#include "platform/compare_dialog.h"
#include "vision/frames_view.h"
#include "workspace/import_controller.h"
#include "workspace/recent_files.h"

namespace bs::ui {

void MainWindow::compare_with_workspace() {
  if (!workspace_) {
    QMessageBox::information(this, tr("Compare"), tr("Open the baseline workspace (A) first."));
    return;
  }
  const QString other = QFileDialog::getOpenFileName(this, tr("Compare with workspace (B)"), {},
                                                     tr("BenchScope workspace (*.bsw);;All files (*)"));
  if (other.isEmpty()) return;
  try {
    const Workspace b(other.toStdString(), Workspace::OpenMode::ReadOnly);
    std::vector<FlopsRun> runs_a, runs_b;
    std::vector<ResultSet> sets_a, sets_b;
    for (const StoredRun& r : workspace_->runs()) runs_a.push_back(r.run);
    for (const StoredRun& r : b.runs()) runs_b.push_back(r.run);
    for (const StoredResultSet& s : workspace_->result_sets()) sets_a.push_back(s.set);
    for (const StoredResultSet& s : b.result_sets()) sets_b.push_back(s.set);
    CompareDialog dialog(runs_a, sets_a, runs_b, sets_b,
                         QFileInfo(QString::fromStdString(workspace_->path())).fileName(), QFileInfo(other).fileName(),
                         this);
    dialog.exec();
  } catch (const std::exception& e) {
    QMessageBox::warning(this, tr("Compare"), QString::fromUtf8(e.what()));
  }
}

void MainWindow::create_actions() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  auto add = [this](QMenu* menu, const QString& text, const QKeySequence& key, const QString& tip, auto slot) {
    QAction* a = menu->addAction(text, this, slot);
    a->setShortcut(key);
    a->setStatusTip(tip);
    a->setToolTip(tip);
    return a;
  };
  add(file, tr("&New workspace"), QKeySequence::New, tr("Start an empty, untitled workspace"),
      [this] { new_untitled_workspace(); });
  add(file, tr("&Open workspace…"), QKeySequence::Open, tr("Open a BenchScope workspace (.bsw)"), [this] {
    const QString p =
        QFileDialog::getOpenFileName(this, tr("Open workspace"), {}, tr("BenchScope workspace (*.bsw);;All files (*)"));
    if (!p.isEmpty()) open_workspace(p);
  });
  recent_ = new RecentFiles(file->addMenu(tr("Open &recent")), this);
  connect(recent_, &RecentFiles::open_requested, this, [this](const QString& p) { open_workspace(p); });
  add(file, tr("&Save"), QKeySequence(Qt::CTRL | Qt::Key_S),
      tr("Every edit is written to the workspace file at once; Save keeps an untitled workspace under a name"),
      [this] { save(); });
  add(file, tr("Save workspace &as…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S),
      tr("Write a copy of the workspace under a new name and continue there"), [this] { save_as(); });
  file->addSeparator();
  add(file, tr("&Import files…"), QKeySequence(Qt::CTRL | Qt::Key_I),
      tr("Import run JSON, Google Benchmark JSON or clpeak output (formats are recognised by content)"), [this] {
        const QStringList files = QFileDialog::getOpenFileNames(this, tr("Import files"));
        if (!files.isEmpty()) import_paths(files);
      });
  add(file, tr("Import &folder…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_I),
      tr("Import every recognised file in a folder and its subfolders"), [this] {
        const QString dir = QFileDialog::getExistingDirectory(this, tr("Import folder"));
        if (!dir.isEmpty()) import_paths({dir});
      });
  file->addSeparator();
  add(file, tr("&Compare with workspace…"), QKeySequence(Qt::CTRL | Qt::Key_D),
      tr("Regression compare of this workspace (A) against another (B), as benchscope-cli compare does"),
      [this] { compare_with_workspace(); });
  QAction* copy_frames =
      add(file, tr("Copy imported &frames into the workspace"), QKeySequence(),
          tr("Store the pixels of imported frames in the workspace instead of a reference to the "
             "file (path + content hash)"),
          [this](bool on) { importer_->set_frame_storage(on ? FrameStorage::Copy : FrameStorage::Reference); });
  copy_frames->setCheckable(true);
  add(file, tr("Export &Figure 3 (triptych)…"), QKeySequence(),
      tr("The Frames tab's triptych as the paper's Figure 3 (PDF or PNG)"),
      [this] { frames_->export_figure_dialog(); });
  file->addSeparator();
  add(file, tr("&Export figure…"), QKeySequence(Qt::CTRL | Qt::Key_E),
      tr("Save the plot of the current tab as PDF, SVG or PNG at a journal width (LNCS, IEEE) with print fonts"),
      [this] { export_current_figure(); });
  add(file, tr("Reproduce &paper figures…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E),
      tr("Write fig1a-fig4, Tables 1 and 2 and figures.json from this workspace, as benchscope-cli figures does"),
      [this] { reproduce_paper_figures(); });
  add(file, tr("Export &report…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R),
      tr("One page per platform (peaks, power, GFLOPS/W, battery, timings) with the figures, as HTML or PDF"),
      [this] { export_report(); });
  file->addSeparator();
  add(file, tr("&Quit"), QKeySequence::Quit, tr("Quit BenchScope"), [this] { close(); });

  QMenu* edit = menuBar()->addMenu(tr("&Edit"));
  undo_edit_ = add(edit, tr("&Undo"), QKeySequence::Undo,
                   tr("Undo the last rename or removal in the workspace tree (the Lens tab has its own undo)"),
                   [this] { edits_->undo(); });
  redo_edit_ = add(edit, tr("&Redo"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), tr("Redo what Undo undid"),
                   [this] { edits_->redo(); });
  connect(edits_, &QUndoStack::undoTextChanged, this,
          [this](const QString& t) { undo_edit_->setText(t.isEmpty() ? tr("&Undo") : tr("&Undo %1").arg(t)); });
  connect(edits_, &QUndoStack::redoTextChanged, this,
          [this](const QString& t) { redo_edit_->setText(t.isEmpty() ? tr("&Redo") : tr("&Redo %1").arg(t)); });
  connect(edits_, &QUndoStack::canUndoChanged, this, &MainWindow::update_edit_actions);
  connect(edits_, &QUndoStack::canRedoChanged, this, &MainWindow::update_edit_actions);
  edit->addSeparator();
  add(edit, tr("Re&name selected item…"), QKeySequence(Qt::Key_F2),
      tr("Rename the platform, power log or frame selected in the workspace tree"),
      [this] { rename_item(tree_->current_ref()); });
  update_edit_actions();

  QMenu* view = menuBar()->addMenu(tr("&View"));
  QAction* log_x = add(view, tr("Log &worker axis"), QKeySequence(Qt::CTRL | Qt::Key_L), tr("Logarithmic worker axis"),
                       [this](bool on) { plot_->set_log_x(on); });
  log_x->setCheckable(true);
  log_x->setChecked(plot_->log_x());
  QAction* log_y = add(view, tr("Log &FLOPS axis"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_L),
                       tr("Logarithmic FLOPS axis"), [this](bool on) { plot_->set_log_y(on); });
  log_y->setCheckable(true);
  log_y->setChecked(plot_->log_y());
  add(view, tr("&Reset zoom"), QKeySequence(Qt::CTRL | Qt::Key_0), tr("Fit all visible series"),
      [this] { plot_->reset_view(); });
  view->addSeparator();
  for (QDockWidget* dock : findChildren<QDockWidget*>()) view->addAction(dock->toggleViewAction());
  add(view, tr("Reset &layout"), QKeySequence(),
      tr("Docks, the FLOPS and Platforms tabs' splits and the window size as on first start"),
      [this] { reset_layout(); });

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  add(help, tr("&Views and shortcuts"), QKeySequence::HelpContents,
      tr("What each tab shows and every keyboard shortcut"), [this] { show_help(); });
  add(help, tr("&About BenchScope"), QKeySequence(), tr("Version and licence"), [this] {
    QMessageBox::about(this, tr("About BenchScope"),
                       tr("<h3>BenchScope %1</h3><p>Which computer should this robot carry? FLOPS, power and vision "
                          "benchmarks compared, after Biddulph et al. 2018.</p><p>Licence: GPL-3.0-or-later.</p>"
                          "<p>Qt %2 · QCustomPlot %3 · OpenCV %4</p>")
                           .arg(BENCHSCOPE_VERSION, qVersion(), QCUSTOMPLOT_VERSION_STR, CV_VERSION_TEXT));
  });
}

// F1: the tabs (with what each shows, from their tooltips) and every menu shortcut, read from the window itself so
// the list can never fall behind the menus.
void MainWindow::show_help() {
  QString html = tr("<h3>Views</h3><table cellspacing='4'>");
  auto* tabs = static_cast<QTabWidget*>(centralWidget());
  for (int i = 0; i < tabs->count(); ++i)
    html += QStringLiteral("<tr><td><b>%1</b></td><td>%2</td></tr>")
                .arg(tabs->tabText(i).remove('&').toHtmlEscaped(), tabs->tabToolTip(i).toHtmlEscaped());
  html += tr("</table><h3>Keyboard shortcuts</h3><table cellspacing='4'>");
  for (QMenu* menu : menuBar()->findChildren<QMenu*>())
    for (QAction* a : menu->actions())
      if (!a->shortcut().isEmpty())
        html += QStringLiteral("<tr><td><tt>%1</tt></td><td>%2 ▸ %3</td></tr>")
                    .arg(a->shortcut().toString(QKeySequence::NativeText).toHtmlEscaped(),
                         menu->title().remove('&').toHtmlEscaped(),
                         a->text().remove('&').remove(QStringLiteral("…")).toHtmlEscaped());
  html +=
      tr("<tr><td><tt>Ctrl+Z / Ctrl+Shift+Z</tt></td><td>Lens tab: undo / redo a lens change</td></tr>"
         "<tr><td><tt>Ctrl+Shift+P / Del</tt></td><td>Lens tab: propose straight lines in the fisheye frame; "
         "delete the selected line</td></tr>"
         "<tr><td><tt>F2 / Del</tt></td><td>Workspace tree: rename the platform, power log or frame; remove "
         "the import that brought the selected item (Ctrl+Z outside the Lens tab undoes)</td></tr>"
         "<tr><td><tt>Double-click</tt></td><td>Platforms and peak tables: show where a number came from</td></tr>"
         "</table><p>The README's <i>Views</i> section and <tt>docs/cli.md</tt> describe every view and command.</p>");
  // A scrolling page in a dialog that fits the screen it opens on (a message box grew taller than a 1280x800 screen,
  // its Close button out of reach).
  QDialog box(this);
  box.setObjectName(QStringLiteral("help"));
  box.setWindowTitle(tr("BenchScope: views and shortcuts"));
  auto* page = new QTextBrowser(&box);
  page->setHtml(html);
  page->setOpenLinks(false);
  auto* close = new QDialogButtonBox(QDialogButtonBox::Close, &box);
  connect(close, &QDialogButtonBox::rejected, &box, &QDialog::reject);
  auto* layout = new QVBoxLayout(&box);
  layout->addWidget(page, 1);
  layout->addWidget(close);
  const QRect screen = (this->screen() ? this->screen() : QGuiApplication::primaryScreen())->availableGeometry();
  const int width = std::min(900, screen.width() * 9 / 10);
  page->document()->setTextWidth(width - 50);  // the page's height as wrapped at the dialog's width
  const int height = static_cast<int>(page->document()->size().height()) + 90;
  box.resize(width, std::min(height, screen.height() * 85 / 100));
  box.exec();
}

}  // namespace bs::ui
