// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote/run_here_or_robot.h"

#include <QAbstractButton>
#include <QFutureWatcher>
#include <QLabel>
#include <QPointer>
#include <QProgressBar>
#include <QtConcurrent/QtConcurrentRun>
#include <mutex>

#include "remote/remote_run.h"
#include "remote/robot_target.h"

namespace bs::ui {
namespace {

// What the worker returns when the work was cancelled: no error message starts with a control character.
QString cancelled_mark() { return QString(QChar(1)) + QStringLiteral("cancelled"); }

}  // namespace

RunHereOrRobot::RunHereOrRobot(RobotTarget* target, QObject* parent)
    : QObject(parent), target_(target), watcher_(new QFutureWatcher<QString>(this)) {
  connect(watcher_, &QFutureWatcher<QString>::finished, this, &RunHereOrRobot::here_done);
}

RunHereOrRobot::~RunHereOrRobot() {
  remote_.reset();  // dropping the connection stops everything on the robot
  if (token_) token_->cancel();
  watcher_->waitForFinished();  // the work must not outlive what it reports to
}

bool RunHereOrRobot::running() const { return watcher_->isRunning() || (remote_ && remote_->running()); }

bool RunHereOrRobot::on_robot() const { return target_ && target_->is_robot(); }

bool RunHereOrRobot::start_here(HereWork work) {
  if (running()) {
    emit failed(tr("A measurement is running already"));
    return false;
  }
  token_ = std::make_shared<CancelToken>();
  // Reported on the worker thread, as often as the work likes (a probe: every cycle); delivered on this one, the
  // latest report only, with at most one delivery waiting: the event loop is never flooded. A report after this
  // object is gone is dropped.
  struct Latest {
    std::mutex mutex;
    double fraction = 0;
    QString step;
    bool waiting = false;
  };
  auto latest = std::make_shared<Latest>();
  QPointer<RunHereOrRobot> self(this);
  token_->set_progress([self, latest](double fraction, std::string_view step) {
    std::lock_guard lock(latest->mutex);
    latest->fraction = fraction;
    latest->step = QString::fromUtf8(step.data(), static_cast<qsizetype>(step.size()));
    if (latest->waiting) return;
    latest->waiting = true;
    QMetaObject::invokeMethod(
        self.data(),
        [self, latest] {
          double f = 0;
          QString text;
          {
            std::lock_guard inner(latest->mutex);
            f = latest->fraction;
            text = latest->step;
            latest->waiting = false;
          }
          if (self) emit self->progress(f, text);
        },
        Qt::QueuedConnection);
  });
  emit busy_changed(true);
  watcher_->setFuture(QtConcurrent::run([work = std::move(work), token = token_]() -> QString {
    try {
      work(*token);
      return {};
    } catch (const Cancelled&) {
      return cancelled_mark();
    } catch (const std::exception& e) {
      return QString::fromUtf8(e.what());
    }
  }));
  return true;
}

void RunHereOrRobot::here_done() {
  const QString outcome = watcher_->result();
  token_.reset();
  emit busy_changed(false);
  if (outcome == cancelled_mark()) {
    emit status(tr("Cancelled; nothing stored"));
    emit here_finished(true);
  } else if (!outcome.isEmpty()) {
    emit status(tr("Failed: %1").arg(outcome));
    emit failed(outcome);
  } else {
    emit here_finished(false);
  }
}

bool RunHereOrRobot::start_on_robot(const std::vector<std::string>& words) {
  if (running()) {
    emit failed(tr("A measurement is running already"));
    return false;
  }
  if (const QString why = target_->not_ready(tr("Run")); !why.isEmpty()) {
    emit status(why);
    emit failed(why);
    return false;
  }
  target_->remember_platform();
  return start_on(target_->target(), target_->platform(), words);
}

bool RunHereOrRobot::start_on(const remote::SshTarget& robot_target, const QString& platform,
                              const std::vector<std::string>& words) {
  if (running()) {
    emit failed(tr("A measurement is running already"));
    return false;
  }
  const QString robot = QString::fromStdString(robot_target.destination);
  remote_ = std::make_unique<RemoteRun>(robot_target, words);
  RemoteRun* run = remote_.get();
  connect(run, &RemoteRun::remote_text, this, [this, robot](const QString& line) {
    emit robot_text(line);
    emit status(QStringLiteral("%1: %2").arg(robot, line));
  });
  connect(run, &RemoteRun::progress, this, &RunHereOrRobot::progress);
  connect(run, &RemoteRun::finished, this, [this, run, platform, robot] {
    const remote::RemoteJob& job = run->job();
    emit status(
        job.status == "cancelled"
            ? tr("%1: cancelled (job %2); what it finished is imported").arg(robot, QString::fromStdString(job.id))
            : tr("Measured on %1 (job %2)").arg(robot, QString::fromStdString(job.id)));
    emit robot_finished(run, platform);
    robot_done();
  });
  connect(run, &RemoteRun::failed, this, [this, robot](const QString& message) {
    emit status(QStringLiteral("%1: %2").arg(robot, message));
    emit failed(QStringLiteral("%1: %2").arg(robot, message));
    robot_done();
  });
  emit busy_changed(true);
  emit robot_started(run);
  emit status(tr("%1: checking the robot and starting…").arg(robot));
  run->start();
  return true;
}

void RunHereOrRobot::robot_done() {
  remote_.release()->deleteLater();  // we are in its signal
  emit busy_changed(false);
}

void RunHereOrRobot::drive(QAbstractButton* run, QAbstractButton* cancel, QProgressBar* progress, QLabel* status) {
  connect(this, &RunHereOrRobot::busy_changed, run, [this, run, cancel, progress](bool on) {
    run->setEnabled(!on);
    cancel->setEnabled(on);
    progress->setVisible(on);
    progress->setRange(0, on && on_robot() ? 0 : 100);
    if (on) progress->setValue(0);
  });
  connect(this, &RunHereOrRobot::status, status, &QLabel::setText);
}

void RunHereOrRobot::cancel() {
  if (remote_) {
    remote_->cancel();
    emit status(tr("Cancelling: the robot stops what it runs; what it finished comes home…"));
    return;
  }
  if (token_) {
    token_->cancel();
    emit status(tr("Cancelling…"));
  }
}

}  // namespace bs::ui
