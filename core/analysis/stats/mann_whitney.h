// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Mann-Whitney U test (Wilcoxon rank-sum): do two sets of repeated measurements come from the same distribution?
// Benchmark timings are skewed and have outliers (a page fault, a context switch), so a rank test is the right
// default; it needs no normality and is insensitive to a single wild repetition.
#include <span>

namespace bs {

struct MannWhitney {
  double u = 0;        // U of the first sample: pairs (a, b) with a > b, ties counting 1/2
  double p_value = 1;  // two-sided
  bool exact = false;  // exact null distribution (small samples without ties) or normal approximation
};

// Exact when both samples are small (n_a + n_b <= 20) and there are no ties; otherwise the normal approximation
// with tie correction and continuity correction. p = 1 when either sample is empty.
MannWhitney mann_whitney_u(std::span<const double> a, std::span<const double> b);

}  // namespace bs
