// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

namespace bs::cli {

// `benchscope-cli bench range-stats`: the Power tab's per-update cost of a selection's statistics on a long trace
// (PowerIndex: prefix sums and a min/max sparse table) against a plain rescan of the same range.
int bench_range_stats(const std::vector<std::string>& args, std::ostream& out);

}  // namespace bs::cli
