// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/pipeline_measure_panel.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QVBoxLayout>

#include "analysis/power/phase_energy.h"
#include "commands/pipeline_grammar.h"
#include "common/wrapping_tool_bar.h"
#include "power/power_sensor_box.h"
#include "remote/remote_run.h"
#include "remote/robot_target.h"
#include "remote/run_here_or_robot.h"
#include "sensors/recorder.h"
#include "vision/pipeline/pipeline_measure.h"
#include "vision/reproject/cuda_preprocess.h"

namespace bs::ui {
namespace {

constexpr auto kFramesKey = "pipeline/measure_frames";
constexpr auto kWorkersKey = "pipeline/detect_workers";
constexpr auto kScaleKey = "pipeline/detect_scale";
constexpr auto kBackendKey = "pipeline/measure_backend";
constexpr auto kDetectorKey = "pipeline/measure_detector";
constexpr auto kModelFile = "\x01model-file";  // the "Model file…" entry: opens a file dialog

}  // namespace

PipelineMeasurePanel::PipelineMeasurePanel(QWidget* parent)
    : QWidget(parent),
      frames_(new QSpinBox(this)),
      workers_(new QSpinBox(this)),
      scale_(new QDoubleSpinBox(this)),
      backend_(new QComboBox(this)),
      detector_(new QComboBox(this)),
      controls_(this, tr("Measure")) {
  const QSettings settings;
  frames_->setRange(1, 100000);
  frames_->setValue(settings.value(kFramesKey, 20).toInt());
  frames_->setSuffix(tr(" frames"));
  frames_->setToolTip(
      tr("How many frames of the synthetic paper capture (1280x1024 BGGR through the 195° lens) "
         "go through the pipeline"));
  workers_->setRange(1, static_cast<int>(vision::kMaxDetectionWorkers));
  workers_->setValue(settings.value(kWorkersKey, static_cast<int>(vision::default_detection_workers())).toInt());
  workers_->setToolTip(tr("Detection worker threads: each detects its own frame, so detection (the slow stage) "
                          "spreads over the cores. Default: this machine's %1 hardware threads. Capture and "
                          "preprocessing keep one thread each.")
                           .arg(vision::default_detection_workers()));
  scale_->setRange(0.05, 1.0);
  scale_->setSingleStep(0.05);
  scale_->setDecimals(2);
  scale_->setValue(settings.value(kScaleKey, 0.5).toDouble());
  scale_->setToolTip(
      tr("Detection scale: HOG runs on the reprojected frame shrunk by this factor (0.5: 640x512 "
         "of 1280x1024) and its boxes are mapped back to full-frame pixels. Smaller is faster and "
         "misses smaller (more distant) people."));
  backend_->addItem(tr("CPU (fused)"), QStringLiteral("cpu"));
  backend_->addItem(tr("OpenCL"), QStringLiteral("opencl"));
  backend_->addItem(tr("CUDA"), QStringLiteral("cuda"));
  backend_->setToolTip(
      tr("Where demosaicing + reprojection run; detection (HOG) always runs on the CPU. OpenCL "
         "takes the first OpenCL device (GPU preferred; PoCL gives a CPU device)."));
  controls_.target->setToolTip(
      tr("Where the pipeline is measured: this computer, or a robot over SSH (its own CLI renders the same "
         "synthetic capture and runs the pipeline there; the run comes home with the robot's name, architecture "
         "and the command run)"));
  target_changed();  // disables what this computer cannot run (CUDA without a GPU), saying why
  const int saved = backend_->findData(settings.value(kBackendKey, QStringLiteral("cpu")).toString());
  const auto* model = qobject_cast<QStandardItemModel*>(backend_->model());
  backend_->setCurrentIndex(saved >= 0 && model->item(saved)->isEnabled() ? saved : 0);
  detector_->addItem(tr("HOG people detector"), QStringLiteral("hog"));
  detector_->addItem(tr("mobilenet-ssd (architecture timing)"), QStringLiteral("mobilenet-ssd"));
  detector_->addItem(tr("yolo-n (architecture timing)"), QStringLiteral("yolo-n"));
  detector_->addItem(tr("Model file…"), QString::fromLatin1(kModelFile));
  detector_->setItemData(1,
                         tr("SSD300 MobileNet v1 built with random weights: times the network's cost, detects nothing"),
                         Qt::ToolTipRole);
  detector_->setItemData(2, tr("YOLOv8n layout built with random weights: times the network's cost, detects nothing"),
                         Qt::ToolTipRole);
  detector_->setItemData(3,
                         tr("A detection network cv::dnn reads (ONNX, Caffe, TensorFlow, Darknet) with SSD, YOLOv5 "
                            "or YOLOv8 outputs"),
                         Qt::ToolTipRole);
  detector_->setToolTip(
      tr("The detection stage: OpenCV's HOG, a built-in architecture (architecture timing: no "
         "detections) or a network from a model file"));
  {
    const QString saved_detector = settings.value(kDetectorKey, QStringLiteral("hog")).toString();
    int at = detector_->findData(saved_detector);
    if (at < 0 && QFileInfo::exists(saved_detector)) {
      detector_->insertItem(3, QFileInfo(saved_detector).fileName(), saved_detector);
      at = 3;
    }
    detector_->setCurrentIndex(at >= 0 ? at : 0);
  }
  connect(detector_, &QComboBox::activated, this, [this](int i) {
    if (detector_->itemData(i).toString() != QString::fromLatin1(kModelFile)) return;
    const QString file = QFileDialog::getOpenFileName(
        this, tr("Detection network"), QString(), tr("Networks (*.onnx *.pb *.caffemodel *.weights);;All files (*)"));
    if (file.isEmpty()) {
      detector_->setCurrentIndex(0);
      return;
    }
    detector_->insertItem(i, QFileInfo(file).fileName(), file);
    detector_->setCurrentIndex(i);
  });
  // Where it runs on the first row; what to measure and the buttons in rows that wrap where the window is narrow,
  // each label with its field; what happened on a row of its own. Two fixed rows held the panel 928 px wide, and a
  // long word in the status (a robot's job id) wider still: with the Kernel Runner's dock beside it the window
  // needed more than a 1280 px screen (issue #50.5).
  const auto labelled = [this](const QString& text, QWidget* field) {
    auto* pair = new QWidget(this);
    auto* row = new QHBoxLayout(pair);
    row->setContentsMargins(0, 0, 0, 0);
    auto* label = new QLabel(text, pair);
    label->setToolTip(field->toolTip());
    label->setBuddy(field);
    row->addWidget(label);
    row->addWidget(field);
    return pair;
  };
  auto* choices = new FlowLayout(nullptr, 10);
  choices->addWidget(labelled(tr("Synthetic frames:"), frames_));
  choices->addWidget(labelled(tr("Detection workers:"), workers_));
  choices->addWidget(labelled(tr("Detection scale:"), scale_));
  choices->addWidget(labelled(tr("Preprocessing on:"), backend_));
  choices->addWidget(labelled(tr("Detector:"), detector_));
  choices->addWidget(labelled(tr("Record power:"), controls_.power));
  choices->addWidget(controls_.run);
  choices->addWidget(controls_.cancel);
  choices->addWidget(controls_.progress);
  controls_.status->setMinimumWidth(200);  // a long word wraps within the row instead of widening the window
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addLayout(controls_.where_row());
  layout->addLayout(choices);
  layout->addWidget(controls_.status);

  RunHereOrRobot* controller = controls_.controller;
  connect(controls_.run, &QPushButton::clicked, this, &PipelineMeasurePanel::start);
  connect(controller, &RunHereOrRobot::failed, this, [this](const QString& message) {
    if (recorder_) {  // a run here that failed: its power recording ends with it, nothing of it kept
      recorder_->end_phase();
      (void)recorder_->finish("Pipeline tab (failed)");
      recorder_.reset();
    }
    emit failed(message);
  });
  connect(controller, &RunHereOrRobot::here_finished, this, &PipelineMeasurePanel::here_finished);
  connect(controller, &RunHereOrRobot::robot_finished, this, &PipelineMeasurePanel::remote_finished);
  connect(controller, &RunHereOrRobot::progress, this,
          [this](double fraction, const QString&) { controls_.show_progress(fraction); });
  // The robot reports "captured k of N frames" as it goes: the bar follows it.
  connect(controller, &RunHereOrRobot::robot_text, this, [this](const QString& line) {
    static const QRegularExpression captured(QStringLiteral("^captured (\\d+) of (\\d+) frames$"));
    if (const auto m = captured.match(line); m.hasMatch() && m.captured(2).toInt() > 0) {
      controls_.progress->setRange(0, 100);
      controls_.progress->setValue(m.captured(1).toInt() * 100 / m.captured(2).toInt());
    }
  });
  connect(controls_.target, &RobotTarget::changed, this, &PipelineMeasurePanel::target_changed);
  for (QSpinBox* box : {frames_, workers_})
    connect(box, &QSpinBox::valueChanged, this, &PipelineMeasurePanel::save_settings);
  connect(scale_, &QDoubleSpinBox::valueChanged, this, &PipelineMeasurePanel::save_settings);
  connect(backend_, &QComboBox::currentIndexChanged, this, &PipelineMeasurePanel::save_settings);
  connect(detector_, &QComboBox::currentIndexChanged, this, &PipelineMeasurePanel::save_settings);
}

PipelineMeasurePanel::~PipelineMeasurePanel() {
  // Cancels and waits for a run here, or drops the robot's connection, before the panel goes.
  delete controls_.controller;
}

void PipelineMeasurePanel::target_changed() {
  const RobotTarget* target = controls_.target;
  const bool robot = target->is_robot();
  controls_.run->setText(robot ? tr("Measure on %1").arg(target->robot_name()) : tr("Measure on this machine"));
  auto* model = qobject_cast<QStandardItemModel*>(backend_->model());
  // A backend the chosen computer cannot run stays visible, disabled, saying why: nobody wonders where it went.
  const auto set = [model](int row, const QString& why) {
    model->item(row)->setEnabled(why.isEmpty());
    model->item(row)->setToolTip(why);
  };
  if (!robot) {
    set(1, {});  // an OpenCL device is asked for at the run (PoCL gives one everywhere)
    const std::string why = vision::cuda_preprocessing_unavailable();
    set(2, why.empty() ? QString() : tr("Not available here: %1").arg(QString::fromStdString(why)));
  } else if (const auto& check = target->check(); check && check->ok) {
    // The robot's own backends, from its check: "opencl:0", "cuda:0".
    bool opencl = false, cuda = false;
    for (const remote::RobotBackend& b : check->info.backends) {
      opencl = opencl || b.id.starts_with("opencl");
      cuda = cuda || b.id.starts_with("cuda");
    }
    const QString name = target->robot_name();
    set(1, opencl ? QString() : tr("%1 has no OpenCL device").arg(name));
    set(2, cuda ? QString() : tr("%1 has no CUDA GPU (or its BenchScope was built without CUDA)").arg(name));
  } else {
    set(1, {});  // not checked yet: the robot says at the run whether it can
    set(2, {});
  }
  if (!model->item(backend_->currentIndex())->isEnabled()) backend_->setCurrentIndex(0);
}

void PipelineMeasurePanel::save_settings() const {
  QSettings settings;
  settings.setValue(kFramesKey, frames_->value());
  settings.setValue(kWorkersKey, workers_->value());
  settings.setValue(kScaleKey, scale_->value());
  settings.setValue(kBackendKey, backend_->currentData().toString());
  if (detector_->currentData().toString() != QString::fromLatin1(kModelFile))
    settings.setValue(kDetectorKey, detector_->currentData().toString());
}

void PipelineMeasurePanel::start() {
  if (controls_.running()) return;
  vision::SyntheticPipelineOptions options;
  options.frames = static_cast<std::size_t>(frames_->value());
  options.detection_workers = static_cast<std::size_t>(workers_->value());
  options.detect_scale = scale_->value();
  options.backend = backend_->currentData().toString().toStdString();
  options.detector = detector_->currentData().toString().toStdString();
  options.tool =
      QStringLiteral("benchscope %1 (GUI, Pipeline tab)").arg(QCoreApplication::applicationVersion()).toStdString();
  if (controls_.target->is_robot()) {
    start_remote(options);
    return;
  }
  trace_.reset();
  try {
    recorder_ = controls_.power->start_recorder();  // null when "Record power" is off
  } catch (const std::exception& e) {
    emit failed(controls_.say(tr("Record power: %1").arg(QString::fromUtf8(e.what()))));
    return;
  }
  if (recorder_) recorder_->begin_phase("pipeline");
  output_ = std::make_shared<std::optional<PipelineRun>>();
  controls_.controller->start_here([options, output = output_](const CancelToken& token) {
    *output = vision::measure_synthetic_pipeline(options, token,
                                                 [&token](double f, std::string_view step) { token.report(f, step); });
  });
  controls_.status->setText(tr("Measuring %1 frames (preprocessing on %4) with %2 detection worker(s) at scale %3…")
                                .arg(options.frames)
                                .arg(options.detection_workers)
                                .arg(options.detect_scale)
                                .arg(backend_->currentText()));
}

void PipelineMeasurePanel::start_remote(const vision::SyntheticPipelineOptions& options) {
  std::vector<std::string> args;
  try {
    args = commands::to_words(commands::robot_pipeline_settings(options, controls_.target->platform().toStdString(),
                                                                !controls_.power->off()));
  } catch (const std::invalid_argument& e) {
    emit failed(controls_.say(tr("%1: %2").arg(controls_.target->robot_name(), QString::fromUtf8(e.what()))));
    return;
  }
  controls_.controller->start_on_robot(args);
}

std::optional<PowerTrace> PipelineMeasurePanel::take_power_trace() {
  auto t = std::move(trace_);
  trace_.reset();
  return t;
}

void PipelineMeasurePanel::here_finished(bool cancelled) {
  const std::shared_ptr<std::optional<PipelineRun>> outcome = std::move(output_);
  const bool measured = !cancelled && outcome && *outcome;
  std::optional<PowerTrace> trace;
  if (recorder_) {
    recorder_->end_phase();
    trace = recorder_->finish(
        "Pipeline tab" + (measured ? " " + (*outcome)->platform + " " + (*outcome)->provenance.date : std::string()));
    recorder_.reset();
  }
  if (!measured) {
    // Cancelled: the pipeline returns nothing rather than throwing (the controller says nothing then).
    if (!cancelled) controls_.status->setText(tr("Cancelled; nothing stored."));
    return;
  }
  const PipelineRun& run = **outcome;
  QString energy;
  if (trace) {
    trace->platform = run.platform;  // the Platforms view pairs runs and traces by platform
    const auto phases = phase_energies(*trace);
    const StageStats* pre = run.stage(pipeline_stage::kPreprocess);
    const StageStats* det = run.stage(pipeline_stage::kDetect);
    const std::size_t frames = pre ? pre->n : 0;
    if (!phases.empty() && frames > 0) {
      const PhaseEnergy& e = phases.front();
      energy = tr(" %1 J per frame through the pipeline (mean %2 W)")
                   .arg(e.energy_j / static_cast<double>(frames), 0, 'f', 3)
                   .arg(e.mean_power_w, 0, 'f', 2);
      if (pre) energy += tr(", %1 J per preprocessed frame").arg(e.mean_power_w * pre->mean_s, 0, 'f', 4);
      if (det) energy += tr(", %1 J per inference").arg(e.mean_power_w * det->mean_s, 0, 'f', 4);
      energy += tr(" (%1: %2).")
                    .arg(QString::fromUtf8(to_string(trace->provenance.measurement).data()),
                         QString::fromStdString(trace->provenance.sensor));
    }
    trace_ = std::move(trace);
  }
  controls_.status->setText(
      (run.throughput_fps
           ? tr("Measured %1 fps on %2.").arg(*run.throughput_fps, 0, 'f', 2).arg(QString::fromStdString(run.platform))
           : tr("Measured on %1.").arg(QString::fromStdString(run.platform))) +
      energy);
  emit run_measured(run);
}

}  // namespace bs::ui
