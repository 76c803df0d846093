// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

namespace bs::cli {

// `benchscope-cli bench vision`: demosaic + reprojection timings against OpenCV, measured in one process, then
// BenchScope's own demosaics against OpenCV's (bench_demosaic.h).
int bench_vision(const std::vector<std::string>& args, std::ostream& out);

}  // namespace bs::cli
