// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The paper's lens on a smaller sensor: `width` x `height` pixels, its 195-degree image circle across the width as on
// the paper's 1280-pixel camera. The same distortion with a fraction of the pixels, so a test reprojects quickly.
#include "vision/lens/lens.h"

namespace bs::test {

inline vision::Lens small_paper_lens(int width, int height) {
  constexpr double kPi = 3.14159265358979323846;
  vision::Lens lens = vision::Lens::paper();
  lens.width = width;
  lens.height = height;
  lens.r_pp = 195 * kPi / 180 / width;
  return lens;
}

}  // namespace bs::test
