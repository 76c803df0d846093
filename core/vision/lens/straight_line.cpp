// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/lens/straight_line.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace bs::vision {

LineResidual line_residual(const std::vector<cv::Point2d>& points) {
  if (points.size() < 3) throw std::invalid_argument("a straight-line residual needs at least 3 points");
  const double n = static_cast<double>(points.size());
  cv::Point2d m(0, 0);
  for (const auto& p : points) m += p;
  m *= 1.0 / n;
  double sxx = 0, syy = 0, sxy = 0;
  for (const auto& p : points) {
    const cv::Point2d d = p - m;
    sxx += d.x * d.x;
    syy += d.y * d.y;
    sxy += d.x * d.y;
  }
  if (sxx + syy < 1e-18) throw std::invalid_argument("the points of a straight-line residual must not coincide");
  // Direction of the largest eigenvector of the 2x2 scatter matrix.
  const double angle = 0.5 * std::atan2(2 * sxy, sxx - syy);
  const cv::Point2d dir(std::cos(angle), std::sin(angle));
  LineResidual r;
  double ss = 0;
  for (const auto& p : points) {
    const cv::Point2d d = p - m;
    const double dist = std::abs(d.x * dir.y - d.y * dir.x);
    ss += dist * dist;
    r.max_px = std::max(r.max_px, dist);
  }
  r.rms_px = std::sqrt(ss / n);
  r.points = static_cast<int>(points.size());
  r.point = m;
  r.direction = dir;
  return r;
}

}  // namespace bs::vision
