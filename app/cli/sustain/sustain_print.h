// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The sustained run in words (#53): one line per interval as it completes (rate, lowest clock against its maximum,
// hottest temperature against its trip point, power), and the summary at the end with units.
#include <iosfwd>
#include <string>

#include "model/sustain_run.h"
#include "sustain/sustain_analysis.h"

namespace bs::cli {

// "  12.0 s  10.31 GFLOPS  cpu0 2.90 GHz (97 % of max)  thermal_zone0 x86_pkg_temp 71.0 °C (trip 95.0 °C)"
std::string interval_line(const SustainRun& run, std::size_t index);
void print_sustain(std::ostream& out, const SustainRun& run, const sustain::SustainAnalysis& analysis);

}  // namespace bs::cli
