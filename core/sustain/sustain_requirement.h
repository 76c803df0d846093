// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A sustained-performance requirement in the decision (#53), beside the control loop's: "stability>=97%,minutes>=20"
// reads "a sustained run of at least 20 minutes whose worst interval stays within 97 % of its best". Each platform is
// judged from its stored sustained records (sustain/sustain_analysis.h); a platform without one is unknown, never
// passing, and so is one whose record cannot answer a term: an imported log (tegrastats, jtop, nvidia-smi) has
// clocks and temperatures but no load rate, so it can judge throttling only.
//
// Syntax, terms separated by commas, any order, at least one:
//   stability >= <percent>%   worst interval's rate / best interval's rate (3DMark's stress test: 97 % is "stable")
//   minutes >= <n>            the record lasted at least this long (its last interval's end, t_s.back() / 60)
//   throttle = none           no throttling detected (a clock below 80 % of its maximum, a zone at its trip point)
//   sustained >= <rate>       the sustained rate (mean of the last third) in the record's own unit (GFLOPS, fps, ...)
//
// Which record judges a platform: among its records that can answer every term (a rate where a rate term is asked,
// throttling known where throttle=none is asked, at least `minutes` long), the longest; when none can, the newest
// (by its provenance date, then its place in the list), whose verdict then says what it cannot answer.
//
// A record shorter than `minutes` still fails what it already shows: worst / best over a longer run can only be
// lower, and throttling seen stays seen; a term it would pass is unknown ("run lasted 5.0 min < 20 min required").
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/platform/platform_comparison.h"
#include "analysis/platform/requirement_text.h"
#include "model/sustain_run.h"

namespace bs::sustain {

struct SustainRequirement {
  std::optional<double> min_stability_percent;
  std::optional<double> min_minutes;
  bool no_throttle = false;
  std::optional<double> min_sustained_rate;  // in the judged record's rate unit
  std::string text;                          // as the user wrote it, for messages and the stored decision
};

// Throws std::invalid_argument naming the term and what is accepted.
SustainRequirement parse_sustain_requirement(const std::string& text);
// "stability >= 97 %, at least 20 min, no throttling, sustained rate >= 50"
std::string describe(const SustainRequirement& r);

struct SustainVerdict {
  std::string platform;
  RequirementStatus status = RequirementStatus::Unknown;
  // One per term that has a value ("stability" in "% of best", "run length" in min, "throttling" in "s throttled",
  // "sustained rate" in the record's unit); a term the record cannot answer has none.
  std::vector<ConstraintCheck> checks;
  // Each judged term against its limit: "stability 91.2 % < 97 %, 5.8 points short; run 25.0 min >= 20 min".
  std::string margin;
  std::string reason;  // for unknown: why; for fail: the failed terms (as in `margin`)
  std::string record;  // which record judged it: label, date, length
};

// One verdict per platform named in `platforms` and per platform that has a record, ranked: passing ones first
// (widest relative margin first), then failing ones (nearest first), then unknown ones.
std::vector<SustainVerdict> evaluate_sustain(const SustainRequirement& r, std::span<const SustainRun> runs,
                                             const std::vector<std::string>& platforms);

// The checks a platform's sustained verdict adds to its decision: a passing or failing verdict's checks; for an
// unknown one (or none), one check without a value that says why ("sustained: no sustained run of this platform"),
// then the checks that have values.
std::vector<ConstraintCheck> sustain_checks(const std::string& platform, std::span<const SustainVerdict> verdicts);

// Adds the sustained checks to each platform's verdict (unknown = not met), then recommends again: the most compute
// among the platforms that now meet everything.
void apply_sustain(std::vector<PlatformVerdict>& verdicts, std::span<const SustainVerdict> sustain);

}  // namespace bs::sustain
