// SPDX-License-Identifier: GPL-3.0-or-later
// File > Export figure / Reproduce paper figures / Export report: the same renderers as `benchscope-cli figures`
// and `benchscope-cli report`, with a progress dialog that cancels between figures.
#include <qcustomplot.h>
#include <QBuffer>
#include <QDesktopServices>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QProgressDialog>
#include <QStatusBar>
#include <QTabWidget>
#include <QUrl>

#include "export_figure_dialog.h"
#include "frames/frame_store.h"
#include "main_window.h"
#include "platform/candidates_panel.h"
#include "platform/platform_view.h"
#include "plot_export.h"
#include "power/log_choice_bar.h"
#include "report/candidates_section.h"
#include "report_dialog.h"
#include "report_writer.h"
#include "store/sustained_runs.h"
#include "workspace/workspace_tree.h"

namespace bs::ui {
namespace {

// Runs `work` with a modal progress dialog whose Cancel fires the token; the work's progress callback keeps the
// GUI responsive (rendering uses QWidgets, so it must stay on the GUI thread).
using ProgressCallback = std::function<void(int done, int total, const QString& what)>;

bool with_progress(QWidget* parent, const QString& title,
                   const std::function<void(const CancelToken&, const ProgressCallback&)>& work) {
  QProgressDialog dialog(title, QObject::tr("Cancel"), 0, 1, parent);
  dialog.setWindowModality(Qt::WindowModal);
  dialog.setMinimumDuration(300);
  CancelToken cancel;
  QObject::connect(&dialog, &QProgressDialog::canceled, parent, [&cancel] { cancel.cancel(); });
  try {
    work(cancel, [&](int done, int total, const QString& what) {
      dialog.setMaximum(total);
      dialog.setValue(done);
      dialog.setLabelText(QObject::tr("%1: %2").arg(title, what));
      QCoreApplication::processEvents();
      if (dialog.wasCanceled()) cancel.cancel();
    });
  } catch (const Cancelled&) {
    parent->window()->findChild<QStatusBar*>()->showMessage(QObject::tr("%1 cancelled; nothing was written").arg(title),
                                                            8000);
    return false;
  } catch (const std::exception& e) {
    QMessageBox::warning(parent, title, QString::fromUtf8(e.what()));
    return false;
  }
  return true;
}

}  // namespace

FigureData MainWindow::figure_data() const {
  FigureData d;
  const QSet<qint64> ticked = tree_->visible_runs();
  for (const StoredRun& r : runs_) {
    d.colors[{r.run.platform, r.run.device}] = r.color_index;
    if (!ticked.contains(r.id)) continue;
    d.runs.push_back(r.run);
    const auto label = run_labels_.find(r.id);
    d.run_labels.push_back(label == run_labels_.end() ? std::string() : label->second);
  }
  d.selection = "runs ticked in the workspace (" + std::to_string(d.runs.size()) + " of " +
                std::to_string(runs_.size()) + "), all power logs and pipeline runs";
  if (workspace_) {
    std::vector<StoredPowerTrace> traces = workspace_->power_traces();
    order_chosen_logs_first(*workspace_, traces);  // as in the views: each platform's chosen log first
    for (StoredPowerTrace& t : traces) d.traces.push_back(std::move(t.trace));
    std::vector<PipelineRun> pipelines;
    for (auto& p : workspace_->pipeline_runs()) pipelines.push_back(std::move(p.run));
    d.pipelines = pipeline_timings(pipelines);
    for (auto& r : workspace_->dnn_runs()) d.inference_runs.push_back(std::move(r.run));
    for (auto& h : workspace_->headroom_measurements()) d.headroom.push_back(std::move(h.measurement));
    d.sustain_runs = sustained_runs_of(*workspace_);
    // fig3 shows the workspace's first capture; a referenced file that moved or changed is an error naming it.
    if (const auto frames = workspace_->frames(); !frames.empty()) d.frame = load_frame(*workspace_, frames.front());
  }
  return d;
}

QString MainWindow::export_folder() const {
  const QString ws = workspace_ ? QString::fromStdString(workspace_->path()) : QString();
  return ws.isEmpty() ? QDir::homePath() : QFileInfo(ws).absolutePath();
}

void MainWindow::export_current_figure() {
  auto* tabs = static_cast<QTabWidget*>(centralWidget());
  QCustomPlot* plot = nullptr;
  for (QCustomPlot* p : tabs->currentWidget()->findChildren<QCustomPlot*>())
    if (p->isVisible()) {
      plot = p;
      break;
    }
  if (!plot) {
    QMessageBox::information(
        this, tr("Export figure"),
        tr("The %1 tab has no plot to export; its tables export as LaTeX or CSV from the tab itself.")
            .arg(tabs->tabText(tabs->currentIndex()).remove('&')));
    return;
  }
  const QString name = tabs->tabText(tabs->currentIndex()).remove('&').toLower();
  ExportFigureDialog dialog(ExportFigureDialog::Target::FileStem, QDir(export_folder()).filePath(name), this);
  dialog.set_preview([plot](const FigureOptions& o) { return render_export_preview(*plot, o, 640); });
  if (dialog.exec() != QDialog::Accepted) return;
  try {
    QStringList files;
    export_plot(*plot, dialog.destination(), dialog.options(), tabs->tabText(tabs->currentIndex()).remove('&'), files);
    statusBar()->showMessage(tr("Wrote %1").arg(files.join(", ")), 10000);
  } catch (const std::exception& e) {
    QMessageBox::warning(this, tr("Export figure"), QString::fromUtf8(e.what()));
  }
}

void MainWindow::reproduce_paper_figures() {
  ExportFigureDialog dialog(ExportFigureDialog::Target::Folder, QDir(export_folder()).filePath("figures"), this);
  if (dialog.exec() != QDialog::Accepted) return;
  const QString folder = dialog.destination();
  QStringList files, contents;
  const bool ok =
      with_progress(this, tr("Paper figures"), [&](const CancelToken& cancel, const ProgressCallback& progress) {
        const auto templates = load_figure_templates(paper_template_path().toStdString());
        const FigureOutput out = render_figures(templates, select_figure_data(figure_data(), dialog.data_choice()),
                                                folder, dialog.options(), cancel, progress);
        files = out.files;
        contents = out.contents;
      });
  if (!ok) return;
  // What each figure shows and what it left out (and why) is said here, not hidden: a figure that silently mixed a
  // run measured on this machine into the paper's data, or dropped a power log, would mislead a reader.
  QString text =
      tr("Wrote %1 files (figures, tables and figures.json) to %2.<ul>").arg(files.size()).arg(folder.toHtmlEscaped());
  for (const QString& line : contents) text += "<li>" + line.toHtmlEscaped() + "</li>";
  text += "</ul>";
  QMessageBox box(QMessageBox::Information, tr("Paper figures"), text, QMessageBox::Ok, this);
  box.setTextFormat(Qt::RichText);
  QPushButton* open = box.addButton(tr("Open folder"), QMessageBox::ActionRole);
  box.setDetailedText(files.join('\n'));
  box.exec();
  if (box.clickedButton() == open) QDesktopServices::openUrl(QUrl::fromLocalFile(folder));
}

// The decision the report will state, in the words of its first page: shown in the report dialog before writing.
QStringList MainWindow::report_decision_lines() const {
  const StoredDecision d = platforms_->decision();
  const std::string c = describe_constraints(d);  // the control loop too
  const QString recommended = platforms_->recommendation();
  QStringList lines;
  lines << tr("<b>Constraints:</b> %1").arg(c.empty() ? tr("none set") : QString::fromStdString(c).toHtmlEscaped());
  lines << (recommended.isEmpty()
                ? tr("<b>Recommendation:</b> none (no platform with a power log meets every constraint)")
                : tr("<b>Recommended%1:</b> %2")
                      .arg(c.empty() ? QString() : tr(" under these constraints"), recommended.toHtmlEscaped()));
  const ComparisonOptions o = platforms_->options();
  QString battery =
      tr("<b>Battery:</b> %1 V, %2 Ah").arg(o.battery_nominal_v, 0, 'f', 1).arg(o.battery_capacity_ah, 0, 'f', 2);
  if (o.extra_load_w > 0) battery += tr(", parallel load %1 W").arg(o.extra_load_w, 0, 'f', 1);
  if (!o.mission.empty()) battery += tr(", mission %1").arg(QString::fromStdString(o.mission).toHtmlEscaped());
  lines << battery;
  lines << tr("<b>Library candidates:</b> %1")
               .arg(d.candidates.empty() ? tr("none") : QString::fromStdString(d.candidates).toHtmlEscaped());
  if (!log_choices_.empty() && !log_choices_.front()->text().isEmpty())
    lines << tr("<b>Power logs:</b> %1").arg(log_choices_.front()->text().toHtmlEscaped());
  return lines;
}

void MainWindow::export_report() {
  ReportDialog dialog(QDir(export_folder()).filePath("report.pdf"), report_decision_lines(), this);
  if (dialog.exec() != QDialog::Accepted) {
    if (dialog.change_requested())
      static_cast<QTabWidget*>(centralWidget())->setCurrentWidget(platforms_->parentWidget());
    return;
  }
  const QString path = dialog.path();
  ReportRequest request;
  request.workspace_name =
      workspace_ ? QFileInfo(QString::fromStdString(workspace_->path())).fileName() : tr("untitled");
  (dialog.pdf() ? request.pdf_path : request.html_path) = path;
  request.constraints = platforms_->constraints();
  request.comparison = platforms_->options();
  request.loop = platforms_->loop_requirement();            // the Platforms tab's control loop, when set and readable
  request.sustained = platforms_->sustained_requirement();  // and its sustained requirement
  if (workspace_)
    for (const auto& [platform, id] : chosen_logs(*workspace_)) request.chosen_log_platforms.push_back(platform);
  // The Platforms tab's candidates (library computers chosen there) become the report's "Candidates" section,
  // with the tab's figure embedded in an HTML report.
  if (const CandidatesPanel* cp = platforms_->candidates(); !cp->selection().isEmpty()) {
    std::string figure;
    if (request.pdf_path.isEmpty()) {
      QByteArray png;
      QBuffer buffer(&png);
      buffer.open(QIODevice::WriteOnly);
      cp->plot()->toPixmap(900, 560).save(&buffer, "PNG");
      figure = "data:image/png;base64," + png.toBase64().toStdString();
    }
    request.candidates = CandidatesSectionInput{cp->classes(), cp->peaks(), cp->selection().toStdString(),
                                                describe_constraints(request.constraints), figure};
  }
  QStringList files;
  const bool ok = with_progress(this, tr("Report"), [&](const CancelToken& cancel, const ProgressCallback& progress) {
    const auto templates = load_figure_templates(paper_template_path().toStdString());
    files = write_report(request, templates, figure_data(), FigureOptions{}, cancel, progress);
  });
  if (ok) statusBar()->showMessage(tr("Wrote %1").arg(files.join(", ")), 10000);
}

}  // namespace bs::ui
