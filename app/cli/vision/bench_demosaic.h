// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <iosfwd>

namespace bs::cli {

// The demosaic part of `bench vision`: BenchScope's bilinear and Malvar-He-Cutler demosaics against OpenCV's
// cvtColor bilinear on the same 1280x1024 mosaic, 8 and 16 bit, on 1 thread and on all of OpenCV's pool
// (`all_threads`), in blocks of frames of alternating order; per variant mean +- SD (n) of ms/frame, the ratio to
// OpenCV's time measured in the same minutes, and whether issue #21's targets are met (bilinear <= 1x,
// Malvar-He-Cutler <= 2x OpenCV's bilinear). `frames` is n per method and variant.
void print_demosaic_bench(std::ostream& out, int frames, int all_threads);

}  // namespace bs::cli
