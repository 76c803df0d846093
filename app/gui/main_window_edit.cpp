// SPDX-License-Identifier: GPL-3.0-or-later
// Renaming and removing what the workspace tree lists, each one undo step (Edit > Undo, Ctrl+Z outside the Lens
// tab, which has its own undo for lens changes). Removing takes away the whole import that brought an item (the
// workspace stores files whole); undo adds the same content back from a snapshot taken before.
#include <QInputDialog>
#include <QMessageBox>
#include <QStatusBar>
#include <QTabWidget>
#include <QUndoCommand>
#include <QUndoStack>
#include <algorithm>
#include <functional>
#include <nlohmann/json.hpp>

#include "main_window.h"
#include "store/battery_preset_store.h"
#include "store/import_snapshot.h"
#include "store/record_kinds.h"
#include "store/run_label_store.h"
#include "vision/lens/lens.h"
#include "vision/lens_tab.h"

namespace bs::ui {
namespace {

// The action already done by the caller (so a failure never reaches the stack); redo and undo after that.
class WorkspaceCommand : public QUndoCommand {
 public:
  WorkspaceCommand(const QString& text, std::function<void()> redo, std::function<void()> undo,
                   std::function<void(const QString&)> report)
      : QUndoCommand(text), redo_(std::move(redo)), undo_(std::move(undo)), report_(std::move(report)) {}
  void redo() override {
    if (first_) {
      first_ = false;
      return;
    }
    run(redo_);
  }
  void undo() override { run(undo_); }

