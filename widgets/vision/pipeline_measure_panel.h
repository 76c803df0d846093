// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <QWidget>
#include <atomic>
#include <memory>
#include <optional>

#include "model/pipeline_run.h"
#include "model/power_trace.h"
#include "remote/run_controls.h"
#include "util/cancel.h"
#include "vision/pipeline/pipeline_measure.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;
template <class T>
class QFutureWatcher;

namespace bs::ui {

// "Measure": runs the concurrent vision pipeline on the synthetic capture of the paper's camera
// (core: vision::measure_synthetic_pipeline) off the GUI thread, with progress and cancel, and hands the finished
// run over (run_measured) to be stored. "Run on" chooses this machine or a robot over SSH (issue #44): a robot
// renders the same capture itself (`benchscope-cli pipeline --synthetic`, core: commands/pipeline_grammar.h),
// its progress shows as it comes, Cancel stops it there, and its job is handed over to be imported with the
// robot's provenance (remote_finished). Frames, detection workers and detection scale are spin boxes remembered
// between sessions (QSettings), and so is where preprocessing runs (CPU, OpenCL, CUDA: a backend this machine
// cannot run is listed but disabled, its tooltip saying why). "Record power" samples an on-board sensor during
// the run; the status line gives the energy per frame and the trace (take_power_trace) is stored with the run.
class PipelineMeasurePanel : public QWidget {
  Q_OBJECT
 public:
  explicit PipelineMeasurePanel(QWidget* parent = nullptr);
  ~PipelineMeasurePanel() override;
  QSpinBox* frames() const { return frames_; }
  QSpinBox* workers() const { return workers_; }
  QDoubleSpinBox* scale() const { return scale_; }
  QComboBox* backend() const { return backend_; }
  // The detection stage: "hog", "mobilenet-ssd", "yolo-n" (architecture timing) or a model file path.
  QComboBox* detector() const { return detector_; }
  // Where, Run, Cancel, the progress bar and the status line, as every run panel has them.
  const RunControls& controls() const { return controls_; }
  // The trace recorded during the last measured run (taken once).
  std::optional<PowerTrace> take_power_trace();

 public slots:
  void start();

 signals:
  void run_measured(const bs::PipelineRun& run);
  // A robot's job came home (a cancelled one too: it brings nothing half-done); `platform` as confirmed.
  void remote_finished(bs::ui::RemoteRun* run, const QString& platform);
  void failed(const QString& message);

 private:
  void here_finished(bool cancelled);
  void save_settings() const;
  void start_remote(const vision::SyntheticPipelineOptions& options);
  // The backends the chosen computer offers (a robot's from its check), the Measure button's words.
  void target_changed();

  QSpinBox* frames_;
  QSpinBox* workers_;
  QDoubleSpinBox* scale_;
  QComboBox* backend_;
  QComboBox* detector_;
  RunControls controls_;  // where, Measure, Cancel, progress, status, and the controller behind them
  std::shared_ptr<sensors::PowerRecorder> recorder_;
  std::optional<PowerTrace> trace_;
  // What the run here measured, written on its worker thread before it returns and read after here_finished.
  std::shared_ptr<std::optional<PipelineRun>> output_;
};

}  // namespace bs::ui
