// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// synth-frame --scene checkerboard: views of a calibration board at given poses through a lens, with the ground
// truth (lens, board, poses) beside them, for checkerboard calibration (lens calibrate) and its tests.
#include <ostream>

#include "common/args.h"
#include "vision/lens/lens.h"

namespace bs::cli {

// The options synth-frame accepts for this scene (besides --out, --lens, --size, --bits).
inline const std::set<std::string> kCheckerboardSceneOptions = {"--board", "--square", "--pose",        "--poses",
                                                                "--noise", "--blur",   "--supersample", "--seed"};

int synth_checkerboard(const ParsedArgs& args, const vision::Lens& lens, const vision::View& view,
                       const std::string& prefix, int bits, std::ostream& out);

}  // namespace bs::cli
