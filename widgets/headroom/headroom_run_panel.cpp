// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/headroom_run_panel.h"

#include <QCheckBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>

#include "commands/headroom_grammar.h"
#include "headroom/command_load.h"
#include "headroom/loads/load_spec.h"
#include "power/power_sensor_box.h"
#include "remote/remote_run.h"
#include "remote/robot_target.h"
#include "remote/run_here_or_robot.h"
#include "sensors/recorder.h"

namespace bs::ui {
namespace {

constexpr auto kGroup = "headroom/";

QString key(const char* name) { return QString::fromLatin1(kGroup) + QString::fromLatin1(name); }

}  // namespace

HeadroomRunPanel::HeadroomRunPanel(QWidget* parent)
    : QWidget(parent),
      rate_(new QDoubleSpinBox(this)),
      seconds_(new QDoubleSpinBox(this)),
      threads_(new QSpinBox(this)),
      computation_(new QDoubleSpinBox(this)),
      priority_(new QSpinBox(this)),
      realtime_(new QCheckBox(tr("Real-time (SCHED_FIFO)"), this)),
      loads_(new QLineEdit(this)),
      command_(new QLineEdit(this)),
      controls_(this, tr("Run")) {
  const QSettings s;
  rate_->setRange(headroom::kMinRateHz, headroom::kMaxRateHz);
  rate_->setDecimals(0);
  rate_->setSuffix(tr(" Hz"));
  rate_->setValue(s.value(key("rate"), 1000).toDouble());
  rate_->setToolTip(tr("The control loop's rate: the probe wakes on absolute times of the monotonic clock"));
  seconds_->setRange(0.5, 3600);
  seconds_->setDecimals(1);
  seconds_->setSuffix(tr(" s per phase"));
  seconds_->setValue(s.value(key("seconds"), 20).toDouble());
  seconds_->setToolTip(tr("How long the loop is measured idle and beside each load"));
  threads_->setRange(1, 64);
  threads_->setValue(s.value(key("threads"), 1).toInt());
  threads_->setPrefix(tr("threads "));
  threads_->setToolTip(tr("Periodic probe threads (one histogram each)"));
  computation_->setRange(0, 1e6);
  computation_->setDecimals(0);
  computation_->setSuffix(tr(" µs work"));
  computation_->setValue(s.value(key("computation_us"), 0).toDouble());
  computation_->setToolTip(
      tr("Busy \"control computation\" per cycle: a cycle misses its deadline when latency + "
         "this work exceeds the period"));
  priority_->setRange(1, 99);
  priority_->setPrefix(tr("priority "));
  priority_->setValue(s.value(key("priority"), 80).toInt());
  priority_->setToolTip(tr("SCHED_FIFO priority asked for (granted only with the right to it)"));
  realtime_->setChecked(s.value(key("realtime"), true).toBool());
  realtime_->setToolTip(
      tr("Ask for SCHED_FIFO and locked memory. Without the right, the probe runs as a normal "
         "thread and the result is flagged non-real-time (not comparable with real-time results)."));
  loads_->setText(s.value(key("loads"), QStringLiteral("pipeline@30fps")).toString());
  loads_->setPlaceholderText(tr("idle only"));
  loads_->setToolTip(
      tr("Loads, one phase each after the idle phase, comma-separated: pipeline[@FPS] (the vision "
         "pipeline at a camera rate), dnn[:mobilenet-ssd|yolo-n|hog][@RATE] (the detector), "
         "flops[:W] (the FLOPS kernel with W workers)"));
  command_->setText(s.value(key("command")).toString());
  command_->setPlaceholderText(tr("external command, e.g. stress-ng --cpu 2 --metrics-brief"));
  command_->setToolTip(
      tr("An external program run as the last load (no shell), stopped with SIGINT at the end of "
         "its phase; stress-ng's bogo ops/s is its achieved rate"));
  controls_.target->setToolTip(
      tr("Where the loop is measured: this computer, or a robot over SSH (its own CLI runs the probe and the "
         "loads there; the result comes home with the robot's name, architecture and the command run)"));
  controls_.run->setToolTip(
      tr("Measure the loop idle, then beside each load, on the computer chosen under \"Run on\""));

  auto* layout = new QGridLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addLayout(controls_.where_row(), 0, 0);
  auto* first = new QHBoxLayout;
  for (QWidget* w : std::initializer_list<QWidget*>{rate_, seconds_, threads_, computation_, realtime_, priority_})
    first->addWidget(w);
  first->addStretch(1);
  layout->addLayout(first, 1, 0);
  auto* second = new QHBoxLayout;
  auto* loads_label = new QLabel(tr("Loads:"), this);
  loads_label->setToolTip(loads_->toolTip());
  second->addWidget(loads_label);
  second->addWidget(loads_, 2);
  second->addWidget(command_, 2);
  second->addWidget(new QLabel(tr("Record power:"), this));
  second->addWidget(controls_.power);
  layout->addLayout(second, 2, 0);
  layout->addLayout(controls_.actions_row(), 3, 0);

  RunHereOrRobot* controller = controls_.controller;
  connect(controls_.run, &QPushButton::clicked, this, &HeadroomRunPanel::start);
  connect(controller, &RunHereOrRobot::failed, this, &HeadroomRunPanel::failed);
  connect(controller, &RunHereOrRobot::here_finished, this, &HeadroomRunPanel::here_finished);
  connect(controller, &RunHereOrRobot::robot_finished, this, &HeadroomRunPanel::remote_finished);
  connect(controller, &RunHereOrRobot::progress, this, [this](double fraction, const QString& step) {
    controls_.show_progress(fraction);
    if (!controls_.controller->on_robot() && !step.isEmpty())
      controls_.status->setText(tr("Measuring: phase '%1'…").arg(step));
  });
  for (QDoubleSpinBox* b : {rate_, seconds_, computation_})
    connect(b, &QDoubleSpinBox::valueChanged, this, &HeadroomRunPanel::save_settings);
  for (QSpinBox* b : {threads_, priority_}) connect(b, &QSpinBox::valueChanged, this, &HeadroomRunPanel::save_settings);
  connect(realtime_, &QCheckBox::toggled, this, &HeadroomRunPanel::save_settings);
  connect(realtime_, &QCheckBox::toggled, priority_, &QSpinBox::setEnabled);
  priority_->setEnabled(realtime_->isChecked());
  for (QLineEdit* e : {loads_, command_})
    connect(e, &QLineEdit::editingFinished, this, &HeadroomRunPanel::save_settings);
}

HeadroomRunPanel::~HeadroomRunPanel() {
  // Cancels and waits for a run here, or drops the robot's connection, before the panel goes.
  delete controls_.controller;
}

void HeadroomRunPanel::save_settings() const {
  QSettings s;
  s.setValue(key("rate"), rate_->value());
  s.setValue(key("seconds"), seconds_->value());
  s.setValue(key("threads"), threads_->value());
  s.setValue(key("computation_us"), computation_->value());
  s.setValue(key("priority"), priority_->value());
  s.setValue(key("realtime"), realtime_->isChecked());
  s.setValue(key("loads"), loads_->text());
  s.setValue(key("command"), command_->text());
}

headroom::RunConfig HeadroomRunPanel::config_from_fields(std::vector<std::string>& command_words) const {
  headroom::RunConfig config;
  config.probe.rate_hz = rate_->value();
  config.probe.threads = threads_->value();
  config.probe.computation_ns = static_cast<std::int64_t>(computation_->value() * 1000);
  config.probe.priority = priority_->value();
  config.probe.realtime = realtime_->isChecked();
  config.phase_s = seconds_->value();
  config.command =
      QStringLiteral("benchscope %1 (GUI, Headroom tab): %2 Hz, loads '%3'%4")
          .arg(QCoreApplication::applicationVersion())
          .arg(rate_->value())
          .arg(loads_->text(), command_->text().isEmpty() ? QString() : ", command '" + command_->text() + "'")
          .toStdString();
  // Check what can be checked before anything starts: the probe's settings, the load specs, the command's words.
  if (const std::string e = headroom::validate(config.probe); !e.empty()) throw std::invalid_argument(e);
  (void)headroom::canonical_load_names(loads_->text().toStdString());
  if (!command_->text().trimmed().isEmpty()) command_words = headroom::split_command(command_->text().toStdString());
  return config;
}

void HeadroomRunPanel::start() {
  if (controls_.running()) return;
  headroom::RunConfig config;
  std::vector<std::string> command_words;
  std::shared_ptr<sensors::PowerRecorder> recorder;
  try {
    config = config_from_fields(command_words);
    if (controls_.target->is_robot()) {
      start_remote(std::move(config));
      return;
    }
    recorder = controls_.power->start_recorder();  // null when "Record power" is off
  } catch (const std::exception& e) {
    emit failed(controls_.say(QString::fromUtf8(e.what())));
    return;
  }
  output_ = std::make_shared<std::optional<headroom::RunOutput>>();
  controls_.controller->start_here([config, specs = loads_->text().toStdString(), command_words, recorder,
                                    output = output_](const CancelToken& token) {
    // Loads are built here, off the GUI thread: a detector network takes a moment to build.
    std::vector<std::unique_ptr<headroom::Load>> owned = headroom::make_loads(specs);
    if (!command_words.empty()) owned.push_back(std::make_unique<headroom::CommandLoad>(command_words));
    std::vector<headroom::Load*> loads;
    for (auto& l : owned) loads.push_back(l.get());
    *output = headroom::run_headroom(config, loads, recorder.get(), &token);
  });
  controls_.status->setText(tr("Starting…"));
}

void HeadroomRunPanel::start_remote(headroom::RunConfig config) {
  config.platform = controls_.target->platform().toStdString();
  commands::HeadroomSettings settings;
  settings.config = config;
  settings.loads = loads_->text().trimmed().toStdString();
  settings.load_command = command_->text().trimmed().toStdString();
  if (!controls_.power->off()) settings.power.sensor = "auto";  // the robot's own sensors
  controls_.controller->start_on_robot(commands::to_words(settings));
}

void HeadroomRunPanel::here_finished(bool cancelled) {
  const std::shared_ptr<std::optional<headroom::RunOutput>> output = std::move(output_);
  if (cancelled || !output || !*output) return;  // the controller said so in the status line
  const headroom::HeadroomMeasurement& m = (*output)->measurement;
  controls_.status->setText(tr("Measured %1 phase(s) on %2%3")
                                .arg(m.phases.size())
                                .arg(QString::fromStdString(m.platform))
                                .arg(m.realtime() ? QString()
                                                  : tr(" — NON-REAL-TIME (normal thread): not comparable with "
                                                       "real-time results")));
  emit measured(**output);
}

}  // namespace bs::ui
