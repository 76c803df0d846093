// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// benchscope-cli lens calibrate: checkerboard calibration (vision/checkerboard_calibration.h) into a lens file.
#include <ostream>
#include <string>
#include <vector>

namespace bs::cli {

int lens_calibrate(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace bs::cli
