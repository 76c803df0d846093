// SPDX-License-Identifier: GPL-3.0-or-later
// What the user sets on a power log after importing it (issue #32.2, #32.3): the supply voltage or another log's
// voltage channel that turns its current into power, and the platform it belongs to. Each change is one undo step;
// an import asks for the platform of a log whose file names none.
#include <QInputDialog>
#include <QStatusBar>

#include "main_window.h"
#include "power/log_voltage_dialog.h"
#include "store/log_settings_store.h"
#include "workspace/import_controller.h"

namespace bs::ui {
namespace {

const StoredPowerTrace* find_trace(const std::vector<StoredPowerTrace>& traces, std::int64_t id) {
  for (const StoredPowerTrace& t : traces)
    if (t.id == id) return &t;
  return nullptr;
}

// The summary (no samples) of the log with this id that an edit starts from; nullopt without a workspace or such a
// log.
std::optional<StoredPowerTrace> log_summary(Workspace* ws, std::int64_t id) {
  if (!ws) return std::nullopt;
  const std::vector<StoredPowerTrace> traces = ws->power_trace_summaries();
  const StoredPowerTrace* t = find_trace(traces, id);
  return t ? std::optional<StoredPowerTrace>(*t) : std::nullopt;
}

}  // namespace

QStringList MainWindow::known_platforms() const {
  QStringList out;
  if (!workspace_) return out;
  const auto add = [&out](const std::string& p) {
    const QString q = QString::fromStdString(p);
    if (!q.trimmed().isEmpty() && !out.contains(q)) out << q;
  };
  for (const DeviceRecord& d : workspace_->devices()) add(d.platform);
  for (const StoredPowerTrace& t : workspace_->power_trace_summaries()) add(t.trace.platform);
  for (const StoredPipelineRun& p : workspace_->pipeline_runs()) add(p.run.platform);
  return out;
}

QString MainWindow::choose_log_platform(const QString& log, const QString& path, const QString& guess,
                                        const QStringList& platforms) {
  if (platform_prompt_) return platform_prompt_(log, path, guess, platforms);
  QStringList items{guess};
  for (const QString& p : platforms)
    if (p != guess) items << p;
  bool ok = false;
  // Over the import's progress dialog while one runs (ImportController::question_parent()): never under it.
  const QString answer = QInputDialog::getItem(
      importer_->question_parent(), tr("Platform of %1").arg(log),
      tr("%1 does not say which platform it measured.\nWhich platform does the log “%2” belong to? (Pick one or "
         "type a new name; it can be changed later: right-click the log > Platform…)")
          .arg(path.section('/', -1), log),
      items, 0, true, &ok);
  return ok && !answer.trimmed().isEmpty() ? answer.trimmed() : guess;
}

void MainWindow::set_log_platform(std::int64_t trace_id, const QString& platform) {
  Workspace* ws = workspace_.get();
  const std::optional<StoredPowerTrace> t = log_summary(ws, trace_id);
  if (!t) return;
  const std::string before = t->trace.platform, after = platform.trimmed().toStdString(), label = t->trace.label;
  if (before == after) return;
  std::function<void()> redo = [ws, trace_id, after] { set_trace_platform(*ws, trace_id, after); };
  std::function<void()> undo = [ws, trace_id, before] {
    if (!before.empty()) set_trace_platform(*ws, trace_id, before);
  };
  if (!try_edit(redo)) return;
  push_edit(tr("platform of “%1” to “%2”").arg(QString::fromStdString(label), platform.trimmed()), std::move(redo),
            std::move(undo));
}

void MainWindow::set_log_voltage(std::int64_t trace_id, const LogVoltageChoice& choice) {
  Workspace* ws = workspace_.get();
  const std::optional<StoredPowerTrace> t = log_summary(ws, trace_id);
  if (!t) return;
  const LogVoltageChoice before{t->trace.supply_voltage_v, trace_voltage_source(*ws, trace_id)};
  const auto apply = [ws, trace_id](const LogVoltageChoice& c) {
    set_trace_supply_voltage(*ws, trace_id, c.supply_v);
    set_trace_voltage_source(*ws, trace_id, c.source);
  };
  std::function<void()> redo = [apply, choice] { apply(choice); };
  std::function<void()> undo = [apply, before] { apply(before); };
  if (!try_edit(redo)) return;
  const QString what = choice.source     ? tr("a borrowed voltage channel")
                       : choice.supply_v ? tr("%1 V").arg(*choice.supply_v)
                                         : tr("no supply voltage");
  push_edit(tr("supply voltage of “%1”: %2").arg(QString::fromStdString(t->trace.label), what), std::move(redo),
            std::move(undo));
}

void MainWindow::ask_log_voltage(const TreeItemRef& log) {
  if (!workspace_) return;
  const auto traces = workspace_->power_trace_summaries();
  const StoredPowerTrace* t = find_trace(traces, log.id);
  if (!t) return;
  // Every other log's voltage channels can lend their voltage.
  std::vector<VoltageChannelOption> channels;
  for (const StoredPowerTrace& o : traces) {
    if (o.id == t->id) continue;
    for (const PowerChannel& c : o.trace.channels)
      if (c.quantity == PowerQuantity::Voltage)
        channels.push_back({{o.id, c.name},
                            tr("%1 — %2 (%3)")
                                .arg(QString::fromStdString(o.trace.label), QString::fromStdString(c.name),
                                     QString::fromStdString(o.trace.platform))});
  }
  LogVoltageDialog dialog(QString::fromStdString(t->trace.label),
                          {t->trace.supply_voltage_v, trace_voltage_source(*workspace_, t->id)}, std::move(channels),
                          this);
  if (dialog.exec() == QDialog::Accepted) set_log_voltage(t->id, dialog.choice());
}

void MainWindow::ask_log_platform(const TreeItemRef& log) {
  const std::optional<StoredPowerTrace> t = log_summary(workspace_.get(), log.id);
  if (!t) return;
  const QString current = QString::fromStdString(t->trace.platform);
  QStringList items{current};
  for (const QString& p : known_platforms())
    if (p != current) items << p;
  bool ok = false;
  const QString answer = QInputDialog::getItem(this, tr("Platform of %1").arg(QString::fromStdString(t->trace.label)),
                                               tr("Platform this power log belongs to:"), items, 0, true, &ok)
                             .trimmed();
  if (ok && !answer.isEmpty()) set_log_platform(t->id, answer);
}

}  // namespace bs::ui
