// SPDX-License-Identifier: GPL-3.0-or-later
#include "sustain/sustain_run_panel.h"

#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPointer>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>

#include "commands/sustain_grammar.h"
#include "headroom/loads/load_spec.h"
#include "power/power_sensor_box.h"
#include "remote/remote_run.h"
#include "remote/robot_target.h"
#include "remote/run_here_or_robot.h"
#include "sensors/recorder.h"
#include "sustain/sustain_text.h"

namespace bs::ui {
namespace {

QString key(const char* name) { return QStringLiteral("sustain/") + QString::fromLatin1(name); }

}  // namespace

SustainRunPanel::SustainRunPanel(QWidget* parent)
    : QWidget(parent),
      load_(new QLineEdit(this)),
      seconds_(new QDoubleSpinBox(this)),
      interval_(new QDoubleSpinBox(this)),
      controls_(this, tr("Run")) {
  const QSettings s;
  const commands::SustainSettings defaults;
  load_->setText(s.value(key("load"), QString::fromStdString(defaults.load)).toString());
  load_->setToolTip(
      tr("The load kept running the whole time, the CLI's syntax: flops[:W] (the FLOPS kernel, GFLOPS), "
         "pipeline[@FPS] (the vision pipeline at a camera rate, fps), dnn[:mobilenet-ssd|yolo-n|hog][@RATE] (the "
         "detector, inferences/s)"));
  seconds_->setRange(1, sustain::kMaxRunS);
  seconds_->setDecimals(0);
  seconds_->setSuffix(tr(" s"));
  seconds_->setValue(s.value(key("seconds"), defaults.seconds).toDouble());
  seconds_->setToolTip(tr("How long the load runs without a break (600 s: a RoboCup half)"));
  interval_->setRange(sustain::kMinIntervalS, sustain::kMaxIntervalS);
  interval_->setDecimals(2);
  interval_->setPrefix(tr("every "));
  interval_->setSuffix(tr(" s"));
  interval_->setValue(s.value(key("interval"), defaults.interval_s).toDouble());
  interval_->setToolTip(tr("How often the rate, every clock and every temperature are taken"));
  controls_.target->setToolTip(
      tr("Where the load runs: this computer, or a robot over SSH (its own CLI runs it there; the record comes "
         "home with the robot's name, architecture and the command run)"));
  controls_.run->setToolTip(tr("Run the load for the time given and record its rate, clocks, temperatures and power"));
  controls_.cancel->setToolTip(tr("Stop: the intervals completed so far are kept"));

  auto* layout = new QGridLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addLayout(controls_.where_row(), 0, 0);
  auto* settings = new QHBoxLayout;
  auto* load_label = new QLabel(tr("Load:"), this);
  load_label->setToolTip(load_->toolTip());
  settings->addWidget(load_label);
  settings->addWidget(load_, 2);
  settings->addWidget(seconds_);
  settings->addWidget(interval_);
  settings->addWidget(new QLabel(tr("Record power:"), this));
  settings->addWidget(controls_.power, 1);
  layout->addLayout(settings, 1, 0);
  layout->addLayout(controls_.actions_row(), 2, 0);

  RunHereOrRobot* controller = controls_.controller;
  connect(controls_.run, &QPushButton::clicked, this, &SustainRunPanel::start);
  connect(load_, &QLineEdit::editingFinished, this, &SustainRunPanel::save_settings);
  for (QDoubleSpinBox* b : {seconds_, interval_})
    connect(b, &QDoubleSpinBox::valueChanged, this, &SustainRunPanel::save_settings);
  connect(controller, &RunHereOrRobot::busy_changed, this, [this](bool on) {
    if (!on) emit stopped();
  });
  connect(controller, &RunHereOrRobot::failed, this, &SustainRunPanel::failed);
  connect(controller, &RunHereOrRobot::here_finished, this, &SustainRunPanel::here_finished);
  connect(controller, &RunHereOrRobot::robot_finished, this, &SustainRunPanel::robot_finished);
  // A robot's intervals, streamed as `sustain --json` lines, drawn as they come like a run here.
  connect(controller, &RunHereOrRobot::robot_started, this, [this](RemoteRun* run) {
    connect(run, &RemoteRun::sustain_interval, this, [this](const SustainRun& so_far) {
      if (so_far.t_s.empty()) return;
      controls_.show_progress(so_far.t_s.back() / seconds_->value());
      emit live_interval(so_far);
    });
  });
}

SustainRunPanel::~SustainRunPanel() {
  delete controls_.controller;  // cancels and waits for a run here before this panel, which it reports to, is gone
}

void SustainRunPanel::save_settings() const {
  QSettings s;
  s.setValue(key("load"), load_->text());
  s.setValue(key("seconds"), seconds_->value());
  s.setValue(key("interval"), interval_->value());
}

void SustainRunPanel::start() {
  if (controls_.running()) return;
  commands::SustainSettings settings;
  settings.load = load_->text().trimmed().toStdString();
  settings.seconds = seconds_->value();
  settings.interval_s = interval_->value();
  try {
    (void)headroom::canonical_load_names(settings.load);  // a wrong load is said before anything starts
    if (controls_.controller->on_robot()) {
      settings.platform = controls_.target->platform().toStdString();
      if (!controls_.power->off()) settings.power.sensor = "auto";  // the robot's own sensors
      controls_.controller->start_on_robot(commands::to_words(settings));
      return;
    }
    std::shared_ptr<sensors::PowerRecorder> recorder = controls_.power->start_recorder();  // null when off
    sustain::RunConfig config;
    config.seconds = settings.seconds;
    config.interval_s = settings.interval_s;
    config.command = QStringLiteral("benchscope %1 (GUI, Sustained tab): load '%2' for %3 s, every %4 s")
                         .arg(QCoreApplication::applicationVersion(), load_->text())
                         .arg(settings.seconds)
                         .arg(settings.interval_s)
                         .toStdString();
    output_ = std::make_shared<std::optional<sustain::RunOutput>>();
    QPointer<SustainRunPanel> self(this);
    const auto on_interval = [self, seconds = settings.seconds](const SustainRun& so_far, std::size_t i,
                                                                const std::vector<std::string>&) {
      QMetaObject::invokeMethod(
          self.data(),
          [self, so_far, i, seconds] {
            if (!self) return;
            self->controls_.progress->setValue(static_cast<int>(100 * so_far.t_s[i] / seconds));
            self->controls_.status->setText(QString::fromStdString(sustain::interval_line(so_far, i)));
            emit self->live_interval(so_far);
          },
          Qt::QueuedConnection);
    };
    controls_.controller->start_here(
        [config, spec = settings.load, recorder, output = output_, on_interval](const CancelToken& token) {
          // The load is built here, off the GUI thread: a detector network takes a moment to build.
          std::vector<std::unique_ptr<headroom::Load>> loads = headroom::make_loads(spec);
          if (loads.size() != 1) throw std::invalid_argument("the Sustained tab runs one load at a time: " + spec);
          const sustain::SysfsSampler sampler("/");
          *output = sustain::run_sustain(config, *loads.front(), sampler, recorder.get(), &token, on_interval);
        });
    controls_.status->setText(tr("Starting %1…").arg(load_->text()));
  } catch (const std::exception& e) {
    emit failed(controls_.say(QString::fromUtf8(e.what())));
  }
}

void SustainRunPanel::here_finished(bool cancelled) {
  // run_sustain returns what it completed when cancelled: those intervals are kept, and said to be all there is.
  if (!output_ || !*output_ || (*output_)->run.t_s.empty()) {
    controls_.status->setText(cancelled ? tr("Cancelled before the first interval; nothing stored")
                                        : tr("No interval completed; nothing stored"));
    output_.reset();
    return;
  }
  const sustain::RunOutput out = std::move(**output_);
  output_.reset();
  controls_.status->setText(tr("%1 %2 interval(s) of %3 on %4")
                                .arg(out.cancelled ? tr("Cancelled after") : tr("Measured"))
                                .arg(out.run.t_s.size())
                                .arg(QString::fromStdString(out.run.load), QString::fromStdString(out.run.platform)));
  emit measured(out);
}

}  // namespace bs::ui
