// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/stats/order_stats.h"

#include <algorithm>

namespace bs {

std::vector<double> select_percentiles(std::vector<double>& values, std::span<const double> qs) {
  std::vector<double> out(qs.size(), 0.0);
  if (values.empty()) return out;
  const std::size_t n = values.size();
  std::size_t settled = 0;  // values[0, settled) are all <= values[settled, n) after the previous selection
  for (std::size_t i = 0; i < qs.size(); ++i) {
    const double pos = std::clamp(qs[i], 0.0, 100.0) / 100.0 * static_cast<double>(n - 1);
    const auto lo = static_cast<std::size_t>(pos);
    const auto first = values.begin() + static_cast<std::ptrdiff_t>(lo >= settled ? settled : 0);
    std::nth_element(first, values.begin() + static_cast<std::ptrdiff_t>(lo), values.end());
    const double at_lo = values[lo];
    // The next value in sorted order is the smallest of those after lo (nth_element put only larger ones there).
    const double at_hi =
        lo + 1 < n ? *std::min_element(values.begin() + static_cast<std::ptrdiff_t>(lo + 1), values.end()) : at_lo;
    out[i] = at_lo + (at_hi - at_lo) * (pos - static_cast<double>(lo));
    settled = lo;
  }
  return out;
}

}  // namespace bs
