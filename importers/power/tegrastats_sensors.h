// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The clocks and temperatures of a tegrastats line (#53), read beside its rails (tegrastats.h):
//   CPU [12%@2035,off,3%@2035]  per-core clock in MHz -> clocks cpu0, cpu1, ...; "off" (core powered down) is NaN,
//                               never 0; JetPack 3's "CPU [12%,off,3%]@2035" gives one clock to every core on
//   GR3D_FREQ 99%@1300          the GPU clock (GR3D); "99%@[1300,1300]" (Orin: one per GPC) -> GR3D GPC0, GR3D GPC1;
//                               "GR3D_FREQ 22%" (some releases) is the load only: no GPU clock, said in not_exposed
//   EMC_FREQ 0%@1600, APE 174, VIC_FREQ 729, NVENC 1190, NVDEC off ...   other engine clocks, named without _FREQ
//   CPU@45.5C, tj@53.062C, gpu@47.1C/47.1C (JetPack 7: current/maximum)  temperatures, the current value
// A clock of 0 MHz (GR3D of a power-gated GPU) is a stopped clock, kept as NaN like "off", so it never reads as a
// throttled one. tegrastats states no maximum clock and no trip point: those stay empty.
// Sentinels, never shown as temperatures: -256 C is tegrastats' (and jetson-stats') "no reading" (the sensor's zone
// is off, e.g. the GPU's when it is power-gated), kept as NaN; PMIC@100C (or 50C) is not a measurement (the PMIC
// reports only whether its die crossed 120 or 140 C, else a fixed value) and is not imported.
// A token that looks like a reading but does not parse (CPU@abcC, GR3D_FREQ 9%@x) or an impossible value is a
// warning naming file:line:column and the field, kept as NaN: the power of that line is still good. On the file's
// last line a cut-off token is expected and left silently (the power importer already warns about that line).
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/power_trace.h"
#include "model/sustain_run.h"
#include "power/sample_series.h"

namespace bs {

class TegrastatsSensors {
 public:
  explicit TegrastatsSensors(const std::string& file) : file_(file) {}
  // One accepted line (a sample of the trace): its whitespace tokens, all views into `raw`.
  void line(const std::vector<std::string_view>& tok, std::string_view raw, std::size_t line_no, bool last);
  // The record for the finished trace (empty when the log had no clock and no temperature); its warnings added.
  std::optional<SustainRun> finish(const PowerTrace& trace, std::vector<std::string>& warnings);

 private:
  void cpu_list(std::string_view list, std::size_t column);
  void engine_clock(std::string_view name, std::string_view value, std::size_t column);
  void temperature(std::string_view name, std::string_view value, std::size_t column);
  void set_clock(std::string_view name, double mhz);
  void set_off(std::string_view name);  // off or unreadable: NaN
  void bad(std::size_t column, std::string_view field, const std::string& why);

  const std::string& file_;
  std::size_t line_no_ = 0;
  bool last_ = false;
  meter::SampleSeries clocks_{256};
  meter::SampleSeries temps_{128};
  std::vector<std::string> warnings_;
  std::size_t bad_ = 0, no_reading_ = 0, stopped_ = 0;
  bool pmic_ = false, too_many_ = false, gpu_load_only_ = false, gpu_clock_ = false;
};

}  // namespace bs
