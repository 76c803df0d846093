// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <QWidget>
#include <optional>
#include <vector>

#include "analysis/peaks/flops.h"
#include "analysis/peaks/plausibility.h"
#include "analysis/power/power_stats.h"
#include "power/shared_traces.h"
#include "store/workspace.h"

class QCheckBox;
class QComboBox;
class QCustomPlot;
class QTableWidget;
class QSplitter;
class QTabWidget;

namespace bs::ui {

class PowerCursors;
class PowerOverlayPanel;
class PowerStatsPanel;
class PowerTraceDrag;

// Supply current (A, the paper's figure 4) or power (W) against time for the workspace's current/power logs, all
// on one time axis (each log from its own start, shifted by its overlay offset), with
// - two cursors A/B and the selection between them, its statistics per visible trace live while dragging
//   (PowerIndex: built once per trace, so a 10-million-sample log answers each mouse move without a rescan;
//   exact percentiles when the drag ends), copied as a table or saved as a named phase in the workspace;
// - phases shaded and named (the log's own: PTDaemon marks, BenchScope's runs, saved selections; and, on
//   request, level changes) with a per-phase statistics table, the one `benchscope-cli power --phases` prints;
// - an overlay panel: traces shown or hidden and shifted by typed offsets, by Ctrl + drag on the plot
//   (PowerTraceDrag) or aligned at a shared phase;
// - the range in view (zoom or pan to choose it): mean ± SD current and power, max, energy, GFLOPS/W as the paper
//   defines it and battery life with the Battery tab's current pack.
// Long traces are drawn as min/max per pixel column of the visible range (analysis/decimate.h).
class PowerView : public QWidget {
  Q_OBJECT
 public:
  explicit PowerView(QWidget* parent = nullptr);
  // `peaks` supplies each platform's best FLOPS for GFLOPS/W; `colors` maps platform -> colour index.
  // The traces are shared with the other views and read in place (widgets/power/shared_traces.h): a 100-million-sample
  // log is not copied. Phases saved from the selection are kept here (and in the workspace), not in the set.
  void set_data(SharedTraces traces, std::vector<PeakRow> peaks, std::vector<std::pair<std::string, int>> colors);
  void set_data(std::vector<StoredPowerTrace> traces, std::vector<PeakRow> peaks,
                std::vector<std::pair<std::string, int>> colors);
  // Where selections are saved as phases and the battery pack comes from (the Battery tab's current setup,
  // workspace setting "battery-tab/current", else the first built-in preset). May be null.
  void set_workspace(Workspace* workspace);
  int trace_count() const { return static_cast<int>(count()); }
  QTableWidget* table() const { return table_; }
  QCustomPlot* plot() const { return plot_; }
  PowerCursors* cursors() const { return cursors_; }
  PowerStatsPanel* selection_panel() const { return selection_; }
  PowerStatsPanel* phase_panel() const { return phases_; }
  PowerOverlayPanel* overlay() const { return overlay_; }
  QTabWidget* panels() const { return panels_; }
  enum class Quantity { Current, Power };
  void set_quantity(Quantity q);
  Quantity quantity() const { return quantity_; }
  // Wall-clock time axis (UTC) instead of seconds from each log's start: possible when every log states its
  // absolute start (ISO 8601 start_time); logs recorded at different times then sit apart, as they were.
  bool set_wall_clock(bool on);  // false (and stays relative) when a log has no absolute start
  bool wall_clock() const { return wall_clock_on_; }
  // Level-change phases (analysis/power_phases.h) shaded and listed next to the log's own.
  void set_detected_phases(bool on);
  // The selection's statistics per trace (index into the traces given to set_data), as last shown.
  const std::vector<std::pair<std::size_t, PowerStats>>& selection_stats() const { return selection_stats_; }
  // Saves the selection A–B as phase `name` of the log it was drawn on (issue #43.4: a phase belongs to one log,
  // not to every log it overlaps), in the workspace when there is one; returns how many logs got it (0 or 1).
  int save_selection_as_phase(const QString& name);
  // The same on the given logs (indexes into the traces given to set_data); the dialog's answer.
  int save_selection_as_phase(const QString& name, const std::vector<std::size_t>& logs);
  // The visible logs the selection covers, and which of them (an index into that list) it was drawn on.
  std::vector<std::size_t> selection_logs() const;
  std::size_t drawn_on(const std::vector<std::size_t>& logs) const;
  double battery_volts() const { return battery_volts_; }
  double battery_ah() const { return battery_ah_; }

 protected:
  void showEvent(QShowEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;

 private:
  void redraw_visible();
  void update_table();
  void update_selection(bool final);
  void update_phase_table();
  void rescale();
  void place_phase_markers();
  void read_battery();
  void ask_save_phase();  // "Save as phase…": the name and the log, then save_selection_as_phase
  void overlay_changed();
  double offset(std::size_t trace) const;
  QString legend_name(std::size_t trace) const;  // the platform, and the log's name where the platform has several
  std::size_t count() const { return traces_->traces.size(); }
  const PowerTrace& trace(std::size_t i) const { return traces_->traces[i]; }
  // The quantity shown (current or power) of trace i as its range index; nullptr when the trace has none.
  const TraceIndex* shown(std::size_t trace) const;
  QComboBox* quantity_box_;
  QCheckBox* wall_clock_box_;
  QCheckBox* detect_box_;
  bool wall_clock_on_ = false;
  std::vector<double> start_epoch_;  // per trace: seconds since 1970 of its first sample (NaN: not stated)
  std::vector<int> colors_;          // per trace: colour index
  QCustomPlot* plot_;
  QTabWidget* panels_;
  QSplitter* split_ = nullptr;
  bool split_placed_ = false;
  QTableWidget* table_;
  PowerStatsPanel* selection_;
  PowerStatsPanel* phases_;
  PowerOverlayPanel* overlay_;
  PowerCursors* cursors_;
  PowerTraceDrag* trace_drag_;
  std::optional<double> drag_base_s_;  // the dragged trace's overlay offset when the drag began
  Workspace* workspace_ = nullptr;
  SharedTraces traces_ = share_traces(std::vector<PowerTrace>{});
  std::vector<std::vector<std::string>> phase_origins_;  // per trace: "log" or "user" per phase of trace_phases_
  std::vector<std::vector<TracePhase>> trace_phases_;    // per trace: the log's phases and the selections saved since
  std::vector<PowerIndex> index_;                  // per trace: the range statistics, built once, reading in place
  std::vector<std::vector<TracePhase>> detected_;  // per trace: level-change phases (filled when shown)
  std::vector<std::pair<std::size_t, PowerStats>> selection_stats_;
  Quantity quantity_ = Quantity::Current;
  std::vector<PeakRow> peaks_;
  std::vector<std::vector<PlausibilityFlag>> flags_;  // per trace, of the whole log (check_power_trace_bundled())
  double battery_volts_ = 0, battery_ah_ = 0;
  QString battery_name_;
};

}  // namespace bs::ui
