// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

namespace bs::cli {

// `benchscope-cli bench tuner`: parameter change -> new reprojected frame, coarse-grid map vs exact map.
int bench_tuner(const std::vector<std::string>& args, std::ostream& out);

}  // namespace bs::cli
