// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The sustained run most tests start from: `benchscope-cli sustain` under the flops load, its rate in GFLOPS, sampled
// every `interval_s`. The test adds the series it checks (times, rates, clocks, temperatures).
#include <string>
#include <utility>

#include "model/sustain_run.h"

namespace bs::test {

inline SustainRun sustained_flops_run(std::string platform, std::string label, double interval_s = 1) {
  SustainRun r;
  r.platform = std::move(platform);
  r.label = std::move(label);
  r.load = "flops";
  r.rate_unit = "GFLOPS";
  r.interval_s = interval_s;
  return r;
}

}  // namespace bs::test
