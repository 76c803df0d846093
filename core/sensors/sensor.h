// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The computer's own power sensors behind one interface: Intel/AMD RAPL (powercap), the Jetson INA3221 (both the
// JetPack 5+ hwmon driver and the JetPack 4 ina3221x iio driver), any hwmon power or energy file, and NVIDIA GPUs
// through NVML. Every sysfs reader takes a root folder ("/" on the machine itself; a fixture tree in tests, the
// host's /sys bind-mounted somewhere in a container), so nothing here needs real hardware to be tested.
#include <optional>
#include <string>
#include <string_view>

namespace bs::sensors {

enum class SensorKind { Rapl, Ina3221, Hwmon, Nvml };
std::string_view to_string(SensorKind kind);  // "rapl", "ina3221", "hwmon", "nvml"

// What the hardware gives: an instantaneous power, or an energy counter from which power is delta E / delta t.
enum class SensorQuantity { Power, Energy };

struct SensorInfo {
  std::string id;  // stable and unique on this machine: "rapl:package-0", "ina3221:1-0040:VDD_IN", "nvml:0"
  SensorKind kind = SensorKind::Hwmon;
  std::string label;   // the rail or domain: "package-0", "VDD_IN", "power1", "NVIDIA H100"
  std::string device;  // the chip or driver it belongs to: "intel-rapl:0", "ina3221 1-0040", "hwmon2 (amdgpu)"
  std::string source;  // the file(s) or library it reads, for the user to check by hand
  SensorQuantity quantity = SensorQuantity::Power;
  std::string unit;  // as read: "uJ", "mW", "uW", "mV x mA", "mW (NVML)"
  bool readable = false;
  std::string reason;  // when not readable: why, and the fix when there is one
  // The whole board's or package's power (RAPL package/psys, the INA3221 input rail VDD_IN/POM_5V_IN), as
  // opposed to one rail inside it. `auto` records these.
  bool board_total = false;
};

class Sensor {
 public:
  virtual ~Sensor() = default;
  const SensorInfo& info() const { return info_; }
  // One reading. Power sensors: watts now. Energy sensors: joules since this sensor's first read, counter
  // wraparound already added back, so the caller only subtracts. Empty when the read failed this time.
  virtual std::optional<double> read() = 0;

 protected:
  SensorInfo info_;
};

}  // namespace bs::sensors
