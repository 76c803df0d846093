// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/lens/view_geometry.h"

#include <algorithm>
#include <cmath>

#include "vision/frames/synthetic.h"

namespace bs::vision {
namespace {

constexpr double kPi = 3.14159265358979323846;
double rad(double deg) { return deg * kPi / 180.0; }

}  // namespace

std::optional<cv::Point2d> output_of(const Lens& lens, const View& view, double fx, double fy) {
  const cv::Point2d c = lens.centre();
  const double dx = fx - c.x, dz = c.y - fy;  // screen-centred, +y up
  const double r = std::hypot(dx, dz);
  const auto theta = lens_theta(lens, r);
  if (!theta) return std::nullopt;
  const double s = std::sin(*theta);
  const cv::Vec3d ray(std::cos(*theta), r > 0 ? s * dx / r : 0.0, r > 0 ? s * dz / r : 0.0);
  // The inverse of the rotation source_of() applies (lens.cpp): back into the view's frame.
  const cv::Vec3d u = view_rotation(view).t() * ray;
  if (u[0] <= 1e-12) return std::nullopt;  // behind the image plane
  const double f = view.focal_px();
  double x = f * u[1] / u[0] + (view.width - 1) / 2.0;
  double y = (view.height - 1) / 2.0 - f * u[2] / u[0];
  // Points on the border come back a rounding error outside it; 1e-6 px is far below anything visible.
  constexpr double eps = 1e-6;
  if (x < -eps || y < -eps || x > view.width - 1 + eps || y > view.height - 1 + eps) return std::nullopt;
  x = std::clamp(x, 0.0, view.width - 1.0);
  y = std::clamp(y, 0.0, view.height - 1.0);
  return cv::Point2d(x, y);
}

std::optional<LensCircle> image_circle(const Lens& lens) {
  const auto r = lens.radius(rad(lens.fov_deg) / 2);
  if (!r) return std::nullopt;
  return LensCircle{lens.centre(), *r};
}

std::vector<cv::Point2d> view_outline(const Lens& lens, const View& view, int per_edge) {
  std::vector<cv::Point2d> out;
  const double w = view.width - 1, h = view.height - 1;
  const cv::Point2d corners[] = {{0, 0}, {w, 0}, {w, h}, {0, h}};
  for (int e = 0; e < 4; ++e) {
    const cv::Point2d a = corners[e], b = corners[(e + 1) % 4];
    for (int i = 0; i < per_edge; ++i) {
      const double t = static_cast<double>(i) / per_edge;
      if (const auto s = source_of(lens, view, a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t)) out.push_back(*s);
    }
  }
  return out;
}

}  // namespace bs::vision
