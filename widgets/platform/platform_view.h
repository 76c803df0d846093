// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Platforms tab: every platform compared (peaks, power, efficiency, pipeline, battery), the person's constraints
// and requirements judged, the recommendation, with the inference table and the library's candidates below.
#include <QStringList>
#include <QWidget>
#include <vector>

#include "analysis/platform/platform_comparison.h"
#include "headroom/loop_requirement.h"
#include "model/dnn_run.h"
#include "power/shared_traces.h"
#include "store/battery_preset_store.h"
#include "store/decision_store.h"
#include "sustain/sustain_requirement.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QScrollArea;
class QSplitter;
class QTableWidget;

namespace bs {
class Workspace;
}

namespace bs::ui {

class CandidatesPanel;
class FrozenFirstColumn;
class InferenceTable;

// One row per platform (peaks, power, GFLOPS/W, pipeline, energy per frame, battery), sortable, the best value of
// each column highlighted, each cell's source in its tooltip; constraints (power budget, fps, runtime) add the
// verdict columns and the recommendation. The numbers come from core (compare_platforms, recommend,
// platform_table) so the view, the CLI and the exported tables agree.
class PlatformView : public QWidget {
  Q_OBJECT
 public:
  explicit PlatformView(QWidget* parent = nullptr);
  ~PlatformView() override;
  // Pipeline runs give the preprocessing and detection columns and, with a power log, energy per frame.
  // The traces are shared with the other views (widgets/power/shared_traces.h), never copied.
  void set_data(std::vector<FlopsRun> runs, SharedTraces traces, std::vector<PipelineRun> pipelines = {});
  void set_data(std::vector<FlopsRun> runs, std::vector<PowerTrace> traces, std::vector<PipelineRun> pipelines = {});
  // bench dnn runs: the inference table under the comparison (hidden while there are none).
  void set_inference_runs(std::vector<DnnRun> runs);
  InferenceTable* inference_table() const { return inference_; }
  // Imported MLPerf LoadGen results (and other result sets): own inference results among the candidates.
  void set_result_sets(std::vector<ResultSet> sets);
  // Candidates from the library of published results, ranked beside the own platforms.
  CandidatesPanel* candidates() const { return candidates_; }
  QTableWidget* table() const { return table_; }
  // The summary, the comparison, the inference table and the candidates, one over the other
  // (platform_view_split.cpp). Until the person moves it, it fits them to the height (fit_split); where the person
  // left it is kept by the window across restarts.
  QSplitter* splitter() const { return split_; }
  QByteArray split_state() const;  // empty while the split is the fitted one (nothing of the person's to keep)
  void restore_split(const QByteArray& state);
  void reset_split();              // View > Reset layout: fitted again
  QString summary_text() const;    // the line above the table (recommendation, battery, logs left out), rich text
  QString recommendation() const;  // the recommended platform, empty when none
  // The battery presets (built-in and the workspace's, with their missions) offered in the Battery and Mission
  // choices; `ws` may be null (built-ins only).
  void set_workspace(const Workspace* ws);
  // The Battery tab's setup as it is now (its edits included): offered first in the Battery choice, and selected by
  // default, so both tabs use the same pack unless the user picks another here. While it is selected, the parallel
  // load and mission follow the Battery tab too.
  void set_battery_tab_setup(const BatterySetup& setup, bool modified);
  // The user edited the Battery tab (after set_battery_tab_setup): while this tab follows it and the workspace keeps
  // a decision, the decision's parallel load and mission are stored anew, so that the CLI and the next opening read
  // what this tab shows (store/decision_inputs.h).
  void battery_tab_edited();
  // A mission profile (parse_mission() text) in parallel with every computer; empty: a constant load.
  void set_mission(const QString& spec);
  QString mission() const;
  void set_power_budget(std::optional<double> watts);
  void set_min_fps(std::optional<double> fps);
  void set_min_runtime_min(std::optional<double> minutes);
  // What the controls say now (battery, extra load; constraints), for the report.
  ComparisonOptions options() const;
  Constraints constraints() const;
  // Headroom measurements (benchscope-cli headroom, the Headroom tab, imports) for the control-loop requirement.
  void set_headroom(std::vector<headroom::HeadroomMeasurement> measurements);
  // The control-loop requirement (headroom/loop_requirement.h syntax); empty: none. Unknown is never passing.
  void set_loop_requirement(const QString& text);
  QCheckBox* loop_check() const { return use_loop_; }
  QLineEdit* loop_edit() const { return loop_; }
  const std::vector<headroom::LoopVerdict>& loop_verdicts() const { return loop_verdicts_; }
  std::optional<headroom::LoopRequirement> loop_requirement() const;  // null when off or mistyped
  // Sustained records (the Sustained tab, benchscope-cli sustain, imported logs) for the sustained requirement.
  void set_sustained(std::vector<SustainRun> runs);
  // The sustained requirement (sustain/sustain_requirement.h syntax); empty: none. Unknown is never passing.
  void set_sustained_requirement(const QString& text);
  QCheckBox* sustained_check() const { return use_sustained_; }
  QLineEdit* sustained_edit() const { return sustained_; }
  const std::vector<sustain::SustainVerdict>& sustained_verdicts() const { return sustained_verdicts_; }
  std::optional<sustain::SustainRequirement> sustained_requirement() const;  // null when off or mistyped
  // What the controls say, as the workspace keeps it (store/decision_store.h): constraints, battery choice ("" while
  // it follows the Battery tab), parallel load, mission, library candidates.
  StoredDecision decision() const;
  // Sets every control from the workspace's decision (nullopt: the defaults: no constraint, the Battery tab's pack,
  // no candidates) without emitting decision_edited.
  // `problem`: why the workspace's stored decision could not be read (said above the table, in red, until a decision
  // is applied again); the defaults are shown then, and the next change replaces the damaged one.
  void apply_decision(const std::optional<StoredDecision>& decision, const QString& problem = {});

