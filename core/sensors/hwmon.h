// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Any hwmon device's power and energy files (Documentation/hwmon/sysfs-interface): sys/class/hwmon/hwmon*/
// power<N>_input and power<N>_average in microwatts (amdgpu's PPT, ACPI power meters, INA2xx chips),
// energy<N>_input in microjoules (AMD Zen's amd_energy, Apple/ARM energy counters), named by power<N>_label /
// energy<N>_label when the driver gives one and by the device's `name` file.
#include <filesystem>
#include <memory>
#include <vector>

#include "sensors/sensor.h"

namespace bs::sensors {

std::vector<std::unique_ptr<Sensor>> find_hwmon(const std::filesystem::path& root);

}  // namespace bs::sensors
