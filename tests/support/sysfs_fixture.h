// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Fake sysfs trees for the power-sensor tests: the files the kernel drivers write, with the names and units of
// Documentation/power/powercap/powercap.rst (RAPL), Documentation/hwmon/ina3221.rst and sysfs-interface.rst
// (hwmon), and NVIDIA's ina3221x iio driver (JetPack 4), under a temporary root passed as --sysfs-root.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace bs::test {

// Writes `text` + '\n' to root/rel, creating folders; through a rename, so a reader never sees half a value.
inline void put(const std::filesystem::path& root, const std::string& rel, const std::string& text) {
  const auto path = root / rel;
  std::filesystem::create_directories(path.parent_path());
  const auto tmp = path.string() + ".tmp";
  {
    std::ofstream f(tmp, std::ios::trunc);
    f << text << '\n';
  }
  std::filesystem::rename(tmp, path);
}

// RAPL package-0 with a core sub-zone (powercap layout: /sys/class/powercap/intel-rapl:0[:0]).
inline void rapl_package(const std::filesystem::path& root, int package, long long energy_uj, long long max_uj) {
  const std::string z = "sys/class/powercap/intel-rapl:" + std::to_string(package);
  put(root, z + "/name", "package-" + std::to_string(package));
  put(root, z + "/energy_uj", std::to_string(energy_uj));
  put(root, z + "/max_energy_range_uj", std::to_string(max_uj));
  put(root, z + "/enabled", "1");
}
inline void rapl_subzone(const std::filesystem::path& root, int package, int sub, const std::string& name,
                         long long energy_uj, long long max_uj) {
  const std::string z = "sys/class/powercap/intel-rapl:" + std::to_string(package) + ":" + std::to_string(sub);
  put(root, z + "/name", name);
  put(root, z + "/energy_uj", std::to_string(energy_uj));
  put(root, z + "/max_energy_range_uj", std::to_string(max_uj));
}

// JetPack 5+ (mainline ina3221 hwmon driver): channels 1..3, inN_label, inN_input (mV), currN_input (mA).
inline std::string ina3221_hwmon_dir(const std::string& bus_addr, int hwmon) {
  return "sys/bus/i2c/drivers/ina3221/" + bus_addr + "/hwmon/hwmon" + std::to_string(hwmon);
}
inline void ina3221_hwmon_channel(const std::filesystem::path& root, const std::string& dir, int ch,
                                  const std::string& label, long long mv, long long ma) {
  const std::string n = std::to_string(ch);
  put(root, dir + "/in" + n + "_label", label);
  put(root, dir + "/in" + n + "_input", std::to_string(mv));
  put(root, dir + "/curr" + n + "_input", std::to_string(ma));
}

// JetPack 4 (NVIDIA's ina3221x iio driver): channels 0..2, rail_name_N, in_powerN_input (mW), in_currentN_input
// (mA), in_voltageN_input (mV).
inline void ina3221x_channel(const std::filesystem::path& root, const std::string& bus_addr, int ch,
                             const std::string& rail, long long mw, long long ma, long long mv) {
  const std::string d = "sys/bus/i2c/drivers/ina3221x/" + bus_addr + "/iio:device0/";
  const std::string n = std::to_string(ch);
  put(root, d + "rail_name_" + n, rail);
  put(root, d + "in_power" + n + "_input", std::to_string(mw));
  put(root, d + "in_current" + n + "_input", std::to_string(ma));
  put(root, d + "in_voltage" + n + "_input", std::to_string(mv));
}

}  // namespace bs::test
