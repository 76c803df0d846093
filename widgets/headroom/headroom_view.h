// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Headroom tab: will the control loop keep its deadlines while the robot sees? One stored headroom measurement
// at a time (measured here, or imported from cyclictest / rttest / performance_test), chosen from a list naming its
// platform, tool, kind and date: its latency histogram as the community draws it (log count axis, a step line per
// phase and thread, each curve's maximum in the legend) with a deadline line and the cycles beyond it, the table
// per phase and thread (core's headroom_table: the CLI prints the same cells), and every flag in a banner above
// (a non-real-time measurement says so in red). The run panel measures this machine; Ctrl+E exports the plot,
// the buttons the table.
#include <QWidget>
#include <optional>
#include <vector>

#include "store/workspace.h"

class QCheckBox;
class QComboBox;
class QCustomPlot;
class QLabel;
class QSpinBox;
class QTableWidget;

namespace bs::ui {

class HeadroomRunPanel;

class HeadroomView : public QWidget {
  Q_OBJECT
 public:
  explicit HeadroomView(QWidget* parent = nullptr);
  // Every stored measurement, in the workspace's order; the one shown stays chosen when it is still there.
  void set_measurements(std::vector<StoredHeadroom> measurements);
  // Shows the measurement with this id (false when there is none).
  bool select(std::int64_t id);

  HeadroomRunPanel* run_panel() const { return run_; }
  QComboBox* chooser() const { return chooser_; }
  QSpinBox* deadline() const { return deadline_; }
  QCheckBox* show_deadline() const { return show_deadline_; }
  QCustomPlot* plot() const { return plot_; }
  QTableWidget* table() const { return table_; }
  QLabel* flags_label() const { return flags_; }
  const headroom::HeadroomMeasurement* current() const;

 private:
  void show_current();
  void redraw_plot();
  void export_table(bool latex);

  HeadroomRunPanel* run_;
  QComboBox* chooser_;
  QSpinBox* deadline_;
  QCheckBox* show_deadline_;
  QLabel* flags_;
  QLabel* source_;
  QLabel* empty_;
  QCustomPlot* plot_;
  QTableWidget* table_;
  std::vector<StoredHeadroom> measurements_;
  std::int64_t newest_seen_ = -1;  // the highest id shown so far: a higher one is new and comes to the front
};

}  // namespace bs::ui
