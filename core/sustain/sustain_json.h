// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A sustained run <-> JSON. The workspace keeps one run as one JSON document (`record_to_json`, read back whole by
// `record_from_json`); `benchscope-cli sustain --json` prints each interval as it completes (`interval_json`) and
// then the run with what it concludes (`result_json`). NaN (an interval without a reading) is written as null.
//
// Reading is reading untrusted input (a workspace anyone may edit): every value is type- and range-checked, series
// lengths must agree, times must increase, and the counts are bounded before anything is copied.
#include <cstddef>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "model/sustain_run.h"
#include "sustain/sustain_analysis.h"

namespace bs::sustain {

// The most intervals and series a stored run may have (a day at 20 ms intervals; a 4096-CPU machine's clocks).
inline constexpr std::size_t kMaxIntervals = std::size_t{1} << 22;
inline constexpr std::size_t kMaxSeries = 8192;

class SustainJsonError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

nlohmann::json record_to_json(const SustainRun& run);
// Throws SustainJsonError naming the place and the reason: "clocks[2].hz: 30 values for 31 intervals".
SustainRun record_from_json(const nlohmann::json& j);

// Interval i as one object: t_s, rate, clocks {name: Hz}, temperatures {name: °C}, power_w.
nlohmann::json interval_json(const SustainRun& run, std::size_t i);
// The run with its conclusions: intervals, stability_percent, stable, throttle, sustained_rate, peak_rate, ...
nlohmann::json result_json(const SustainRun& run, const SustainAnalysis& analysis);

}  // namespace bs::sustain
