// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <QWidget>
#include <vector>

#include "analysis/flops.h"
#include "analysis/plausibility.h"
#include "store/workspace.h"

class QCheckBox;
class QComboBox;
class QCustomPlot;
class QTableWidget;

namespace bs::ui {

// Supply current (A, the paper's figure 4) or power (W) against time for the workspace's current/power logs, all
// on one time axis from each log's start, and a table of statistics for the time range in view (zoom or pan to
// choose it): mean ± SD current and power, max, energy, GFLOPS/W as the paper defines it and battery life with the
// paper's battery. Long traces are drawn as min/max per pixel column of the visible range (analysis/decimate.h).
class PowerView : public QWidget {
  Q_OBJECT
 public:
  explicit PowerView(QWidget* parent = nullptr);
  // `peaks` supplies each platform's best FLOPS for GFLOPS/W; `colors` maps platform -> colour index.
  void set_data(std::vector<StoredPowerTrace> traces, std::vector<PeakRow> peaks, std::vector<std::pair<std::string, int>> colors);
  int trace_count() const { return static_cast<int>(traces_.size()); }
  QTableWidget* table() const { return table_; }
  QCustomPlot* plot() const { return plot_; }
  enum class Quantity { Current, Power };
  void set_quantity(Quantity q);
  Quantity quantity() const { return quantity_; }
  // Wall-clock time axis (UTC) instead of seconds from each log's start: possible when every log states its
  // absolute start (ISO 8601 start_time); logs recorded at different times then sit apart, as they were.
  bool set_wall_clock(bool on);  // false (and stays relative) when a log has no absolute start
  bool wall_clock() const { return wall_clock_on_; }

 private:
  void redraw_visible();
  void update_table();
  void rescale();
  void place_phase_markers();
  double offset(std::size_t trace) const { return wall_clock_on_ ? start_epoch_[trace] : 0.0; }
  const std::vector<double>& shown(std::size_t trace) const;
  QComboBox* quantity_box_;
  QCheckBox* wall_clock_box_;
  bool wall_clock_on_ = false;
  std::vector<double> start_epoch_;  // per trace: seconds since 1970 of its first sample (NaN: not stated)
  std::vector<int> colors_;          // per trace: colour index
  QCustomPlot* plot_;
  QTableWidget* table_;
  std::vector<StoredPowerTrace> traces_;
  std::vector<std::vector<double>> power_;    // W per sample, per trace (empty: unknown)
  std::vector<std::vector<double>> current_;  // A per sample, per trace (empty: no current channel)
  Quantity quantity_ = Quantity::Current;
  std::vector<PeakRow> peaks_;
  std::vector<std::vector<PlausibilityFlag>> flags_;  // per trace, of the whole log (check_power_trace_bundled())
};

}  // namespace bs::ui
