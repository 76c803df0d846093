// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a sustained run (#53) reads at the end of every interval, under a settable root ("/" on the machine, a
// fixture tree in tests): every CPU's clock against its maximum (cpufreq, kHz), every devfreq device's clock (a
// Jetson's GPU, Hz), every thermal zone with its lowest passive/hot/critical trip point, and every hwmon
// temperature. The sources are found once, when the sampler is made; each sample then reads one small file per
// source through the bounded sysfs reader. A value that is missing, junk or out of any plausible range is NaN for
// that interval with a warning naming the file, never a crash; what the machine does not expose at all is said in
// words, so that a missing clock never reads as "no throttling".
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace bs::sustain {

struct ClockSource {
  std::string name;  // "cpu0", "gpu 17000000.gv11b"
  std::filesystem::path current;
  double scale = 1;              // to Hz: 1000 for cpufreq's kHz, 1 for devfreq
  std::optional<double> max_hz;  // cpuinfo_max_freq / max_freq when readable and plausible
};

struct TemperatureSource {
  std::string name;  // "thermal_zone0 x86_pkg_temp", "hwmon coretemp Package id 0"
  std::filesystem::path file;
  std::optional<double> trip_c;  // the lowest passive/hot/critical trip point, thermal zones only
};

struct SysfsSample {
  std::vector<double> clock_hz;       // one per clock source, NaN where the read failed
  std::vector<double> temperature_c;  // one per temperature source, NaN where the read failed
  std::vector<std::string> warnings;  // "cpu1: .../scaling_cur_freq: 'abc' is not a clock in kHz (NaN)"
};

class SysfsSampler {
 public:
  explicit SysfsSampler(std::filesystem::path root = "/");
  const std::vector<ClockSource>& clocks() const { return clocks_; }
  const std::vector<TemperatureSource>& temperatures() const { return temperatures_; }
  // What is not there, in words ("no cpufreq under /sys/devices/system/cpu: no CPU clock").
  const std::vector<std::string>& not_exposed() const { return not_exposed_; }
  // Problems met while finding the sources (an unreadable maximum, a junk trip point).
  const std::vector<std::string>& discovery_warnings() const { return discovery_warnings_; }
  SysfsSample sample() const;

 private:
  std::filesystem::path root_;
  std::vector<ClockSource> clocks_;
  std::vector<TemperatureSource> temperatures_;
  std::vector<std::string> not_exposed_, discovery_warnings_;
};

// Plausible ranges: a clock from 1 kHz to 100 GHz, a temperature from -100 to 300 °C. Outside: a misread.
inline constexpr double kMinClockHz = 1e3, kMaxClockHz = 1e11;
inline constexpr double kMinCelsius = -100, kMaxCelsius = 300;

}  // namespace bs::sustain
