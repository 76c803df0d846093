// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// "Run here or on a robot" for a measurement panel, without a widget of its own (the pattern of QGroundControl's
// controllers behind its views): the panel builds its settings and says what to run here (a function run off the GUI
// thread with a cancel token and progress) or which words a robot's CLI runs (core/commands); this controller starts
// it, relays progress and the robot's text, cancels, and says how it ended. A panel's Run, Cancel, progress bar and
// status line stay the panel's; their enabling follows `busy_changed`.
#include <QObject>
#include <QString>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "remote/ssh.h"
#include "util/cancel.h"

class QAbstractButton;
class QLabel;
class QProgressBar;
template <class T>
class QFutureWatcher;

namespace bs::ui {

class RemoteRun;
class RobotTarget;

class RunHereOrRobot : public QObject {
  Q_OBJECT
 public:
  // Work done here: runs on a worker thread; throws Cancelled when the token is cancelled, anything else to fail.
  // What it produces it keeps itself (the panel's captured state), read in `here_finished`.
  using HereWork = std::function<void(const CancelToken& token)>;

  RunHereOrRobot(RobotTarget* target, QObject* parent = nullptr);
  ~RunHereOrRobot() override;  // a run still going is cancelled and waited for; a robot's connection dropped

  bool running() const;
  bool on_robot() const;  // the chosen target is a robot (what Run will do)
  RobotTarget* target() const { return target_; }

  // Starts work here. False (and `failed`) when something runs already.
  bool start_here(HereWork work);
  // Starts `words` (the robot's CLI arguments) on the chosen robot after checking that it is ready; the platform the
  // user confirmed is remembered with the robot. False (and `failed` naming why) when it cannot start.
  bool start_on_robot(const std::vector<std::string>& words);
  // Starts `words` on `robot`, its results to go under `platform`: one robot of a queue the panel runs in turn
  // ("Several robots…"), not necessarily the chosen one, so no check of the chosen one (the job checks its robot
  // before it runs anyway). False (and `failed`) when something runs already.
  bool start_on(const remote::SshTarget& robot, const QString& platform, const std::vector<std::string>& words);
  void cancel();
  // The panel's Run and Cancel buttons, progress bar and status line follow the controller: Run disabled and Cancel
  // enabled while busy, the bar shown then (busy without a value on a robot until it says how far it is), the status
  // line its words. The panel still feeds the bar from `progress` its own way.
  void drive(QAbstractButton* run, QAbstractButton* cancel, QProgressBar* progress, QLabel* status);

 signals:
  void busy_changed(bool busy);
  void progress(double fraction, const QString& step);  // here: the token's reports; a robot: its events
  void status(const QString& text);                     // a line for the panel's status label
  void robot_text(const QString& line);                 // the robot's own messages (live output)
  void robot_started(bs::ui::RemoteRun* run);           // for a panel's own live signals of its kind
  void here_finished(bool cancelled);                   // the work returned or was cancelled
  // A robot's job came home (cancelled jobs too: the robot keeps nothing half-done); `platform` as confirmed. The
  // run is deleted later, after this signal.
  void robot_finished(bs::ui::RemoteRun* run, const QString& platform);
  void failed(const QString& message);  // here or on the robot; nothing came of it

 private:
  void here_done();
  void robot_done();

  RobotTarget* target_;
  QFutureWatcher<QString>* watcher_;  // the work here: "" or its error
  std::shared_ptr<CancelToken> token_;
  std::unique_ptr<RemoteRun> remote_;
};

}  // namespace bs::ui
