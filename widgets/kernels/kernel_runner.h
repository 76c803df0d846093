// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <QWidget>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "kernels/backends/backend.h"
#include "kernels/ceilings/ceilings.h"
#include "kernels/sweep.h"
#include "model/power_trace.h"
#include "remote/run_panel_fwd.h"

class QCheckBox;
class QComboBox;
class QFormLayout;
class QLayout;
class QLineEdit;
class QSpinBox;
class QPushButton;
class QProgressBar;
class QLabel;
class QTableWidget;

namespace bs::ui {

// Runs the paper's kernel on a chosen backend/device off the GUI thread: worker spec, D list, N, repeats and
// variant; Run/Cancel; each completed point is reported (live_run) so the FLOPS view fills in while it runs, and
// the finished (or cancelled, partial) runs are handed over to be stored (finished). "Record power" samples one
// of the computer's own power sensors (or auto: the board or package total) during the sweep; the energy of
// every point is shown in a table and the trace, with a phase per point, is stored with the runs.
// The target is this computer or a robot over SSH (RobotTarget): on a robot the same sweep runs as a remote job,
// its points plotted live as they arrive, Cancel asks the robot to stop (the completed points come home), and the
// results are handed over to be imported with their provenance (remote_finished); "Several robots…" runs the
// sweep on each chosen robot in turn. Here or on a robot, the shared controller (RunHereOrRobot) starts, relays
// and cancels; this panel keeps its own progress bar format (the robot's name, its power) and the robot queue.
class KernelRunner : public QWidget {
  Q_OBJECT
 public:
  explicit KernelRunner(QWidget* parent = nullptr);
  ~KernelRunner() override;
  bool running() const;
  RobotTarget* target() const { return target_; }
  QCheckBox* robot_power_box() const { return robot_power_; }
  QPushButton* several_robots_button() const { return several_; }
  // Runs the sweep on each robot in turn, each under its platform name ({robot, platform} pairs).
  void start_on_robots(const std::vector<std::pair<QString, QString>>& robots);
  // The robot's text of the run under way (its CLI's messages), for a glance.
  QLabel* remote_log() const { return remote_log_; }
  void set_workers_spec(const QString& spec);
  QString workers_spec() const;  // as typed (remembered from the last sweep started, issue #32.8)
  void set_dims(const QString& dims);
  void set_iterations(int n);
  void set_repeats(int r);
  PowerSensorBox* power_box() const { return power_; }
  QProgressBar* progress_bar() const { return progress_; }
  // Why the typed workers/D fields cannot run, naming the field ("Workers: ..."); empty when they can.
  QString input_error() const;
  QTableWidget* energy_table() const { return energy_; }
  // The trace of the last sweep recorded with power (taken once: the next call gives none).
  std::optional<PowerTrace> take_power_trace();
  void start();
  void cancel();
  // Measures the empirical ceilings (kernels/ceilings.h) of the selected backend's device (the CPU for CPU SIMD, the
  // OpenCL or CUDA device for theirs) off the GUI thread, stores them in the per-host cache and emits
  // ceilings_measured; the details then show them. Nothing for a backend without ceilings (CPU scalar).
  void measure_ceilings();
  bool measuring_ceilings() const { return ceiling_cancel_ != nullptr; }
  QLabel* ceilings_label() const { return ceilings_; }
  // The cached (or just measured) ceilings of this CPU with its SIMD target, if any.
  const std::optional<kernels::CeilingSet>& ceilings() const { return ceiling_set_; }
  // The cached (or just measured) ceilings of a device backend ("opencl:0", "cuda:0"), or nullptr.
  const kernels::CeilingSet* device_ceilings(const std::string& backend_id) const;
  QPushButton* measure_ceilings_button() const { return measure_ceilings_; }
  void select_backend(const QString& id);  // by Backend::id; nothing when there is none

 signals:
  void started();
  void live_run(const bs::FlopsRun& run);
  void finished(const std::vector<bs::FlopsRun>& runs, bool cancelled);
  void failed(const QString& message);
  void ceilings_measured(const bs::ResultSet& set);  // to be stored in the workspace beside the runs
  // A robot's job came home (finished or cancelled): its staged results are to be imported now (the run object
  // lives until the slot returns) under `platform`.
  void remote_finished(bs::ui::RemoteRun* run, const QString& platform);

 private:
  void populate();
  void on_target_changed();  // the backends of this computer or of the robot checked; rows shown for either
  void fill_backends();
  void start_remote_next();  // the next robot of the queue, or the end of the queue
  void finish_remote();
  void here_finished();          // the sweep here returned (finished or cancelled)
  void busy_changed(bool busy);  // the controller started or ended a run
  void relay_progress(double fraction, const QString& step);
  void robot_started(RemoteRun* run);  // the robot's live points and power readings
  void robot_finished(RemoteRun* run, const QString& platform);
  void run_failed(const QString& message);  // here, or one robot of the queue
  void choose_robots();                     // "Several robots…"
  void restore_parameters();                // the last sweep's workers, D, N, repeats, variant and backend (QSettings)
  void save_parameters() const;
  void show_backend_details();
  void show_energies(const std::vector<FlopsRun>& runs);
  void validate_inputs();  // as the user types: a bad field turns red with the reason, Run is disabled
  void show_ceilings(const std::vector<FlopsRun>& last_runs = {});
  const kernels::Backend* current_backend() const;
  kernels::CpuInfo cpu_;
  std::vector<kernels::Backend> backends_;
  QComboBox* backend_;
  QComboBox* variant_;
  QLineEdit* workers_;
  QLineEdit* dims_;
  QSpinBox* iterations_;
  QSpinBox* repeats_;
  QLabel* details_;
  QLabel* input_error_;
  QLabel* ceilings_;
  QPushButton* measure_ceilings_;
  std::optional<kernels::CeilingSet> ceiling_set_;
  std::map<std::string, kernels::CeilingSet> device_ceilings_;  // by backend id
  std::shared_ptr<CancelToken> ceiling_cancel_;
  QPushButton* run_;
  QPushButton* stop_;
  QProgressBar* progress_;
  PowerSensorBox* power_;
  QTableWidget* energy_;
  std::shared_ptr<sensors::PowerRecorder> recorder_;
  std::optional<PowerTrace> trace_;
  QFormLayout* form_ = nullptr;
  QLayout* ceiling_row_ = nullptr;
  RobotTarget* target_;
  QCheckBox* robot_power_;
  QPushButton* several_;
  QLabel* remote_log_;
  std::vector<std::string> robot_backend_ids_;  // the backend box's ids while a robot is the target
  RunHereOrRobot* controller_;                  // here or on a robot: starts, relays progress, cancels
  // The sweep here, written on its worker thread before it returns and read in here_finished.
  std::shared_ptr<std::optional<kernels::SweepResult>> sweep_;
  bool on_robots_ = false;                                // a queue of robots runs (from its start to its end)
  QString robot_name_, robot_who_, robot_platform_;       // the robot running now: "robot", "robot (2 of 3)", its
                                                          // platform name
  std::deque<std::pair<QString, QString>> remote_queue_;  // robots still to run, with their platform names
  std::vector<std::string> remote_command_;
  QString remote_backend_;  // the backend id a run on several robots uses
  QString last_power_;      // the robot's last power reading, shown in the progress bar
  QStringList remote_failures_;
  int remote_total_ = 0;
};

}  // namespace bs::ui
