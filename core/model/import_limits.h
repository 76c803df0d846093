// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Documented limits on untrusted input: the importers apply them to files, the workspace reader to what it reads
// back from a workspace (which anyone may have edited), so both refuse the same sizes before allocating.
#include <cstddef>

namespace bs {

// Documented limits that bound what an untrusted file can make us allocate or recurse into.
struct ImportLimits {
  std::size_t max_json_bytes = std::size_t{256} << 20;  // whole-document formats (JSON, clpeak text)
  std::size_t max_json_depth = 64;
  std::size_t max_samples = 10'000'000;  // total timing values in one file
  // Rows of a streamed meter CSV (power_csv): a 4 kS/s meter over 7 hours is 100 million; 250 million rows of
  // time + one channel are 4 GB of samples, the most this 24 GB class of machine imports with room to spare.
  std::size_t max_power_rows = 250'000'000;
  // Values (numbers, strings, ...) in one JSON document: each costs 16+ bytes in the parsed tree, so this bounds
  // the tree at about half a GiB whatever the bytes are.
  std::size_t max_json_values = 32'000'000;
  // Frames: pixels in one image (64 Mpx, 8192 x 8192; the paper's camera has 1.3 Mpx) and the longest side. A
  // header or sidecar claiming more is rejected before anything is allocated.
  std::size_t max_frame_pixels = std::size_t{64} << 20;
  int max_frame_side = 65535;
};

}  // namespace bs
