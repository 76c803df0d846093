// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/frames/synthetic.h"

#include <cmath>

namespace bs::vision {

cv::Vec3d chart_colour(double y, double z) {
  const auto near = [](double v, double at, double width) { return std::abs(v - at) < width; };
  const auto on_line = [&](double width) {
    return near(y, 0.5, width) || near(y, -0.5, width) || near(z, 0.4, width) || near(z, -0.4, width);
  };
  if (on_line(0.01)) return {0.05, 0.05, 0.05};
  // A light quiet zone on both sides, so a line's position can be measured without the checkerboard's edges.
  if (on_line(0.06)) return {0.9, 0.9, 0.9};
  // Colour patches in the middle, a checkerboard around them.
  if (std::abs(y) < 0.3 && std::abs(z) < 0.2) {
    const int patch = static_cast<int>(std::floor((y + 0.3) / 0.1)) + 6 * static_cast<int>(std::floor((z + 0.2) / 0.1));
    return {0.2 + 0.12 * (patch % 6), 0.25 + 0.15 * (patch % 4), 0.9 - 0.1 * (patch % 7)};
  }
  const bool dark = (static_cast<int>(std::floor(y / 0.25)) + static_cast<int>(std::floor(z / 0.25))) & 1;
  return dark ? cv::Vec3d(0.3, 0.35, 0.3) : cv::Vec3d(0.85, 0.85, 0.8);
}

std::optional<double> lens_theta(const Lens& lens, double radius_px) {
  const double max_theta = lens.fov_deg * 3.14159265358979323846 / 360.0;
  const auto rmax = lens.radius(max_theta);
  if (!rmax || radius_px > *rmax) return std::nullopt;
  double lo = 0, hi = max_theta;  // every model is monotonic on [0, fov/2]
  for (int i = 0; i < 60; ++i) {
    const double mid = (lo + hi) / 2;
    const auto r = lens.radius(mid);
    if (r && *r < radius_px)
      lo = mid;
    else
      hi = mid;
  }
  return (lo + hi) / 2;
}

cv::Mat render_fisheye(const Lens& lens, int bits) {
  lens.validate();
  const bool wide = bits > 8;
  const double scale = wide ? (1 << bits) - 1 : 255.0;
  cv::Mat out(lens.height, lens.width, wide ? CV_16UC3 : CV_8UC3);
  const cv::Point2d c = lens.centre();
#pragma omp parallel for schedule(dynamic, 8)
  for (int row = 0; row < lens.height; ++row) {
    for (int col = 0; col < lens.width; ++col) {
      cv::Vec3d sum(0, 0, 0);
      for (int sub = 0; sub < 4; ++sub) {
        const double px = col - 0.25 + 0.5 * (sub & 1), py = row - 0.25 + 0.5 * (sub >> 1);
        const double dx = px - c.x, dz = c.y - py;  // screen +z up
        const double r = std::hypot(dx, dz);
        const auto theta = lens_theta(lens, r);
        if (!theta) continue;
        const double vx = std::cos(*theta), s = std::sin(*theta);
        if (vx < 0.05) continue;  // the ray misses the chart
        const double vy = r > 0 ? s * dx / r : 0, vz = r > 0 ? s * dz / r : 0;
        sum += chart_colour(vy / vx, vz / vx);
      }
      const cv::Vec3d v = sum * (scale / 4);
      if (wide)
        out.at<cv::Vec3w>(row, col) =
            cv::Vec3w(static_cast<std::uint16_t>(std::lround(v[0])), static_cast<std::uint16_t>(std::lround(v[1])),
                      static_cast<std::uint16_t>(std::lround(v[2])));
      else
        out.at<cv::Vec3b>(row, col) =
            cv::Vec3b(static_cast<std::uint8_t>(std::lround(v[0])), static_cast<std::uint8_t>(std::lround(v[1])),
                      static_cast<std::uint8_t>(std::lround(v[2])));
    }
  }
  return out;
}

}  // namespace bs::vision
