// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Regression compare: the same measures in two result collections (two workspaces, or a baseline and a new build),
// each change tested for significance over the repetitions. A regression is a change in the bad direction that is
// both larger than the threshold and significant (Mann-Whitney U, p < alpha): a large change with too few
// repetitions to tell it from noise is reported, not flagged.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "analysis/stats/mann_whitney.h"
#include "analysis/stats/stats.h"
#include "model/flops_run.h"

namespace bs {

enum class CompareVerdict {
  Unchanged,       // within the threshold
  Regression,      // worse beyond the threshold, significant
  Improvement,     // better beyond the threshold, significant
  NotSignificant,  // beyond the threshold but not significant (too few repetitions or too much noise)
  Changed,         // beyond the threshold, significant, but the measure has no better direction (unknown unit)
  OnlyInA,
  OnlyInB,
};
std::string_view to_string(CompareVerdict v);

struct MeasureComparison {
  std::string key;      // what is compared: "NUC | NUC GPU | OpenCL | paper | D=4 | W=2048"
  std::string measure;  // "FLOPS", or a Google Benchmark / clpeak metric
  std::string unit;
  std::optional<bool> higher_is_better;  // unknown for dimensionless or unknown units
  Summary a, b;
  double change = 0;  // (mean_b - mean_a) / mean_a
  MannWhitney test;
  CompareVerdict verdict = CompareVerdict::Unchanged;
};

struct CompareOptions {
  double threshold = 0.05;   // relative change that matters
  double alpha = 0.05;       // significance level
  bool every_point = false;  // FLOPS runs: compare every common worker count, not only A's peak
};

struct CompareInput {
  std::span<const FlopsRun> runs;
  std::span<const ResultSet> result_sets;
};

// Rows sorted by key then measure. FLOPS runs are matched on (platform, device, backend, variant, D, N) and, by
// default, compared at A's peak worker count (FLOPS per repetition, 6DNW/t); result-set measurements on
// (platform, device, backend, name, metric).
std::vector<MeasureComparison> compare_results(const CompareInput& a, const CompareInput& b,
                                               const CompareOptions& options = {});

// Which way is better for a unit: seconds (and ms, us, ns) lower; rates (FLOP/s, B/s, 1/s) higher.
std::optional<bool> higher_is_better_for_unit(std::string_view unit);

}  // namespace bs
