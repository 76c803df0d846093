// SPDX-License-Identifier: GPL-3.0-or-later
// What the user sets that changes the decision, kept in the workspace (issue #43.2, #43.4): the Platforms tab's
// constraints, battery, mission and candidates, and the power log each platform's numbers come from. Each change is
// one step of Edit > Undo; reopening the workspace, the report and benchscope-cli find them there.
#include <QStatusBar>

#include "main_window.h"
#include "platform/platform_view.h"
#include "power/log_choice_bar.h"

namespace bs::ui {
namespace {

// "power budget ≤ 10 W", "no constraints", "candidates orin,pi5": the undo step's name.
QString decision_words(const std::optional<StoredDecision>& d) {
  if (!d) return QObject::tr("nothing set");
  QStringList parts;
  const std::string c = describe_constraints(*d);  // the control loop too
  parts << (c.empty() ? QObject::tr("no constraints") : QString::fromStdString(c));
  if (!d->candidates.empty()) parts << QObject::tr("candidates %1").arg(QString::fromStdString(d->candidates));
  if (!d->mission.empty()) parts << QObject::tr("mission %1").arg(QString::fromStdString(d->mission));
  return parts.join(", ");
}

}  // namespace

void MainWindow::store_decision(const StoredDecision& after) {
  if (!workspace_) return;
  Workspace* ws = workspace_.get();
  std::optional<StoredDecision> before;
  try {
    try {
      before = stored_decision(*ws);
    } catch (const WorkspaceError& e) {
      // The stored one is damaged (the Platforms tab says why): this change replaces it; Undo removes the change.
      if (e.kind() != WorkspaceError::Kind::Corrupt) throw;
      before.reset();
    }
    if (before == after) return;
    set_stored_decision(*ws, after);
  } catch (const std::exception& e) {
    report_edit_error(QString::fromUtf8(e.what()));
    platforms_->apply_decision(before);  // the controls show what the workspace holds
    return;
  }
  // Only the Platforms tab depends on it: no reload of every view per value typed.
  const auto refresh = [this] {
    if (workspace_) platforms_->apply_decision(stored_decision(*workspace_));
  };
  push_edit(
      tr("Platforms: %1").arg(decision_words(after)), [ws, after] { set_stored_decision(*ws, after); },
      [ws, before] { set_stored_decision(*ws, before); }, refresh);
}

void MainWindow::choose_power_log(const QString& platform, qint64 trace_id) {
  if (!workspace_) return;
  Workspace* ws = workspace_.get();
  const std::string name = platform.toStdString();
  std::optional<std::int64_t> before;
  std::string label;
  try {
    const auto chosen = chosen_logs(*ws);
    if (const auto it = chosen.find(name); it != chosen.end()) before = it->second;
    if (before == trace_id) return;
    for (const StoredPowerTrace& t : ws->power_trace_summaries())
      if (t.id == trace_id) label = t.trace.label;
    set_chosen_log(*ws, name, trace_id);
  } catch (const std::exception& e) {
    report_edit_error(QString::fromUtf8(e.what()));
    return;
  }
  push_edit(
      tr("power log of %1: %2").arg(platform, QString::fromStdString(label)),
      [ws, name, trace_id] { set_chosen_log(*ws, name, trace_id); },
      [ws, name, before] { set_chosen_log(*ws, name, before); });
}

void MainWindow::show_log_choices(const SharedTraces& traces) {
  for (LogChoiceBar* bar : log_choices_) bar->set_logs(traces->traces, traces->ids);
}

}  // namespace bs::ui
