// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote/run_controls.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>

#include "power/power_sensor_box.h"
#include "remote/robot_target.h"
#include "remote/run_here_or_robot.h"

namespace bs::ui {

RunControls::RunControls(QWidget* owner, const QString& run_text)
    : panel(owner),
      power(new PowerSensorBox(owner)),
      target(new RobotTarget(owner)),
      run(new QPushButton(run_text, owner)),
      cancel(new QPushButton(QObject::tr("Cancel"), owner)),
      progress(new QProgressBar(owner)),
      status(new QLabel(owner)),
      controller(new RunHereOrRobot(target, owner)) {
  cancel->setEnabled(false);
  progress->setRange(0, 100);
  progress->setMaximumWidth(160);
  progress->hide();
  status->setTextFormat(Qt::PlainText);
  status->setWordWrap(true);  // a long message wraps instead of widening the window
  controller->drive(run, cancel, progress, status);
  // Cancel stops the run wherever it runs: here (the worker's token) or on the robot (the job).
  QObject::connect(cancel, &QPushButton::clicked, controller, &RunHereOrRobot::cancel);
}

bool RunControls::running() const { return controller->running(); }

QHBoxLayout* RunControls::where_row() const {
  auto* where = new QHBoxLayout;
  where->addWidget(new QLabel(QObject::tr("Run on:"), panel));
  where->addWidget(target, 1);
  return where;
}

QHBoxLayout* RunControls::actions_row() const {
  auto* actions = new QHBoxLayout;
  actions->addWidget(run);
  actions->addWidget(cancel);
  actions->addWidget(progress);
  actions->addWidget(status, 1);
  return actions;
}

void RunControls::show_progress(double fraction) const {
  progress->setRange(0, 100);
  progress->setValue(static_cast<int>(fraction * 100));
}

QString RunControls::say(const QString& message) const {
  status->setText(message);
  return status->text();
}

}  // namespace bs::ui
