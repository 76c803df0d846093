// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Exact linear-interpolated percentiles by selection instead of a full sort: a 100-million-sample log needs four
// percentiles, not its whole order. std::nth_element finds the k-th smallest value in linear time, and the value
// after it is the smallest of the part above it, so the result is bit-identical to sorting and reading
// sorted[lo] + (sorted[hi] - sorted[lo]) * frac (analysis/power.h's rule).
#include <span>
#include <vector>

namespace bs {

// `values` holds present samples only (no NaN) and is reordered. `qs` in [0, 100]; ascending ones reuse the previous
// selection. One result per q; all 0 when `values` is empty.
std::vector<double> select_percentiles(std::vector<double>& values, std::span<const double> qs);

}  // namespace bs
