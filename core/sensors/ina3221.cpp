// SPDX-License-Identifier: GPL-3.0-or-later
#include "sensors/ina3221.h"

#include "sensors/sysfs_file.h"

namespace bs::sensors {
namespace {

// JetPack 5+: mV and mA files of one channel; W = mV x mA x 1e-6.
class Ina3221HwmonRail final : public Sensor {
 public:
  Ina3221HwmonRail(const std::filesystem::path& root, const std::filesystem::path& hwmon, const std::string& bus_addr,
                   int channel, const std::string& rail)
      : volts_(hwmon / ("in" + std::to_string(channel) + "_input")),
        amps_(hwmon / ("curr" + std::to_string(channel) + "_input")) {
    info_.id = "ina3221:" + bus_addr + ":" + rail;
    info_.kind = SensorKind::Ina3221;
    info_.label = rail;
    info_.device = "ina3221 " + bus_addr + " (hwmon)";
    info_.source = "/" + std::filesystem::relative(volts_, root).string() + " x " + amps_.filename().string();
    info_.quantity = SensorQuantity::Power;
    info_.unit = "mV x mA";
    info_.board_total = is_input_rail(rail);
    int err = 0;
    if (read_sysfs_integer(volts_, &err) && read_sysfs_integer(amps_, &err))
      info_.readable = true;
    else
      info_.reason = describe_error(err);
  }
  std::optional<double> read() override {
    const auto mv = read_sysfs_integer(volts_);
    const auto ma = read_sysfs_integer(amps_);
    if (!mv || !ma) return std::nullopt;
    return static_cast<double>(*mv) * static_cast<double>(*ma) * 1e-6;
  }

 private:
  std::filesystem::path volts_, amps_;
};

// JetPack 4: the driver computes power itself, in mW.
class Ina3221xRail final : public Sensor {
 public:
  Ina3221xRail(const std::filesystem::path& root, const std::filesystem::path& dev, const std::string& bus_addr,
               int channel, const std::string& rail)
      : power_(dev / ("in_power" + std::to_string(channel) + "_input")) {
    info_.id = "ina3221:" + bus_addr + ":" + rail;
    info_.kind = SensorKind::Ina3221;
    info_.label = rail;
    info_.device = "ina3221x " + bus_addr + " (iio)";
    info_.source = "/" + std::filesystem::relative(power_, root).string();
    info_.quantity = SensorQuantity::Power;
    info_.unit = "mW";
    info_.board_total = is_input_rail(rail);
    int err = 0;
    if (read_sysfs_integer(power_, &err))
      info_.readable = true;
    else
      info_.reason = describe_error(err);
  }
  std::optional<double> read() override {
    const auto mw = read_sysfs_integer(power_);
    if (!mw) return std::nullopt;
    return static_cast<double>(*mw) * 1e-3;
  }

 private:
  std::filesystem::path power_;
};

// Labels of channels that are no rail: unconnected ("NC") and the Orin's shunt-sum channel.
bool usable_rail(const std::string& label) {
  return !label.empty() && label != "NC" && label.find("Sum of") == std::string::npos;
}

}  // namespace

bool is_input_rail(std::string_view rail) { return rail == "VDD_IN" || rail == "POM_5V_IN" || rail == "5V_IN"; }

std::vector<std::unique_ptr<Sensor>> find_ina3221(const std::filesystem::path& root) {
  std::vector<std::unique_ptr<Sensor>> out;
  for (const auto& dev : entries_with_prefix(under_root(root, "/sys/bus/i2c/drivers/ina3221"), "")) {
    const std::string bus_addr = dev.filename().string();
    if (bus_addr.find('-') == std::string::npos) continue;  // "bind", "uevent", "module": not devices
    for (const auto& hwmon : entries_with_prefix(dev / "hwmon", "hwmon")) {
      for (int ch = 1; ch <= 3; ++ch) {
        const FileRead label = read_sysfs(hwmon / ("in" + std::to_string(ch) + "_label"));
        if (!label.ok() || !usable_rail(label.text)) continue;
        out.push_back(std::make_unique<Ina3221HwmonRail>(root, hwmon, bus_addr, ch, label.text));
      }
    }
  }
  for (const auto& dev : entries_with_prefix(under_root(root, "/sys/bus/i2c/drivers/ina3221x"), "")) {
    const std::string bus_addr = dev.filename().string();
    if (bus_addr.find('-') == std::string::npos) continue;
    for (const auto& iio : entries_with_prefix(dev, "iio:device")) {
      for (int ch = 0; ch <= 2; ++ch) {
        const FileRead rail = read_sysfs(iio / ("rail_name_" + std::to_string(ch)));
        if (!rail.ok() || !usable_rail(rail.text)) continue;
        out.push_back(std::make_unique<Ina3221xRail>(root, iio, bus_addr, ch, rail.text));
      }
    }
  }
  return out;
}

}  // namespace bs::sensors
