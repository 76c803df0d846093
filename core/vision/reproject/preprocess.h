// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The preprocessing stage of the pipeline, built once per lens/view: either the fused path (bilinear demosaic of
// only the taps each output pixel samples, one pass) or demosaic (any method) followed by the reprojection LUT.
#include <string_view>

#include "vision/demosaic/bayer.h"
#include "vision/lens/lens.h"
#include "vision/pipeline/pipeline.h"

namespace bs::vision {

enum class PreprocessPath { Fused, Separate };
std::string_view to_string(PreprocessPath p);
PreprocessPath preprocess_path_from_string(std::string_view s);  // "fused", "separate"; throws std::invalid_argument

// Throws std::invalid_argument for an invalid lens/view or a fused path with a method other than bilinear.
Preprocessor make_preprocessor(const Lens& lens, const View& view, BayerPattern pattern, DemosaicMethod method,
                               PreprocessPath path);

}  // namespace bs::vision
