// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// GFLOPS/W per platform: each platform's highest FLOPS peak (any device/backend; the paper uses each platform's
// GPU peak, which is its highest) paired with the current log of the same platform name. One row feeds both
// `benchscope-cli efficiency` and the GUI's Efficiency tab, so the two always show the same numbers.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "analysis/peaks/flops.h"
#include "analysis/platform/efficiency.h"
#include "analysis/stats/stats.h"
#include "model/power_trace.h"

namespace bs {

struct PlatformEfficiency {
  PeakRow peak;                           // the platform's best run: device, backend, D, peak FLOPS
  std::string trace_label;                // the current log used
  double supply_v = 0;                    // the log's (or the override's) supply voltage
  Summary current_a;                      // n, mean, SD, min, max of the supply current over the whole log
  Summary power_w;                        // the same for power
  double paper_gflops_per_w = 0;          // peak / (V x max current): the paper's figure
  double mean_power_gflops_per_w = 0;     // peak / mean power
  double joules_per_gflop = 0;            // mean power / (peak / 1e9)
  std::vector<EfficiencyFigure> figures;  // the same three, labelled (analysis/efficiency.h)
  std::string measurement;                // how the log was measured (measurement_text())
  // The peak's flags and the log's (check_power_trace_bundled()): a GFLOPS/W figure is as doubtful as either.
  std::vector<PlausibilityFlag> flags;
};

// Platforms in the order of their first current log; logs without a current channel or without a supply voltage
// (and no override), and platforms without runs, are left out. `supply_v` overrides every log's own voltage.
std::vector<PlatformEfficiency> platform_efficiency(std::span<const FlopsRun> runs, std::span<const PowerTrace> traces,
                                                    std::optional<double> supply_v = std::nullopt);

}  // namespace bs