 private:
  void run(const std::function<void()>& f) {
    try {
      f();
    } catch (const std::exception& e) {
      report_(QString::fromUtf8(e.what()));
      setObsolete(true);  // the workspace no longer matches this step: drop it
    }
  }
  bool first_ = true;
  std::function<void()> redo_, undo_;
  std::function<void(const QString&)> report_;
};

// What an import holds, in its record kinds' words (store/record_kinds.h): "2 runs, 1 power log".
QString count_text(const ImportBatch& b) {
  RecordCounts counts;
  counts.add(b);
  return counts.total() == 0 ? QString() : QString::fromStdString(counts.summary());
}

QString file_name(const std::string& path) {
  const QString p = QString::fromStdString(path);
  return p.section('/', -1).isEmpty() ? p : p.section('/', -1);
}

QString provenance_line(const Provenance& p) {
  QStringList parts{QString::fromUtf8(to_string(p.origin).data())};
  for (const std::string* s : {&p.host, &p.tool, &p.sensor, &p.date, &p.source_file})
    if (!s->empty()) parts << QString::fromStdString(*s).toHtmlEscaped();
  return parts.join(QStringLiteral(" · "));
}

TreeItemRef item_ref(TreeItemRef::Kind kind, qint64 id, qint64 import_id, const QString& name) {
  TreeItemRef ref;
  ref.kind = kind;
  ref.id = id;
  ref.import_id = import_id;
  ref.name = name;
  return ref;
}

}  // namespace

std::vector<WorkspaceItem> MainWindow::workspace_items() const {
  std::vector<WorkspaceItem> out;
  if (!workspace_) return out;
  using K = TreeItemRef::Kind;
  // Summaries only (no samples): listing a 100-million-sample log costs the same as a short one.
  for (const StoredPowerTrace& t : workspace_->power_trace_summaries()) {
    const PowerTrace& tr_ = t.trace;
    const double duration = t.summary.duration_s;
    out.push_back({item_ref(K::PowerLog, t.id, t.import_id, QString::fromStdString(tr_.label)),
                   tr("%1 — %2").arg(QString::fromStdString(tr_.platform), QString::fromStdString(tr_.label)),
                   tr("<b>%1</b><br>%L2 samples over %3 s, %4 channel(s)<br>%5")
                       .arg(QString::fromStdString(tr_.label).toHtmlEscaped())
                       .arg(t.summary.samples)
                       .arg(duration, 0, 'f', 1)
                       .arg(tr_.channels.size())
                       .arg(provenance_line(tr_.provenance))});
  }
  for (const StoredFrame& f : workspace_->frames()) {
    const Frame& fr = f.frame;
    QString lens_line;
    if (!fr.lens_json.empty()) {
      try {
        lens_line = tr("<br>Lens: %1")
                        .arg(QString::fromStdString(vision::describe(
                            vision::lens_from_json(nlohmann::json::parse(fr.lens_json)).first.calibration)));
      } catch (const std::exception&) {
        lens_line = tr("<br>Lens: unreadable");
      }
    }
    out.push_back(
        {item_ref(K::Frame, f.id, f.import_id, QString::fromStdString(fr.label)),
         tr("%1 (%2×%3, %4-bit)").arg(QString::fromStdString(fr.label)).arg(fr.width).arg(fr.height).arg(fr.bit_depth),
         tr("<b>%1</b><br>%2<br>%3%4")
             .arg(QString::fromStdString(fr.label).toHtmlEscaped(), QString::fromStdString(f.path).toHtmlEscaped(),
                  provenance_line(fr.provenance), lens_line)});
  }
  for (const StoredPipelineRun& p : workspace_->pipeline_runs()) {
    const PipelineRun& r = p.run;
    out.push_back({item_ref(K::PipelineRun, p.id, p.import_id, QString::fromStdString(r.platform)),
                   tr("%1 — %2 (%3)")
                       .arg(QString::fromStdString(r.platform), QString::fromStdString(r.device),
                            QString::fromStdString(r.backend)),
                   tr("<b>%1</b>, %2 stage(s)<br>%3")
                       .arg(QString::fromStdString(r.platform).toHtmlEscaped())
                       .arg(r.stages.size())
                       .arg(provenance_line(r.provenance))});
  }
  for (const StoredResultSet& s : workspace_->result_sets()) {
    const ResultSet& r = s.set;
    out.push_back({item_ref(K::ResultSet, s.id, s.import_id, QString::fromStdString(r.device)),
                   tr("%1 — %2 (%3)")
                       .arg(QString::fromStdString(r.platform), QString::fromStdString(r.device),
                            QString::fromStdString(r.source_format)),
                   tr("<b>%1</b>, %2 measurement(s)<br>%3")
                       .arg(QString::fromStdString(r.device).toHtmlEscaped())
                       .arg(r.measurements.size())
                       .arg(provenance_line(r.provenance))});
  }
  for (const StoredHeadroom& h : workspace_->headroom_measurements()) {
    const headroom::HeadroomMeasurement& m = h.measurement;
    const QString kind = QString::fromStdString(std::string(headroom::to_string(m.kind)));
    out.push_back({item_ref(K::Headroom, h.id, h.import_id, QString::fromStdString(m.platform)),
                   tr("%1 — %2, %n phase(s)", nullptr, static_cast<int>(m.phases.size()))
                       .arg(QString::fromStdString(m.platform), kind),
                   tr("<b>%1</b>: %2 by %3%4<br>%5")
                       .arg(QString::fromStdString(m.platform).toHtmlEscaped(), kind,
                            QString::fromStdString(m.tool).toHtmlEscaped(),
                            m.realtime() ? QString() : tr(" (non-real-time: not comparable with real-time results)"),
                            provenance_line(m.provenance))});
  }
  // Inference and sustained runs had no rows: a user could not see or remove what such an import brought (#52).
  for (const StoredDnnRun& d : workspace_->dnn_runs()) {
    const DnnRun& r = d.run;
    out.push_back(
        {item_ref(K::InferenceRun, d.id, d.import_id, QString::fromStdString(r.platform)),
         tr("%1 — %2 %3×%4 (%5)")
             .arg(QString::fromStdString(r.platform), QString::fromStdString(r.model))
             .arg(r.input_width)
             .arg(r.input_height)
             .arg(QString::fromStdString(r.backend)),
         tr("<b>%1</b> on %2: %L3 ms per image, batch %4<br>%5")
             .arg(QString::fromStdString(r.model).toHtmlEscaped(), QString::fromStdString(r.device).toHtmlEscaped())
             .arg(r.inference_s() * 1e3, 0, 'f', 2)
             .arg(r.batch)
             .arg(provenance_line(r.provenance))});
  }
  for (const StoredSustainRun& s : workspace_->sustain_runs()) {
    const SustainRun& r = s.run;
    const double seconds = r.t_s.empty() ? 0.0 : r.t_s.back();
    out.push_back({item_ref(K::SustainedRun, s.id, s.import_id, QString::fromStdString(r.label)),
                   tr("%1 — %2").arg(QString::fromStdString(r.platform), QString::fromStdString(r.label)),
                   tr("<b>%1</b>: %2 intervals over %L3 s%4<br>%5")
                       .arg(QString::fromStdString(r.label).toHtmlEscaped())
                       .arg(r.t_s.size())
                       .arg(seconds, 0, 'f', 0)
                       .arg(r.rate_unit.empty() ? tr(", no rate (an imported log)")
                                                : tr(", rate in %1").arg(QString::fromStdString(r.rate_unit)))
                       .arg(provenance_line(r.provenance))});
  }
  for (const BatterySetup& b : workspace_battery_setups(*workspace_)) {
    out.push_back(
        {item_ref(K::BatteryPreset, 0, 0, QString::fromStdString(b.pack.name)), QString::fromStdString(b.pack.name),
         tr("Battery preset saved in this workspace: %1 V nominal, %2 Ah%3")
             .arg(b.pack.nominal_v())
             .arg(b.pack.capacity_ah)
             .arg(b.mission.empty() ? QString() : tr(", mission %1").arg(QString::fromStdString(b.mission)))});
  }
  return out;
}

void MainWindow::report_edit_error(const QString& message) {
  QMessageBox::warning(this, tr("Workspace"), message);
  reload();
}

void MainWindow::rename_item(const TreeItemRef& item) {
  if (!workspace_ || !item.renamable()) return;
  bool ok = false;
  const bool run = item.kind == TreeItemRef::Kind::Run;
  const QString title = item.kind == TreeItemRef::Kind::Platform ? tr("Rename platform")
                        : run                                    ? tr("Name this run")
                                                                 : tr("Rename");
  // A run keeps its own name (device, backend, D, N); its label is shown after it in every view, export and report.
  const QString prompt = run ? tr("Label shown after the run's name (empty: none):") : tr("New name:");
  const QString name = QInputDialog::getText(this, title, prompt, QLineEdit::Normal, item.name, &ok).trimmed();
  if (!ok || (name.isEmpty() && !run) || name == item.name) return;
  Workspace* ws = workspace_.get();
  const std::string from = item.name.toStdString(), to = name.toStdString();
  std::function<void(const std::string&)> apply;
  switch (item.kind) {
    case TreeItemRef::Kind::PowerLog:
      apply = [ws, id = item.id](const std::string& n) { ws->rename_power_trace(id, n); };
      break;
    case TreeItemRef::Kind::Frame:
      apply = [ws, id = item.id](const std::string& n) { ws->rename_frame(id, n); };
      break;
    case TreeItemRef::Kind::Run: {
      const auto stored = std::find_if(runs_.begin(), runs_.end(), [&](const StoredRun& r) { return r.id == item.id; });
      if (stored == runs_.end()) return;
      apply = [ws, run = *stored](const std::string& n) { set_run_label(*ws, run, n); };
      break;
    }
    default:
      break;
  }
  std::function<void()> redo, undo;
  if (item.kind == TreeItemRef::Kind::Platform) {
    redo = [ws, from, to] { ws->rename_platform(from, to); };
    undo = [ws, from, to] { ws->rename_platform(to, from); };
  } else {
    redo = [apply, to] { apply(to); };
    undo = [apply, from] { apply(from); };
  }
  if (!try_edit(redo)) return;
  push_edit(run ? tr("label run “%1”").arg(name) : tr("rename “%1” to “%2”").arg(item.name, name), std::move(redo),
            std::move(undo));
}

void MainWindow::remove_item(const TreeItemRef& item) {
  if (!workspace_ || !item.removable()) return;
  Workspace* ws = workspace_.get();
  if (item.kind == TreeItemRef::Kind::BatteryPreset) {
    const auto setup = find_battery_setup(ws, item.name.toStdString());
    if (!setup || !setup->from_workspace) return;
    std::function<void()> redo = [ws, name = setup->pack.name] { remove_battery_setup(*ws, name); };
    std::function<void()> undo = [ws, s = *setup] { save_battery_setup(*ws, s); };
    if (!try_edit(redo)) return;
    push_edit(tr("remove preset “%1”").arg(item.name), std::move(redo), std::move(undo));
    return;
  }
  // The import id changes when undo adds the content back: both steps share it.
  auto import_id = std::make_shared<std::int64_t>(item.import_id);
  auto snapshot = std::make_shared<ImportSnapshot>();
  std::function<void()> redo = [ws, import_id, snapshot] {
    *snapshot = snapshot_import(*ws, *import_id);
    ws->remove_import(*import_id);
  };
  std::function<void()> undo = [ws, import_id, snapshot] { *import_id = restore_import(*ws, *snapshot); };
  if (!try_edit(redo)) return;
  push_edit(tr("remove import “%1” (%2)").arg(file_name(snapshot->record.path), count_text(snapshot->batch)),
            std::move(redo), std::move(undo));
}

bool MainWindow::try_edit(const std::function<void()>& redo) {
  try {
    redo();
    return true;
  } catch (const std::exception& e) {
    report_edit_error(QString::fromUtf8(e.what()));
    return false;
  }
}

void MainWindow::push_edit(const QString& text, std::function<void()> redo, std::function<void()> undo,
                           std::function<void()> refresh) {
  // Each step brings the views up to date after it ran, whichever way: all of them (reload) unless the step says
  // which (a constraint changes the Platforms tab alone).
  if (!refresh) refresh = [this] { reload(); };
  auto then_refresh = [refresh](std::function<void()> f) {
    return [refresh, f = std::move(f)] {
      f();
      refresh();
    };
  };
  work_since_open_ = true;
  edits_->push(new WorkspaceCommand(text, then_refresh(std::move(redo)), then_refresh(std::move(undo)),
                                    [this](const QString& m) { report_edit_error(m); }));
  refresh();
  statusBar()->showMessage(tr("Done: %1 — Ctrl+Z undoes").arg(text), 10000);
}

void MainWindow::set_device_color(const TreeItemRef& device, int color_index) {
  if (!workspace_ || device.kind != TreeItemRef::Kind::Device || color_index == device.color_index) return;
  Workspace* ws = workspace_.get();
  const std::string platform = device.platform.toStdString(), name = device.name.toStdString();
  std::function<void()> redo = [ws, platform, name, color_index] { ws->set_device_color(platform, name, color_index); };
  std::function<void()> undo = [ws, platform, name, old = device.color_index] {
    ws->set_device_color(platform, name, old);
  };
  if (!try_edit(redo)) return;
  push_edit(tr("colour of %1").arg(device.name), std::move(redo), std::move(undo));
}

void MainWindow::update_edit_actions() {
  // On the Lens tab Ctrl+Z belongs to the lens tuner's own undo; elsewhere it undoes workspace edits.
  const bool lens_in_front = static_cast<QTabWidget*>(centralWidget())->currentWidget() == lens_;
  undo_edit_->setEnabled(edits_->canUndo() && !lens_in_front);
  redo_edit_->setEnabled(edits_->canRedo() && !lens_in_front);
}

}  // namespace bs::ui
