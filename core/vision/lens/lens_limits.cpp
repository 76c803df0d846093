// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/lens/lens_limits.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "util/text.h"

namespace bs::vision {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Angle off the lens axis of output pixel (x, y), degrees (as source_of() computes it).
double angle_of(const View& view, const cv::Matx33d& rotation, double x, double y) {
  const double sx = x - (view.width - 1) / 2.0;
  const double sy = (view.height - 1) / 2.0 - y;
  cv::Vec3d v(view.focal_px(), sx, sy);
  v = rotation * (v / cv::norm(v));
  return std::acos(std::clamp(v[0], -1.0, 1.0)) * 180 / kPi;
}

}  // namespace

double view_reach_deg(const Lens& lens, const View& view) {
  // The angle off the axis has no maximum inside the image (the rays inside lie between those of the border), so
  // the border decides; 256 points per edge find its largest value to well under a tenth of a degree.
  const cv::Matx33d rotation = view_rotation(view);
  const double w = view.width - 1, h = view.height - 1;
  double reach = 0;
  constexpr int kSteps = 256;
  for (int i = 0; i <= kSteps; ++i) {
    const double t = static_cast<double>(i) / kSteps;
    for (const auto& [x, y] : {std::pair{t * w, 0.0}, std::pair{t * w, h}, std::pair{0.0, t * h}, std::pair{w, t * h}})
      reach = std::max(reach, angle_of(view, rotation, x, y));
  }
  return std::min(reach, lens.fov_deg / 2);
}

std::string extrapolation_note(const Lens& lens, const View& view) {
  if (!lens.calibration.covered_deg) return {};
  const double covered = *lens.calibration.covered_deg, reach = view_reach_deg(lens, view);
  if (reach <= covered + 0.5) return {};
  return "this view reaches " + format_number("%.0f", reach) +
         " degrees off the axis, the calibration's corners covered " + format_number("%.0f", covered) +
         " degrees: beyond " + format_number("%.0f", covered) +
         " degrees the lens model is extrapolated (calibrate with corners nearer the rim, or narrow the view)";
}

std::optional<RimComparison> compare_with_rim(const Lens& lens, const ImageCircle& rim,
                                              std::optional<double> lens_se_px) {
  const std::optional<double> r = lens.radius(lens.fov_deg / 2 * kPi / 180);
  if (!r) return std::nullopt;
  RimComparison c;
  c.fitted_radius_px = *r;
  c.fitted_centre = lens.centre();
  c.rim_radius_px = rim.radius;
  c.rim_centre = rim.centre;
  c.radius_gap_px = std::abs(c.fitted_radius_px - c.rim_radius_px);
  c.centre_gap_px = std::hypot(c.fitted_centre.x - c.rim_centre.x, c.fitted_centre.y - c.rim_centre.y);
  const double lens_se = lens_se_px.value_or(lens.calibration.rim_radius_se_px.value_or(0.0));
  // The rim fit's standard error: its points' scatter over the square root of their count.
  const double rim_se = rim.edge_points > 0 ? rim.rms_px / std::sqrt(static_cast<double>(rim.edge_points)) : rim.rms_px;
  c.tolerance_px = std::max(1.0, 3 * std::hypot(lens_se, rim_se));
  c.disagrees = c.radius_gap_px > c.tolerance_px || c.centre_gap_px > c.tolerance_px;
  if (!c.disagrees) return c;
  c.text = "the lens's " + format_number("%.0f", lens.fov_deg) + "-degree circle (radius " +
           format_number("%.1f", c.fitted_radius_px) + " px" +
           (lens_se > 0 ? " \xC2\xB1 " + format_number("%.1f", lens_se) : std::string()) + ", centre (" +
           format_number("%.1f", c.fitted_centre.x) + ", " + format_number("%.1f", c.fitted_centre.y) +
           ")) disagrees with the image's detected rim (radius " + format_number("%.1f", c.rim_radius_px) +
           " px \xC2\xB1 " + format_number("%.1f", rim_se) + ", centre (" + format_number("%.1f", c.rim_centre.x) +
           ", " + format_number("%.1f", c.rim_centre.y) + ")): " + format_number("%.1f", c.radius_gap_px) +
           " px in radius, centres " + format_number("%.1f", c.centre_gap_px) + " px apart, more than the " +
           format_number("%.1f", c.tolerance_px) +
           " px their uncertainties allow; the lens's field of view or its model beyond the corners is off (a "
           "circle fit to the rim gives the field of view the image shows)";
  return c;
}

}  // namespace bs::vision
