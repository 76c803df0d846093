// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Jetson boards' INA3221 three-channel power monitors, in both kernel layouts:
//  - JetPack 5+ (mainline hwmon driver): sys/bus/i2c/drivers/ina3221/<bus-addr>/hwmon/hwmon*/ with inN_label,
//    inN_input (bus voltage, mV) and currN_input (mA), channels 1..3; power = V x I.
//  - JetPack 4 (NVIDIA's ina3221x iio driver): sys/bus/i2c/drivers/ina3221x/<bus-addr>/iio:device*/ with
//    rail_name_N, in_powerN_input (mW), in_currentN_input (mA), in_voltageN_input (mV), channels 0..2.
// The board's total is its input rail (VDD_IN, or POM_5V_IN on the Nano), which already contains every other
// rail: it is marked board_total, and nothing ever adds the rails to it.
#include <filesystem>
#include <memory>
#include <string_view>
#include <vector>

#include "sensors/sensor.h"

namespace bs::sensors {

// Whether a rail name is a board's input (total) rail: VDD_IN, POM_5V_IN, 5V_IN (Xavier NX documentation).
bool is_input_rail(std::string_view rail);

std::vector<std::unique_ptr<Sensor>> find_ina3221(const std::filesystem::path& root);

}  // namespace bs::sensors
