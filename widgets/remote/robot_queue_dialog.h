// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// "Several robots…": which robots run the same sweep one after another, each under which platform name (its
// stored name, else its host name, else the SSH name: the user confirms or renames it here), and on which backend
// (an id every robot understands: cpu, cpu-scalar, opencl, cuda, or one of the first robot's own).
#include <QDialog>
#include <utility>
#include <vector>

#include "remote/robots.h"

class QComboBox;
class QTableWidget;

namespace bs::ui {

class RobotQueueDialog : public QDialog {
  Q_OBJECT
 public:
  RobotQueueDialog(const std::vector<remote::Robot>& robots, const QString& backend, QWidget* parent = nullptr);
  // The checked robots in list order, each with its platform name.
  std::vector<std::pair<QString, QString>> chosen() const;
  QString backend() const;
  QTableWidget* table() const { return table_; }
  QComboBox* backend_box() const { return backend_; }

 private:
  QTableWidget* table_;
  QComboBox* backend_;
};

}  // namespace bs::ui
