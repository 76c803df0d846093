// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A headroom measurement <-> JSON: the workspace keeps one measurement as one JSON document (read whole, never
// queried field by field), `benchscope-cli headroom --json` prints it with each thread's summary added, and tests
// round-trip it. Histograms are written sparse ([bin, count] pairs): a 10 ms limit is 10,000 bins, mostly empty.
//
// Reading is reading untrusted input (a workspace anyone may edit): every value is type- and range-checked, the
// bin count is bounded before anything is allocated, and the bookkeeping (cycles == bins + overflows) must hold.
#include <cstddef>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "headroom/headroom_measurement.h"

namespace bs::headroom {

// The most bins a histogram read back may have (4 s at 1 us bins; 32 MiB of counts).
inline constexpr std::size_t kMaxHistogramBins = std::size_t{1} << 22;

// A value that breaks the rules, with its place: "phases[1].threads[0].histogram.cycles: 12 != 10 in bins + 1".
class HeadroomJsonError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// with_summary adds each thread's "summary" (percentiles, misses, as summarize() gives them) for readers of the CLI's
// output; measurement_from_json ignores it.
nlohmann::json to_json(const HeadroomMeasurement& m, bool with_summary = false);
nlohmann::json to_json(const LatencySummary& s);
nlohmann::json to_json(const KernelFacts& k);
// Throws HeadroomJsonError naming the place and the reason.
HeadroomMeasurement measurement_from_json(const nlohmann::json& j);

}  // namespace bs::headroom
