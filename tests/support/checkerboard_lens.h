// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The lens the checkerboard-calibration tests render their boards through and then recover: one definition for
// the core test (1280x1024) and the dialog's test (the same lens on a 640x512 sensor).
#include "vision/lens/lens.h"

namespace bs::test {

// A 190 degree Kannala-Brandt lens, 360 px per radian on a 1280 px wide sensor (fewer on a narrower one, so the
// image circle fills the sensor alike), its principal point at (cx, cy): off the centre, as a real one is.
inline vision::Lens checkerboard_truth_lens(int width, int height, double cx, double cy) {
  vision::Lens l;
  l.type = vision::LensType::KannalaBrandt;
  l.width = width;
  l.height = height;
  l.r_pp = 1.0 / (360.0 * width / 1280);
  l.k = {0.02, -0.004, 0.0005, 0};
  l.cx = cx;
  l.cy = cy;
  l.fov_deg = 190;
  return l;
}

}  // namespace bs::test
