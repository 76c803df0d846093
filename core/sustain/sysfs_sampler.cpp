// SPDX-License-Identifier: GPL-3.0-or-later
#include "sustain/sysfs_sampler.h"

#include <cmath>
#include <limits>
#include <regex>

#include "sensors/sysfs_file.h"

namespace bs::sustain {
namespace {

namespace fs = std::filesystem;
using sensors::describe_error;
using sensors::entries_with_prefix;
using sensors::read_sysfs;
using sensors::read_sysfs_integer;
using sensors::under_root;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// A thermal zone states its trip points as trip_point_0.. ; no driver has more than a handful, so reading stops
// at the first missing one or at this bound.
constexpr int kMaxTripPoints = 64;

bool is_numbered(const std::string& name, const std::string& prefix) {
  if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) return false;
  for (std::size_t i = prefix.size(); i < name.size(); ++i)
    if (name[i] < '0' || name[i] > '9') return false;
  return true;
}

// "/sys/class/thermal/thermal_zone0/temp" for messages, whatever the root.
std::string shown(const fs::path& root, const fs::path& file) {
  return "/" + file.lexically_relative(root).generic_string();
}

// One integer file as a value in `unit`s (value x scale), checked against [lo, hi]; the reason when not.
std::optional<double> read_scaled(const fs::path& file, double scale, double lo, double hi, const char* what,
                                  std::string& why) {
  int err = 0;
  const std::optional<long long> v = read_sysfs_integer(file, &err);
  if (!v) {
    if (err == EINVAL) {
      const std::string text = read_sysfs(file).text;
      why = text.empty() ? std::string("empty") : "'" + text.substr(0, 40) + "' is not a whole number";
    } else {
      why = describe_error(err);
    }
    return std::nullopt;
  }
  const double x = static_cast<double>(*v) * scale;
  if (!(x >= lo && x <= hi)) {
    why = std::to_string(*v) + " is not a plausible " + what;
    return std::nullopt;
  }
  return x;
}

}  // namespace

