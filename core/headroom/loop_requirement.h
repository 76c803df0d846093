// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A control-loop requirement in the decision, like a power budget: "1kHz,p99.9<=200us,max-consecutive-misses<=1,
// load=pipeline@30fps" reads "a 1 kHz loop whose p99.9 latency stays within 200 us and that never misses two
// deadlines in a row while the vision pipeline runs at 30 fps". Each platform is checked against its headroom
// measurement (an application loop at that rate, in the named phase); a platform without one is unknown, never
// passing, and one whose measurement cannot answer a term (no run lengths in an imported histogram) is unknown too.
//
// Syntax, terms separated by commas, any order, the rate required:
//   <rate>                 1kHz, 500Hz, 1000hz
//   p50|p99|p99.9|p99.99|max <= <time>     time in ns, us or ms (200us, 0.2ms)
//   misses <= <percent>%   deadline misses as measured (latency + computation > the measurement's deadline)
//   max-consecutive-misses <= <n>          the longest run of consecutive misses
//   load=<phase>           the phase to judge (pipeline@30fps, dnn:yolo-n, flops:64, idle); absent: every phase,
//                          the worst one decides
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "analysis/platform/platform_comparison.h"
#include "analysis/platform/requirement_text.h"
#include "headroom/headroom_measurement.h"

namespace bs::headroom {

struct LoopRequirement {
  double rate_hz = 0;
  std::optional<std::int64_t> p50_ns, p99_ns, p999_ns, p9999_ns, max_ns;
  std::optional<double> max_miss_percent;
  std::optional<std::uint64_t> max_consecutive_misses;
  std::string load;  // phase name; "" = every phase
  std::string text;  // as the user wrote it, for messages
};

// Throws std::invalid_argument naming the term and what is accepted.
LoopRequirement parse_loop_requirement(const std::string& text);
// "1 kHz, p99.9 <= 200 us, max consecutive misses <= 1, beside pipeline@30fps"
std::string describe(const LoopRequirement& r);

struct LoopVerdict {
  std::string platform;
  RequirementStatus status = RequirementStatus::Unknown;
  std::vector<ConstraintCheck> checks;  // one per term, "p99.9 (pipeline@30fps)" in us; actual empty when unknown
  std::string reason;                   // for unknown: why; for fail: the worst term and by how much
  std::string measurement;              // which measurement judged it: tool, date, phase, thread
  bool realtime = false;                // that measurement ran under SCHED_FIFO/RR
};

// One verdict per platform named in `platforms` and per platform that has a measurement, ranked: passing ones first
// (widest relative margin first), then failing ones (nearest first), then unknown ones.
// The checks a platform's loop verdict adds to its decision (the Platforms verdicts, the candidates): a passing or
// failing verdict's terms; for an unknown one (or none), one check without a value that says why, then the terms
// that have values.
std::vector<ConstraintCheck> loop_checks(const std::string& platform, std::span<const LoopVerdict> loop);

std::vector<LoopVerdict> evaluate_loop(const LoopRequirement& r, std::span<const HeadroomMeasurement> measurements,
                                       const std::vector<std::string>& platforms);

// Adds the loop's checks to each platform's verdict (unknown = not met), then recommends again: the most compute
// among the platforms that now meet everything.
void apply_loop(std::vector<PlatformVerdict>& verdicts, std::span<const LoopVerdict> loop);

}  // namespace bs::headroom
