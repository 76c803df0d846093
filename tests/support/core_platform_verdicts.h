// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Platforms as the comparison leaves them before a requirement judged outside it (the control loop, sustained
// performance) adds its checks: the tests of those requirements start from the same verdicts and check who is
// recommended once the requirement has had its say.
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "analysis/platform/platform_comparison.h"

namespace bs::test {

// One verdict per platform, in the order given, with its ranked compute (FLOP/s); every one meets all constraints
// so far, and the one with the most compute is recommended, as recommend() would have chosen.
inline std::vector<PlatformVerdict> verdicts_meeting_all(const std::vector<std::pair<std::string, double>>& compute) {
  std::vector<PlatformVerdict> verdicts;
  for (const auto& [platform, flops] : compute) {
    PlatformVerdict v;
    v.platform = platform;
    v.ranked_flops = flops;
    v.meets_all = true;
    verdicts.push_back(v);
  }
  if (!verdicts.empty())
    std::max_element(verdicts.begin(), verdicts.end(), [](const PlatformVerdict& a, const PlatformVerdict& b) {
      return a.ranked_flops < b.ranked_flops;
    })->recommended = true;
  return verdicts;
}

}  // namespace bs::test
