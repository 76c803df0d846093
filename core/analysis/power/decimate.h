// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Min/max decimation for drawing long traces: a 10-million-sample power log becomes at most two points per pixel
// column of the visible time range, the column's minimum and maximum in time order, so a line through them covers
// exactly the vertical extent the full trace would cover in that column (no spike is lost, none is invented).
#include <cstddef>
#include <span>
#include <vector>

namespace bs {

struct DecimatedSeries {
  std::vector<double> t;  // time, non-decreasing
  std::vector<double> v;  // value at that time
};

// Samples (t[i], v[i]) with t non-decreasing, viewed over [t_lo, t_hi] split into `columns` equal columns.
// Column c holds t_lo + c w <= t < t_lo + (c + 1) w (the last one also t == t_hi), w = (t_hi - t_lo) / columns.
// When the range holds at most 2 x columns samples they are returned as they are; otherwise each non-empty
// column gives its min and max sample (one point when they coincide). The nearest sample outside each end of the
// range is kept too, so the line enters and leaves the view where the data goes. NaN values are skipped.
// Throws std::invalid_argument for t and v of different lengths, columns == 0 or t_hi < t_lo.
DecimatedSeries decimate_min_max(std::span<const double> t, std::span<const double> v, double t_lo, double t_hi,
                                 std::size_t columns);

}  // namespace bs
