// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where the Kernel Runner measures: this computer, or a robot reached over SSH (the robots of the SSH config and
// those added, core/remote/robots.h). Choosing a robot checks it at once off the GUI thread (architecture,
// BenchScope there, backends, power sensors); the result, or the problem with the command that fixes it, shows
// under the box. The platform its results will carry is filled from the robot (its stored name, else its host
// name) for the user to confirm or rename.
#include <QFutureWatcher>
#include <QWidget>
#include <memory>
#include <optional>
#include <vector>

#include "remote/robots.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace bs::ui {

class RobotTarget : public QWidget {
  Q_OBJECT
 public:
  explicit RobotTarget(QWidget* parent = nullptr);
  ~RobotTarget() override;
  bool is_robot() const;
  QString robot_name() const;  // empty for this computer
  remote::SshTarget target() const;
  // The last check of the chosen robot; none while it runs or for this computer.
  const std::optional<remote::RobotCheck>& check() const { return check_; }
  bool checking() const { return watcher_ != nullptr; }
  QString platform() const;  // as the user confirmed or renamed it
  // Why a measurement cannot start on the chosen robot now (being checked, or its check failed), naming the button
  // to press again ("Run", "Measure"); empty when it can.
  QString not_ready(const QString& button) const;
  // Stores the platform name with the robot (its next runs get it too).
  void remember_platform();
  // The robots list again (from the file and the SSH config), keeping the choice when it is still there.
  void reload();
  void select(const QString& name);  // empty: this computer
  void recheck();
  // The robots known now, for a run on several.
  std::vector<remote::Robot> robots() const { return robots_; }
  QComboBox* box() const { return box_; }
  QLineEdit* platform_field() const { return platform_; }
  QLabel* status_label() const { return status_; }

 signals:
  void changed();  // another target, or a check finished

 private:
  void on_choice();
  void add_robot();
  QComboBox* box_;
  QLabel* status_;
  QPushButton* check_button_;
  QLineEdit* platform_;
  QWidget* robot_row_;
  std::vector<remote::Robot> robots_;
  std::optional<remote::RobotCheck> check_;
  QFutureWatcher<remote::RobotCheck>* watcher_ = nullptr;
  std::shared_ptr<CancelToken> abort_ = std::make_shared<CancelToken>();
  QString checking_name_;
  bool platform_edited_ = false;
};

}  // namespace bs::ui
