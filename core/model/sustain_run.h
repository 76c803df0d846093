// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A sustained-performance record (#53): what a load achieved interval by interval over minutes, with every clock
// and temperature the machine exposes on the same time axis. `benchscope-cli sustain` writes one from a run on
// this computer or a robot; the importers make one from a lab's own long logs (tegrastats, jtop CSV, nvidia-smi),
// which carry clocks and temperatures but no load rate.
#include <optional>
#include <string>
#include <vector>

#include "model/provenance.h"

namespace bs {

// One clock, one value per interval (the interval's last reading). NaN: not read in that interval.
struct ClockSeries {
  std::string name;              // "cpu0", "gpu 17000000.gv11b", "GR3D", "SM"
  std::optional<double> max_hz;  // the clock's stated maximum (cpuinfo_max_freq, devfreq max_freq); absent: unknown
  std::vector<double> hz;
};

// One temperature sensor, one value per interval (the interval's highest reading). NaN: not read.
struct TemperatureSeries {
  std::string name;              // "thermal_zone0 x86_pkg_temp", "hwmon coretemp Package id 0", "CPU", "GPU"
  std::optional<double> trip_c;  // the lowest passive/hot/critical trip point the zone states; absent: none stated
  std::vector<double> celsius;
};

struct SustainRun {
  std::string platform;   // "NUC", "Jetson TX2"
  std::string label;      // "flops for 600 s", the log's file name
  std::string load;       // as asked: "flops", "pipeline@30", "dnn:mobilenet-ssd"; empty for an imported log
  std::string rate_unit;  // "GFLOPS", "fps", "inferences/s"; empty when the record has no rate (an imported log)
  double interval_s = 0;  // the asked interval; the real ones are t_s's differences
  // End of each interval, seconds from the start of the run (or log), increasing.
  std::vector<double> t_s;
  // The load's achieved rate in each interval; empty for a record without a rate, else one per t_s (NaN where an
  // interval completed no work).
  std::vector<double> rate;
  std::vector<ClockSeries> clocks;
  std::vector<TemperatureSeries> temperatures;
  // Mean power in each interval where a sensor or the log gave one; empty when none, else one per t_s.
  std::vector<double> power_w;
  std::string power_sensor;  // "RAPL package-0", "tegrastats VDD_IN"
  // What the machine did not expose, in words ("no cpufreq under /sys/devices/system/cpu: no CPU clock"), so a
  // missing clock is never read as "no throttling".
  std::vector<std::string> not_exposed;
  Provenance provenance;
};

}  // namespace bs
