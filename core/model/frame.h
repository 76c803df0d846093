// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One camera frame as imported: a Bayer mosaic (the paper's camera writes BGGR), a grey image or a colour image.
// Kept free of OpenCV so the model and the store build without it; core/vision/frames/frame_image.h turns it into a
// cv::Mat.
#include <cstdint>
#include <string>
#include <vector>

#include "model/provenance.h"

namespace bs {

// How the workspace keeps a frame: by reference (path + content hash; the file is read again on open and must
// still hash the same) or as a copy of the pixels inside the workspace file.
enum class FrameStorage { Reference, Copy };

struct Frame {
  std::string label;  // e.g. the file stem
  int width = 0;
  int height = 0;
  int channels = 1;           // 1: Bayer mosaic or grey; 3: colour, interleaved B, G, R (OpenCV's order)
  int bit_depth = 8;          // significant bits per sample (1..16); above 8 each sample takes two bytes
  std::string pattern;        // "BGGR", "RGGB", "GRBG", "GBRG" for a Bayer mosaic; empty for grey or colour
  bool synthetic = false;     // rendered (benchscope-cli synth-frame), not captured by a camera
  std::string lens_json;      // lens + view from the sidecar ("lens" object), empty when none was given
  std::string source_format;  // importer id, e.g. "raw-bayer", "pnm", "png", "tiff"
  std::string read_options;   // JSON the importer needs to read the file again (raw geometry), "{}" if none
  FrameStorage storage = FrameStorage::Reference;
  // Row-major samples; 16-bit samples (bit_depth > 8) in the host's byte order, values in the low bits.
  std::vector<std::uint8_t> pixels;
  Provenance provenance;

  int bytes_per_sample() const { return bit_depth > 8 ? 2 : 1; }
  std::size_t expected_bytes() const {
    return static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * static_cast<std::size_t>(channels) *
           static_cast<std::size_t>(bytes_per_sample());
  }
  bool is_mosaic() const { return channels == 1 && !pattern.empty(); }
};

}  // namespace bs