 signals:
  // The user changed a control that changes the decision (a check box, a value entered, the battery, the mission,
  // the candidates): the window stores it in the workspace, one undo step each (issue #43.2).
  void decision_edited(const bs::StoredDecision& decision);
  // The user asked where a cell's number came from (double-click): the platform and the column id.
  void source_requested(const PlatformRow& row, const QString& column);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void fit_split();
  void recompute();
  void fill_table();
  void export_table(bool latex);
  void fill_battery_choices();
  bool constrained() const;
  void user_changed();  // emits decision_edited when the decision differs from the one last applied or emitted

  QCheckBox *use_budget_, *use_fps_, *use_runtime_;
  QDoubleSpinBox *budget_, *fps_, *runtime_, *extra_load_;
  QComboBox* battery_;
  QComboBox* mission_;  // editable: the presets' missions, or typed name:seconds:watts,...
  QString mission_error_;
  std::vector<BatterySetup> setups_;  // in the Battery choice's order: the Battery tab's setup first when known
  bool has_tab_setup_ = false;
  QString tab_setup_label_;
  QLabel* summary_;
  QTableWidget* table_;
  QScrollArea* summary_box_ = nullptr;
  QSplitter* split_ = nullptr;
  bool auto_split_ = true;  // the split is fitted to the contents until the person moves it or a kept one is restored
  InferenceTable* inference_ = nullptr;
  CandidatesPanel* candidates_ = nullptr;
  std::vector<PipelineRun> pipeline_runs_;  // as given: the detection stage is an own candidate
  std::vector<DnnRun> dnn_runs_;
  std::vector<ResultSet> result_sets_;
  FrozenFirstColumn* frozen_ = nullptr;  // keeps the platform's name in view while the numbers scroll
  std::vector<FlopsRun> runs_;
  SharedTraces traces_ = share_traces(std::vector<PowerTrace>{});
  std::vector<PipelineTimings> pipelines_;
  std::vector<PlatformRow> rows_;
  std::vector<PlatformVerdict> verdicts_;
  QStringList empty_columns_;  // header texts of the columns hidden for lack of data
  QCheckBox* use_loop_ = nullptr;
  QLineEdit* loop_ = nullptr;
  std::vector<headroom::HeadroomMeasurement> headroom_;
  std::vector<headroom::LoopVerdict> loop_verdicts_;
  QCheckBox* use_sustained_ = nullptr;
  QLineEdit* sustained_ = nullptr;
  std::vector<SustainRun> sustained_runs_;
  std::vector<sustain::SustainVerdict> sustained_verdicts_;
  StoredDecision last_decision_;  // as last applied from the workspace or emitted
  bool decision_stored_ = false;  // the workspace keeps a decision (applied from it, or emitted since)
  QString decision_problem_;      // the stored decision could not be read: why (empty when it could)
};

}  // namespace bs::ui
