// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote/remote_run.h"

#include "sustain/sustain_live.h"

#include <QPointer>
#include <QtConcurrent>

#include "remote/job_agent.h"

namespace bs::ui {

RemoteRun::RemoteRun(remote::SshTarget target, std::vector<std::string> command, QObject* parent)
    : QObject(parent), target_(std::move(target)), command_(std::move(command)) {
  qRegisterMetaType<bs::FlopsRun>();
}

RemoteRun::~RemoteRun() {
  abort_.cancel();
  if (watcher_) watcher_->waitForFinished();
}

void RemoteRun::post(std::function<void()> fn) { QMetaObject::invokeMethod(this, std::move(fn), Qt::QueuedConnection); }

void RemoteRun::start() {
  if (running_) return;
  running_ = true;
  watcher_ = new QFutureWatcher<QString>(this);
  connect(watcher_, &QFutureWatcher<QString>::finished, this, [this] {
    running_ = false;
    const QString error = watcher_->result();
    if (error.isEmpty())
      emit finished();
    else
      emit failed(error);
  });
  const std::string staging = staging_.path().toStdString();
  // The worker owns nothing of ours but what it writes back through post() or the members it fills before it
  // returns (read only after finished()).
  watcher_->setFuture(QtConcurrent::run([this, staging]() -> QString {
    const remote::JobControl control{&cancel_, &abort_};
    try {
      const remote::RobotCheck check = remote::check_robot(target_, control);
      if (!check.ok)
        return QString::fromStdString(check.problem + (check.fix.empty() ? ""
                                                                         : "\nTo install it, run "
                                                                           "at this desk:\n" +
                                                                               check.fix));
      robot_ = check.info;
      std::vector<FlopsRun> live;
      SustainRun sustained;  // a `sustain --json` run's intervals so far
      remote::JobHandlers handlers;
      handlers.on_event = [this, &live, &sustained](const remote::Event& e) {
        if (e.type == "progress") {
          const double f = e.body.value("fraction", 0.0);
          const QString step = QString::fromStdString(e.body.value("step", ""));
          post([this, f, step] { emit progress(f, step); });
        } else if (e.type == "point") {
          const FlopsRun run = remote::apply_point(live, e);
          post([this, run] { emit live_run(run); });
        } else if (e.type == "power") {
          const std::string total = e.body.value("total", "");
          const auto w = e.body.find("watts");
          if (w != e.body.end() && w->is_object() && w->contains(total) && (*w)[total].is_number()) {
            const double watts = (*w)[total].get<double>();
            post([this, watts, total] { emit power(watts, QString::fromStdString(total)); });
          }
        } else if (e.type == "interval") {
          try {
            sustain::append_interval(sustained, e.body);
            post([this, run = sustained] { emit sustain_interval(run); });
          } catch (const std::exception& bad) {
            const QString text = tr("an interval the robot sent was left out: %1").arg(QString::fromUtf8(bad.what()));
            post([this, text] { emit remote_text(text); });
          }
        } else if (e.type == "message" || e.type == "error") {
          const QString text = QString::fromStdString(e.body.value(e.type == "error" ? "message" : "text", ""));
          post([this, text] { emit remote_text(text); });
        }
      };
      handlers.on_remote_stderr = [this](const std::string& line) {
        const QString text = QString::fromStdString(line);
        post([this, text] { emit remote_text(text); });
      };
      job_ = remote::run_remote_job(target_, remote::new_job_id(), command_, staging, handlers, control);
      if (job_.status == "failed")
        return QString::fromStdString(target_.destination + ": the measurement failed on the robot" +
                                      (job_.error.empty() ? std::string(".") : ": " + job_.error));
      return {};
    } catch (const std::exception& e) {
      return QString::fromUtf8(e.what());
    }
  }));
}

void RemoteRun::cancel() { cancel_.cancel(); }

}  // namespace bs::ui
