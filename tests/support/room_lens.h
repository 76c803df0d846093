// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The lens the line-fit and edge-proposal tests render the synthetic room through (vision/synthetic_room.h), and
// the start a circle fit gives them: one definition for the core and widget tests that recover it.
#include "vision/lens/lens.h"

namespace bs::test {

// Kannala-Brandt, 195 degrees, rim radius 600 px about (652.3, 498.7).
inline vision::Lens room_truth_lens() {
  constexpr double kPi = 3.14159265358979323846;
  vision::Lens l;
  l.type = vision::LensType::KannalaBrandt;
  l.fov_deg = 195;
  l.k = {0.06, -0.02, 0.003, 0};
  l.cx = 652.3;
  l.cy = 498.7;
  l.r_pp = 1;
  l.r_pp = *l.radius(195 * kPi / 360) / 600;  // rim radius 600 px
  return l;
}

// What the circle fit gives to start from: equidistant with the right rim, the centre (dx, dy) px off.
inline vision::Lens circle_fit_start(const vision::Lens& truth, double dx, double dy) {
  constexpr double kPi = 3.14159265358979323846;
  vision::Lens s = truth;
  s.type = vision::LensType::Equidistant;
  s.k = {};
  s.r_pp = (truth.fov_deg * kPi / 360) / *truth.radius(truth.fov_deg * kPi / 360);
  s.cx += dx;
  s.cy += dy;
  return s;
}

}  // namespace bs::test