SysfsSampler::SysfsSampler(fs::path root) : root_(std::move(root)) {
  const auto warn = [&](const std::string& name, const fs::path& file, const std::string& why) {
    discovery_warnings_.push_back(name + ": " + shown(root_, file) + ": " + why);
  };
  // CPU clocks: cpufreq's current clock against cpuinfo_max_freq (the hardware's maximum, not the governor's).
  for (const fs::path& dir : entries_with_prefix(under_root(root_, "/sys/devices/system/cpu"), "cpu")) {
    const std::string name = dir.filename().string();
    if (!is_numbered(name, "cpu")) continue;
    const fs::path cur = dir / "cpufreq" / "scaling_cur_freq";
    std::error_code ec;
    if (!fs::exists(cur, ec)) continue;
    ClockSource c{name, cur, 1000, std::nullopt};
    std::string why;
    const fs::path max = dir / "cpufreq" / "cpuinfo_max_freq";
    c.max_hz = read_scaled(max, 1000, kMinClockHz, kMaxClockHz, "clock in kHz", why);
    if (!c.max_hz) warn(name, max, why + ": the clock has no stated maximum");
    clocks_.push_back(std::move(c));
  }
  if (clocks_.empty()) not_exposed_.push_back("no cpufreq under /sys/devices/system/cpu: no CPU clock");
  // Device clocks (a Jetson's GPU, a memory controller): devfreq, already in Hz.
  const std::size_t cpu_clocks = clocks_.size();
  for (const fs::path& dir : entries_with_prefix(under_root(root_, "/sys/class/devfreq"), "")) {
    const fs::path cur = dir / "cur_freq";
    std::error_code ec;
    if (!fs::exists(cur, ec)) continue;
    const std::string name = "devfreq " + dir.filename().string();
    ClockSource c{name, cur, 1, std::nullopt};
    std::string why;
    c.max_hz = read_scaled(dir / "max_freq", 1, kMinClockHz, kMaxClockHz, "clock in Hz", why);
    if (!c.max_hz) warn(name, dir / "max_freq", why + ": the clock has no stated maximum");
    clocks_.push_back(std::move(c));
  }
  if (clocks_.size() == cpu_clocks) not_exposed_.push_back("no devfreq device under /sys/class/devfreq: no GPU clock");
  // Thermal zones with their lowest passive, hot or critical trip point (an "active" trip only starts a fan).
  for (const fs::path& dir : entries_with_prefix(under_root(root_, "/sys/class/thermal"), "thermal_zone")) {
    const std::string zone = dir.filename().string();
    if (!is_numbered(zone, "thermal_zone")) continue;
    std::error_code ec;
    if (!fs::exists(dir / "temp", ec)) continue;
    const sensors::FileRead type = read_sysfs(dir / "type");
    TemperatureSource t{zone + (type.ok() && !type.text.empty() ? " " + type.text.substr(0, 64) : ""), dir / "temp",
                        std::nullopt};
    for (int k = 0; k < kMaxTripPoints; ++k) {
      const std::string stem = "trip_point_" + std::to_string(k);
      const sensors::FileRead kind = read_sysfs(dir / (stem + "_type"));
      if (!kind.ok()) break;
      if (kind.text != "passive" && kind.text != "hot" && kind.text != "critical") continue;
      std::string why;
      const auto trip = read_scaled(dir / (stem + "_temp"), 1e-3, kMinCelsius, kMaxCelsius, "temperature", why);
      if (!trip) {
        warn(t.name, dir / (stem + "_temp"), why + ": trip point left out");
        continue;
      }
      if (!t.trip_c || *trip < *t.trip_c) t.trip_c = trip;
    }
    temperatures_.push_back(std::move(t));
  }
  if (temperatures_.empty()) not_exposed_.push_back("no thermal zone under /sys/class/thermal");
  // hwmon temperatures (coretemp, k10temp, nvme, ...): tempK_input in millidegrees, named by tempK_label.
  const std::size_t zones = temperatures_.size();
  static const std::regex temp_re(R"(temp(\d+)_input)");
  for (const fs::path& dir : entries_with_prefix(under_root(root_, "/sys/class/hwmon"), "hwmon")) {
    const sensors::FileRead chip = read_sysfs(dir / "name");
    const std::string chip_name = chip.ok() && !chip.text.empty() ? chip.text.substr(0, 64) : dir.filename().string();
    for (const fs::path& f : entries_with_prefix(dir, "temp")) {
      std::smatch m;
      const std::string file = f.filename().string();
      if (!std::regex_match(file, m, temp_re)) continue;
      const sensors::FileRead label = read_sysfs(dir / ("temp" + m[1].str() + "_label"));
      const std::string what = label.ok() && !label.text.empty() ? label.text.substr(0, 64) : "temp" + m[1].str();
      temperatures_.push_back({"hwmon " + chip_name + " " + what, f, std::nullopt});
    }
  }
  if (temperatures_.size() == zones) not_exposed_.push_back("no hwmon temperature under /sys/class/hwmon");
}

SysfsSample SysfsSampler::sample() const {
  SysfsSample s;
  s.clock_hz.reserve(clocks_.size());
  s.temperature_c.reserve(temperatures_.size());
  std::string why;
  for (const ClockSource& c : clocks_) {
    const auto v = read_scaled(c.current, c.scale, kMinClockHz, kMaxClockHz,
                               c.scale == 1000 ? "clock in kHz" : "clock in Hz", why);
    s.clock_hz.push_back(v.value_or(kNaN));
    if (!v) s.warnings.push_back(c.name + ": " + shown(root_, c.current) + ": " + why + " (NaN this interval)");
  }
  for (const TemperatureSource& t : temperatures_) {
    const auto v = read_scaled(t.file, 1e-3, kMinCelsius, kMaxCelsius, "temperature in millidegrees", why);
    s.temperature_c.push_back(v.value_or(kNaN));
    if (!v) s.warnings.push_back(t.name + ": " + shown(root_, t.file) + ": " + why + " (NaN this interval)");
  }
  return s;
}

}  // namespace bs::sustain
