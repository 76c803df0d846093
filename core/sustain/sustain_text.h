// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A sustained run in words (#53), the same for `benchscope-cli sustain`, the Sustained tab and the desk's status
// line: one line per interval as it completes (rate, the clock furthest below its maximum, the sensor nearest its
// trip point, power), and the conclusions as labelled rows with units, mean ± SD and n.
#include <string>
#include <vector>

#include "model/sustain_run.h"
#include "sustain/sustain_analysis.h"

namespace bs::sustain {

// "12.0 s: 10.31 GFLOPS, cpu0 2.90 GHz (97 % of max), thermal_zone0 x86_pkg_temp 71.0 °C (trip 95.0 °C), 31.20 W"
std::string interval_line(const SustainRun& run, std::size_t index);

struct SummaryRow {
  std::string label;   // "stability"
  std::string value;   // "91.2 % (worst / best interval): NOT stable (threshold 97.0 %)"
  bool alarm = false;  // a verdict against the lab: not stable, throttling detected
};

// The record's heading is the caller's; these are its conclusions, in the order the CLI prints them.
std::vector<SummaryRow> summary_rows(const SustainRun& run, const SustainAnalysis& analysis);

}  // namespace bs::sustain
