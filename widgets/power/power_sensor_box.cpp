// SPDX-License-Identifier: GPL-3.0-or-later
#include "power/power_sensor_box.h"

#include <QStandardItemModel>
#include <algorithm>

#include "sensors/discovery.h"

namespace bs::ui {

PowerSensorBox::PowerSensorBox(QWidget* parent) : QComboBox(parent) {
  setToolTip(
      tr("Sample one of this computer's power sensors while it runs (RAPL, Jetson INA3221, hwmon, NVML); "
         "auto takes the board's or package's total. The trace is stored with the run (Power tab)."));
  if (const QByteArray root = qgetenv("BENCHSCOPE_SYSFS_ROOT"); !root.isEmpty()) root_ = QString::fromLocal8Bit(root);
  refresh();
}

void PowerSensorBox::refresh() {
  clear();
  addItem(tr("off"), QString());
  const sensors::SensorSet set = sensors::find_sensors({root_.toStdString(), sensors::default_nvml_library()});
  const bool any =
      std::any_of(set.sensors.begin(), set.sensors.end(), [](const auto& s) { return s->info().readable; });
  if (any) addItem(tr("auto (board or package total)"), QStringLiteral("auto"));
  auto* items = qobject_cast<QStandardItemModel*>(model());
  for (const auto& s : set.sensors) {
    const sensors::SensorInfo& i = s->info();
    addItem(QStringLiteral("%1 — %2").arg(QString::fromStdString(i.id), QString::fromStdString(i.label)),
            QString::fromStdString(i.id));
    const int row = count() - 1;
    setItemData(row, QString::fromStdString(i.readable ? i.device + ", " + i.source : "not readable: " + i.reason),
                Qt::ToolTipRole);
    if (!i.readable && items) items->item(row)->setEnabled(false);
  }
  if (set.sensors.empty()) setItemData(0, tr("no power sensors found"), Qt::ToolTipRole);
}

void PowerSensorBox::set_sysfs_root(const QString& root) {
  root_ = root;
  refresh();
}

bool PowerSensorBox::choose(const QString& spec) {
  const int i = findData(spec);
  if (i < 0) return false;
  setCurrentIndex(i);
  return true;
}

std::shared_ptr<sensors::PowerRecorder> PowerSensorBox::start_recorder() const {
  if (off()) return nullptr;
  sensors::SensorSet set = sensors::find_sensors({root_.toStdString(), sensors::default_nvml_library()});
  auto rec = std::make_shared<sensors::PowerRecorder>(
      sensors::select_sensors(set, currentData().toString().toStdString()), std::chrono::milliseconds(100));
  rec->start();
  return rec;
}

}  // namespace bs::ui
