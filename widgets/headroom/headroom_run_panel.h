// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// "Run" for the Headroom tab: the probe's rate, seconds per phase, threads, per-cycle computation, priority and
// real-time request, the loads (the CLI's syntax: pipeline@30fps, dnn, flops:64) and an external command, "Record
// power", and where: this machine, or a robot over SSH (issue #44: the loop must be measured on the computer that
// will run it). On this machine, Run starts core's run_headroom off the GUI thread with progress and cancel, and
// hands the finished measurement (with its power trace) over to be stored. On a robot, the same settings go as
// `benchscope-cli headroom` arguments (core: commands/headroom_grammar.h) to the robot's CLI through RemoteRun; the
// robot's phases show as they start, Cancel stops everything there, and the job is handed over to be imported
// with the robot's provenance (remote_finished). Every setting is remembered (QSettings).
#include <QWidget>
#include <memory>
#include <optional>

#include "headroom/headroom_run.h"
#include "remote/run_controls.h"
#include "util/cancel.h"

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;

namespace bs::ui {

class HeadroomRunPanel : public QWidget {
  Q_OBJECT
 public:
  explicit HeadroomRunPanel(QWidget* parent = nullptr);
  ~HeadroomRunPanel() override;
  QDoubleSpinBox* rate() const { return rate_; }
  QDoubleSpinBox* seconds() const { return seconds_; }
  QSpinBox* threads() const { return threads_; }
  QDoubleSpinBox* computation() const { return computation_; }
  QSpinBox* priority() const { return priority_; }
  QCheckBox* realtime() const { return realtime_; }
  QLineEdit* loads() const { return loads_; }
  QLineEdit* command() const { return command_; }
  // Where, Run, Cancel, the progress bar and the status line, as every run panel has them.
  const RunControls& controls() const { return controls_; }

 public slots:
  void start();

 signals:
  void measured(const bs::headroom::RunOutput& output);
  // A robot's job came home (cancelled jobs too: the robot keeps nothing half-done); `platform` as confirmed.
  void remote_finished(bs::ui::RemoteRun* run, const QString& platform);
  void failed(const QString& message);

 private:
  void here_finished(bool cancelled);
  void save_settings() const;
  // The settings as a run configuration; throws std::invalid_argument saying what is wrong.
  headroom::RunConfig config_from_fields(std::vector<std::string>& command_words) const;
  void start_remote(headroom::RunConfig config);

  QDoubleSpinBox* rate_;
  QDoubleSpinBox* seconds_;
  QSpinBox* threads_;
  QDoubleSpinBox* computation_;
  QSpinBox* priority_;
  QCheckBox* realtime_;
  QLineEdit* loads_;
  QLineEdit* command_;
  RunControls controls_;  // where, Run, Cancel, progress, status, and the controller behind them
  // What the run here produced, written on its worker thread before it returns and read after here_finished.
  std::shared_ptr<std::optional<headroom::RunOutput>> output_;
};

}  // namespace bs::ui
