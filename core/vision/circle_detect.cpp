// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/circle_detect.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

namespace bs::vision {
namespace {

struct Fit {
  double a, b, r;
};

// Kasa's algebraic fit: x^2 + y^2 + D x + E y + F = 0 in least squares; a good start for the geometric fit.
std::optional<Fit> algebraic_fit(const std::vector<cv::Point2d>& pts) {
  if (pts.size() < 3) return std::nullopt;
  cv::Mat A(static_cast<int>(pts.size()), 3, CV_64F), b(static_cast<int>(pts.size()), 1, CV_64F);
  for (int i = 0; i < A.rows; ++i) {
    const auto& p = pts[static_cast<std::size_t>(i)];
    A.at<double>(i, 0) = p.x;
    A.at<double>(i, 1) = p.y;
    A.at<double>(i, 2) = 1;
    b.at<double>(i) = -(p.x * p.x + p.y * p.y);
  }
  cv::Mat s;
  if (!cv::solve(A, b, s, cv::DECOMP_SVD)) return std::nullopt;
  const double D = s.at<double>(0), E = s.at<double>(1), F = s.at<double>(2);
  const double a = -D / 2, bb = -E / 2, r2 = a * a + bb * bb - F;
  if (!(r2 > 0)) return std::nullopt;
  return Fit{a, bb, std::sqrt(r2)};
}

// Gauss-Newton on sum (|p - c| - r)^2.
Fit geometric_fit(const std::vector<cv::Point2d>& pts, Fit f) {
  for (int it = 0; it < 20; ++it) {
    cv::Matx33d JtJ = cv::Matx33d::zeros();
    cv::Vec3d Jtr(0, 0, 0);
    for (const auto& p : pts) {
      const double dx = p.x - f.a, dy = p.y - f.b, d = std::hypot(dx, dy);
      if (d < 1e-9) continue;
      const cv::Vec3d J(-dx / d, -dy / d, -1);
      const double res = d - f.r;
      JtJ += J * J.t();
      Jtr += J * res;
    }
    cv::Vec3d delta;
    if (!cv::solve(JtJ, -Jtr, delta, cv::DECOMP_CHOLESKY)) break;
    f.a += delta[0];
    f.b += delta[1];
    f.r += delta[2];
    if (cv::norm(delta) < 1e-6) break;
  }
  return f;
}

}  // namespace

std::optional<ImageCircle> detect_image_circle(const cv::Mat& image, double min_level) {
  if (image.empty()) return std::nullopt;
  cv::Mat gray;
  if (image.channels() == 3) cv::cvtColor(image, gray, cv::COLOR_BGR2GRAY);
  else if (image.channels() == 1) gray = image;
  else return std::nullopt;
  if (gray.depth() == CV_16U) {
    double mx = 0;
    cv::minMaxLoc(gray, nullptr, &mx);
    gray.convertTo(gray, CV_8U, mx > 0 ? 255.0 / mx : 1.0);
  } else if (gray.depth() != CV_8U) {
    return std::nullopt;
  }
  // Bright level: the 95th percentile of the image, so a few saturated pixels do not set the threshold.
  int hist[256] = {};
  for (int y = 0; y < gray.rows; ++y) {
    const auto* row = gray.ptr<std::uint8_t>(y);
    for (int x = 0; x < gray.cols; ++x) ++hist[row[x]];
  }
  const long long total = static_cast<long long>(gray.total());
  long long acc = 0;
  int p95 = 255;
  for (int v = 0; v < 256; ++v) {
    acc += hist[v];
    if (acc >= total * 95 / 100) {
      p95 = v;
      break;
    }
  }
  const double level = std::max(min_level, 0.15 * p95);
  cv::Mat bin;
  cv::threshold(gray, bin, level, 255, cv::THRESH_BINARY);
  // Close dark scene content inside the disc (dark objects, chart lines) so the outer contour is the circle.
  cv::morphologyEx(bin, bin, cv::MORPH_CLOSE, cv::getStructuringElement(cv::MORPH_ELLIPSE, {9, 9}));
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(bin, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  if (contours.empty()) return std::nullopt;
  const auto largest = std::max_element(contours.begin(), contours.end(), [](const auto& a, const auto& b) {
    return cv::contourArea(a) < cv::contourArea(b);
  });
  if (cv::contourArea(*largest) < 0.01 * static_cast<double>(gray.total())) return std::nullopt;
  // Contour pixels are the outermost lit pixels; the edge lies a fraction of a pixel further out (0.25 px on
  // antialiased synthetic renders at this threshold), which the radius gets back below. Points on the image border are the sensor's edge, not the circle's.
  std::vector<cv::Point2d> pts;
  for (const auto& p : *largest)
    if (p.x > 1 && p.y > 1 && p.x < gray.cols - 2 && p.y < gray.rows - 2) pts.emplace_back(p.x, p.y);
  auto fit = algebraic_fit(pts);
  if (!fit) return std::nullopt;
  Fit f = geometric_fit(pts, *fit);
  // Drop outliers (closing artefacts, dark scene at the rim) and refit once.
  std::vector<cv::Point2d> kept;
  for (const auto& p : pts)
    if (std::abs(std::hypot(p.x - f.a, p.y - f.b) - f.r) < 3) kept.push_back(p);
  if (kept.size() < 20) return std::nullopt;
  f = geometric_fit(kept, f);
  double ss = 0;
  for (const auto& p : kept) ss += std::pow(std::hypot(p.x - f.a, p.y - f.b) - f.r, 2);
  ImageCircle c;
  c.centre = {f.a, f.b};
  c.radius = f.r + 0.25;
  c.rms_px = std::sqrt(ss / static_cast<double>(kept.size()));
  c.edge_points = static_cast<int>(kept.size());
  return c;
}

Lens propose_lens(const Lens& lens, const ImageCircle& circle, double circle_fov_deg) {
  Lens out = lens;
  out.cx = circle.centre.x;
  out.cy = circle.centre.y;
  // Every model's radius is proportional to the focal length 1/r_pp: solve r(fov/2) = radius for r_pp.
  constexpr double kPi = 3.14159265358979323846;
  Lens unit = lens;
  unit.r_pp = 1;
  double theta = (circle_fov_deg > 0 ? circle_fov_deg : lens.fov_deg) * kPi / 360.0;
  if (lens.type == LensType::Orthographic) theta = std::min(theta, kPi / 2);
  if (lens.type == LensType::Rectilinear) theta = std::min(theta, kPi / 2 - 1e-3);
  const auto g = unit.radius(theta);
  if (g && *g > 0 && circle.radius > 0) out.r_pp = *g / circle.radius;
  return out;
}

}  // namespace bs::vision
