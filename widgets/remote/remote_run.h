// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One measurement on a robot, started from the GUI: the robot is checked, then the job runs (core/remote), both
// on a worker thread; the robot's events arrive here as signals on the GUI thread (progress, the sweep so far for
// the live plot, power readings, its text), and the results wait in a private staging folder until the main
// window has imported them. Destroying it while it runs drops the connection: the robot stops everything.
#include <QFutureWatcher>
#include <QObject>
#include <QString>
#include <QTemporaryDir>
#include <memory>
#include <string>
#include <vector>

#include "model/flops_run.h"
#include "model/sustain_run.h"
#include "remote/job_client.h"
#include "remote/robot_check.h"

namespace bs::ui {

class RemoteRun : public QObject {
  Q_OBJECT
 public:
  RemoteRun(remote::SshTarget target, std::vector<std::string> command, QObject* parent = nullptr);
  ~RemoteRun() override;
  void start();
  // Asks the robot to stop as Ctrl+C would: what it completed comes home (finished() with status "cancelled").
  void cancel();
  bool running() const { return running_; }
  const remote::SshTarget& target() const { return target_; }
  const std::vector<std::string>& command() const { return command_; }
  // After finished():
  const remote::RemoteJob& job() const { return job_; }
  const remote::RobotInfo& robot() const { return robot_; }

 signals:
  void progress(double fraction, const QString& step);
  void live_run(const bs::FlopsRun& run);               // the sweep of one D so far
  void sustain_interval(const bs::SustainRun& so_far);  // a sustained run's intervals so far
  void power(double watts, const QString& channel);     // each reading of the total
  void remote_text(const QString& line);                // the robot's messages
  void finished();                                      // job() and robot() are set; files staged
  void failed(const QString& message);                  // nothing came home

 private:
  void post(std::function<void()> fn);
  remote::SshTarget target_;
  std::vector<std::string> command_;
  QTemporaryDir staging_;
  CancelToken cancel_, abort_;
  QFutureWatcher<QString>* watcher_ = nullptr;
  remote::RemoteJob job_;
  remote::RobotInfo robot_;
  bool running_ = false;
};

}  // namespace bs::ui
