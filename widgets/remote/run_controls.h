// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The controls a "run here or on a robot" panel shows (Headroom, Sustained, Pipeline): "Record power", "Run on:" with
// the robot target, the Run and Cancel buttons, a progress bar, a status line, and the controller behind them
// (RunHereOrRobot), which drives them. Made, set up and laid out once here, so that the panels look and behave
// alike; what to run, and what to say when it ends, stays each panel's.
#include <QString>

#include "remote/run_panel_fwd.h"

class QHBoxLayout;
class QLabel;
class QProgressBar;
class QPushButton;
class QWidget;

namespace bs::ui {

struct RunControls {
  // The controls as children of `panel`, created in this order (the focus chain follows it); `run_text` is the Run
  // button's word ("Run", "Measure"). Run starts nothing yet: the panel connects it.
  RunControls(QWidget* panel, const QString& run_text);

  // "Run on:" and the target: the panel's first row.
  QHBoxLayout* where_row() const;
  // Run, Cancel, the progress bar and the status line, the status taking what room is left: a panel's last row.
  QHBoxLayout* actions_row() const;
  // The bar at `fraction` (0..1) of the run; a robot's busy bar (no value yet) turns into a percentage.
  void show_progress(double fraction) const;
  // `message` in the status line, returned for the panel's `failed` signal.
  QString say(const QString& message) const;
  // Whether a run started here or on a robot is still going (Cancel stops it: connected here).
  bool running() const;

  QWidget* const panel;
  PowerSensorBox* const power;  // "Record power": off, or the sensor sampled while it runs (the panel places it)
  RobotTarget* const target;
  QPushButton* const run;
  QPushButton* const cancel;
  QProgressBar* const progress;
  QLabel* const status;
  // Here or on the robot: starts, relays progress, cancels, says how it ended. The panel deletes it first in its
  // destructor, so that a run here is cancelled and waited for while what it reports to still exists.
  RunHereOrRobot* const controller;
};

}  // namespace bs::ui
