// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What every requirement judged per platform outside the comparison shares (the control loop,
// headroom/loop_requirement.h; sustained performance, sustain/sustain_requirement.h): which platforms get a verdict,
// how the verdicts are ranked, and the checks a verdict adds to its platform's decision. A verdict has `platform`,
// `status` (an enum with Pass, Fail and Unknown), `checks` and `reason`; a record has `platform`.
#include <algorithm>
#include <span>
#include <string>
#include <vector>

#include "analysis/platform/platform_comparison.h"

namespace bs {

// The platforms asked about, then each platform that only has a record, in the order of its first record.
template <class Record>
std::vector<std::string> platforms_to_judge(std::vector<std::string> platforms, std::span<const Record> records) {
  for (const Record& r : records)
    if (std::find(platforms.begin(), platforms.end(), r.platform) == platforms.end()) platforms.push_back(r.platform);
  return platforms;
}

// Passing verdicts by their tightest relative margin (widest first), then failing ones by their worst (nearest
// first), then unknown ones; equal ones keep their order.
template <class Verdict>
void rank_requirement_verdicts(std::vector<Verdict>& verdicts) {
  using Status = decltype(Verdict::status);
  const auto rank = [](Status s) { return s == Status::Pass ? 0 : s == Status::Fail ? 1 : 2; };
  std::stable_sort(verdicts.begin(), verdicts.end(), [&](const Verdict& a, const Verdict& b) {
    if (rank(a.status) != rank(b.status)) return rank(a.status) < rank(b.status);
    return tightest_relative_margin(a.checks) > tightest_relative_margin(b.checks);
  });
}

// The checks `platform`'s verdict adds to its decision: a passing or failing verdict's checks; for an unknown one (or
// none), one check without a value that says why ("<requirement>: <reason>", `without_record` when the platform has
// no verdict), then the checks that have values, to be seen. Unknown is never passing.
template <class Verdict>
std::vector<ConstraintCheck> requirement_checks(const std::string& platform, std::span<const Verdict> verdicts,
                                                const std::string& requirement, const std::string& without_record) {
  using Status = decltype(Verdict::status);
  const auto it =
      std::find_if(verdicts.begin(), verdicts.end(), [&](const Verdict& v) { return v.platform == platform; });
  if (it != verdicts.end() && it->status != Status::Unknown) return it->checks;
  std::vector<ConstraintCheck> out;
  out.push_back(
      {requirement + ": " + (it == verdicts.end() ? without_record : it->reason), "", 0, std::nullopt, false, 0});
  if (it != verdicts.end())
    for (const ConstraintCheck& k : it->checks)
      if (k.actual) out.push_back(k);
  return out;
}

}  // namespace bs
