// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/reproject/preprocess.h"

#include <memory>
#include <stdexcept>
#include <string>

#include "vision/reproject/fused.h"

namespace bs::vision {

std::string_view to_string(PreprocessPath p) { return p == PreprocessPath::Fused ? "fused" : "separate"; }

PreprocessPath preprocess_path_from_string(std::string_view s) {
  if (s == "fused") return PreprocessPath::Fused;
  if (s == "separate") return PreprocessPath::Separate;
  throw std::invalid_argument("unknown preprocessing path '" + std::string(s) + "' (fused or separate)");
}

Preprocessor make_preprocessor(const Lens& lens, const View& view, BayerPattern pattern, DemosaicMethod method,
                               PreprocessPath path) {
  lens.validate();
  view.validate();
  if (path == PreprocessPath::Fused) {
    if (method != DemosaicMethod::Bilinear)
      throw std::invalid_argument("the fused path demosaics bilinearly; use --path separate for " +
                                  std::string(to_string(method)));
    auto table = std::make_shared<const FusedTable>(build_reprojection_map(lens, view),
                                                    cv::Size(lens.width, lens.height), pattern);
    return [table](const cv::Mat& mosaic) {
      cv::Mat out;
      table->run(mosaic, out);
      return out;
    };
  }
  auto lut = std::make_shared<const ReprojectionLut>(lens, view);
  return [lut, pattern, method](const cv::Mat& mosaic) { return lut->apply(demosaic(mosaic, pattern, method)); };
}

}  // namespace bs::vision
