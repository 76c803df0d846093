// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <QWidget>
#include <vector>

#include "analysis/flops.h"
#include "store/workspace.h"

class QCustomPlot;
class QTableWidget;

namespace bs::ui {

// Power (W) against time for the workspace's current/power logs, and a table of statistics for the time range in
// view (zoom or pan to choose it): mean ± SD current and power, max, energy, GFLOPS/W as the paper defines it and
// battery life with the paper's battery. Long traces are drawn as min/max per pixel column of the visible range.
class PowerView : public QWidget {
  Q_OBJECT
 public:
  explicit PowerView(QWidget* parent = nullptr);
  // `peaks` supplies each platform's best FLOPS for GFLOPS/W; `colors` maps platform -> colour index.
  void set_data(std::vector<StoredPowerTrace> traces, std::vector<PeakRow> peaks, std::vector<std::pair<std::string, int>> colors);
  int trace_count() const { return static_cast<int>(traces_.size()); }
  QTableWidget* table() const { return table_; }
  QCustomPlot* plot() const { return plot_; }

 private:
  void redraw_visible();
  void update_table();
  QCustomPlot* plot_;
  QTableWidget* table_;
  std::vector<StoredPowerTrace> traces_;
  std::vector<std::vector<double>> power_;  // W per sample, per trace
  std::vector<PeakRow> peaks_;
};

}  // namespace bs::ui
