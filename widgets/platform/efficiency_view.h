// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <QWidget>
#include <string>
#include <utility>
#include <vector>

#include "analysis/platform/platform_efficiency.h"

class QCustomPlot;
class QTableWidget;

namespace bs::ui {

// Compute per watt per platform, from analysis/platform_efficiency.h (the rows `benchscope-cli efficiency`
// prints): a table with each platform's peak and the run that gave it, supply voltage, max current, mean current
// and power (mean ± SD, n), GFLOPS/W as the paper defines it (peak / (V x max I)) beside the honest variants
// (peak / mean power, J per GFLOP), and a grouped bar chart of the two GFLOPS/W figures per platform. Every
// platform of the workspace has a row: one without a figure says why in it (no power log, no FLOPS run), and a
// log of power only (tegrastats) says in the paper's column that it has no supply current.
class EfficiencyView : public QWidget {
  Q_OBJECT
 public:
  explicit EfficiencyView(QWidget* parent = nullptr);
  void set_data(const std::vector<FlopsRun>& runs, const std::vector<PowerTrace>& traces);
  const std::vector<PlatformEfficiency>& rows() const { return rows_; }         // the platforms with figures
  const std::vector<EfficiencyLeftOut>& left_out() const { return left_out_; }  // the others, with why
  QTableWidget* table() const { return table_; }
  QCustomPlot* plot() const { return plot_; }

 private:
  void fill_table();
  void fill_plot();
  QTableWidget* table_;
  QCustomPlot* plot_;
  std::vector<PlatformEfficiency> rows_;
  std::vector<EfficiencyLeftOut> left_out_;
};

}  // namespace bs::ui
