// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Reading one camera frame (a Bayer mosaic) from disk for the pipeline: images OpenCV's imgcodecs reads (PNG, PGM,
// TIFF; single channel, 8 or 16 bit) or raw Bayer samples (.raw or .bin) with a JSON sidecar
//   {"width": W, "height": H, "pattern": "BGGR", "bit_depth": 1..16, "endianness": "little"|"big"}
// read by model/raw_sidecar.h, the same rules as the frame importer's (what `benchscope-cli synth-frame` writes).
// A sidecar without "pattern" leaves the caller's default. Kept small on purpose: the full frame importers live
// elsewhere.
#include <string>

#include <opencv2/core.hpp>

#include "vision/demosaic/bayer.h"

namespace bs::vision {

struct FrameFile {
  cv::Mat mosaic;  // CV_8UC1, or CV_16UC1 with values in the low `bit_depth` bits
  int bit_depth = 8;
  BayerPattern pattern = BayerPattern::BGGR;
  bool pattern_from_file = false;  // the sidecar named the pattern (images carry none)
};

// `path` ending in .raw/.bin needs a sidecar (find_raw_sidecar: the same path with .json instead, or path +
// ".json"). Throws
// std::runtime_error naming the file and what is wrong (missing sidecar, bad field, size mismatch, colour image).
// The raw file's size is checked against width x height x bytes per sample before anything is allocated.
FrameFile read_frame_file(const std::string& path, BayerPattern default_pattern = BayerPattern::BGGR);

// 16-bit samples of `bit_depth` bits scaled to 8 bits (the pipeline's stages work on 8-bit mosaics).
cv::Mat to_8bit(const cv::Mat& mosaic, int bit_depth);

}  // namespace bs::vision
