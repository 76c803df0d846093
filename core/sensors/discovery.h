// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Every power sensor of this computer, and the choice of what to record: one sensor by id, or `auto`, the
// board's or package's total (the INA3221 input rail, RAPL psys or the package(s), else a GPU through NVML,
// else a hwmon power file) together with the rails beside it.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "sensors/sensor.h"

namespace bs::sensors {

struct DiscoveryOptions {
  std::filesystem::path root = "/";                // --sysfs-root
  std::string nvml_library = "libnvidia-ml.so.1";  // empty: do not look for NVML
};

// The NVML library to use: $BENCHSCOPE_NVML_LIBRARY when set ("" or "none" turns NVML off, for tests and for
// machines whose driver misbehaves), else libnvidia-ml.so.1.
std::string default_nvml_library();

struct SensorSet {
  std::vector<std::unique_ptr<Sensor>> sensors;  // RAPL, INA3221, hwmon, NVML, in that order
  std::vector<std::string> notes;                // what was looked for and not found, e.g. NVML's absence
};

SensorSet find_sensors(const DiscoveryOptions& options);

// What a recording reads: the sensors (channels, in order) and which of them is the total.
struct Selection {
  std::vector<std::unique_ptr<Sensor>> sensors;
  std::size_t total = 0;  // index into sensors
  std::string note;       // how `auto` chose, for the user
};

// `spec`: "auto", one id, or ids separated by commas (the first is the total). Takes the chosen sensors out of
// `set`. Throws std::invalid_argument naming the problem: an unknown id (with the ids there are), a sensor that
// cannot be read (with the reason), or nothing readable for auto.
Selection select_sensors(SensorSet& set, const std::string& spec);

}  // namespace bs::sensors
