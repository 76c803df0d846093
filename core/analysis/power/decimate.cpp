// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/power/decimate.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace bs {

DecimatedSeries decimate_min_max(std::span<const double> t, std::span<const double> v, double t_lo, double t_hi,
                                 std::size_t columns) {
  if (t.size() != v.size()) throw std::invalid_argument("decimate_min_max: time and value counts differ");
  if (columns == 0) throw std::invalid_argument("decimate_min_max: no columns");
  if (!(t_hi >= t_lo)) throw std::invalid_argument("decimate_min_max: range end before its start");
  DecimatedSeries out;
  const auto first = static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), t_lo) - t.begin());
  const auto last = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), t_hi) - t.begin());  // one past
  const auto push = [&](std::size_t i) {
    if (std::isnan(v[i])) return;
    out.t.push_back(t[i]);
    out.v.push_back(v[i]);
  };
  if (first > 0) push(first - 1);
  if (last - first <= 2 * columns) {
    for (std::size_t i = first; i < last; ++i) push(i);
  } else {
    out.t.reserve(2 * columns + 2);
    out.v.reserve(2 * columns + 2);
    const double width = (t_hi - t_lo) / static_cast<double>(columns);
    // Column of a sample: floor((t - t_lo) / w), the last column closed at t_hi. Monotone in t, so one pass.
    const auto column_of = [&](double ti) {
      if (!(width > 0)) return std::size_t{0};  // a zero-length range is one column
      return std::min(columns - 1, static_cast<std::size_t>((ti - t_lo) / width));
    };
    std::size_t i = first;
    while (i < last) {
      // The column's samples end where column_of first exceeds this one: a binary search per column rather than
      // a division per sample (10 M samples, ~1600 columns).
      const std::size_t c = column_of(t[i]);
      const auto end = static_cast<std::size_t>(std::partition_point(t.begin() + static_cast<std::ptrdiff_t>(i),
                                                                     t.begin() + static_cast<std::ptrdiff_t>(last),
                                                                     [&](double x) { return column_of(x) <= c; }) -
                                                t.begin());
      std::size_t k = i;
      while (k < end && std::isnan(v[k])) ++k;
      if (k < end) {
        // Comparisons with NaN are false, so NaN after the first number are passed over without a test.
        std::size_t i_min = k, i_max = k;
        double lo = v[k], hi = v[k];
        for (std::size_t j = k + 1; j < end; ++j) {
          if (v[j] < lo) lo = v[j], i_min = j;
          if (v[j] > hi) hi = v[j], i_max = j;
        }
        // In time order, so the line goes through both extremes of the column.
        if (i_min == i_max)
          push(i_min);
        else if (i_min < i_max)
          push(i_min), push(i_max);
        else
          push(i_max), push(i_min);
      }
      i = end;
    }
  }
  if (last < t.size()) push(last);
  return out;
}

}  // namespace bs
