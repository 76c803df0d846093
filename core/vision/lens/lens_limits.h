// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where a calibrated lens may be trusted (issue #43.8). A checkerboard fit is measured only as far off the axis as
// the corners were seen, and its field-of-view circle is a prediction that the image's own rim can contradict:
//  - a view reaching further off the axis than the corners did uses the model beyond its data, which is said;
//  - a fitted circle (the lens's FOV/2 ray) farther from the detected rim than their uncertainties allow is said,
//    with both circles' numbers (on main a 195-degree fit at 663-674 px against a 620 px rim went unsaid).
#include <optional>
#include <string>

#include "vision/lens/circle_detect.h"
#include "vision/lens/lens.h"

namespace bs::vision {

// The largest angle off the lens axis (degrees) at which the view's output image takes its colour: the border of
// the output image mapped through the view's rotation, capped at the lens's FOV/2 (beyond it there is no source).
double view_reach_deg(const Lens& lens, const View& view);

// "This view reaches 90° off the axis, the checkerboard's corners covered 57°: beyond 57° the lens is
// extrapolated". Empty when the lens records no covered angle or the view stays within it (0.5° slack).
std::string extrapolation_note(const Lens& lens, const View& view);

// How a lens's field-of-view circle compares with a detected image rim.
struct RimComparison {
  double fitted_radius_px = 0, rim_radius_px = 0;
  cv::Point2d fitted_centre, rim_centre;
  double radius_gap_px = 0, centre_gap_px = 0;
  double tolerance_px = 0;  // 3 x the combined standard errors (the lens's, and the rim fit's), at least 1 px
  bool disagrees = false;
  std::string text;  // both circles with their numbers, and what to do; empty when they agree
};
// nullopt when the lens has no circle at its FOV (the model folds back before it). `lens_se_px` overrides the
// lens's own calibration.rim_radius_se_px (0 when it has none).
std::optional<RimComparison> compare_with_rim(const Lens& lens, const ImageCircle& rim,
                                              std::optional<double> lens_se_px = std::nullopt);

}  // namespace bs::vision
