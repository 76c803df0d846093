// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// "Record power": a combo box of this computer's power sensors (core/sensors): off, auto (the board's or
// package's total) and every sensor found, the unreadable ones listed but disabled with the reason as tooltip.
// Makes the recorder when a run starts. Shared by the Kernel Runner and the Pipeline tab's measure panel.
#include <QComboBox>
#include <memory>

#include "sensors/recorder.h"

namespace bs::ui {

class PowerSensorBox : public QComboBox {
  Q_OBJECT
 public:
  explicit PowerSensorBox(QWidget* parent = nullptr);
  // Where the sensors' files are: "/" unless set, or $BENCHSCOPE_SYSFS_ROOT at start. Lists the sensors again.
  void set_sysfs_root(const QString& root);
  // "" (off), "auto" or a sensor id; false when the list has no such entry.
  bool choose(const QString& spec);
  bool off() const { return currentData().toString().isEmpty(); }
  // A started recorder for the chosen sensor(s), or null when off. Throws std::invalid_argument saying why not.
  std::shared_ptr<sensors::PowerRecorder> start_recorder() const;

 private:
  void refresh();
  QString root_ = "/";
};

}  // namespace bs::ui
