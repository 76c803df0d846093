// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/lens/circle_detect.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "vision/lens/stretch_8bit.h"

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

// The circle through three points; nullopt when they are (nearly) collinear.
std::optional<Fit> circle_through(const cv::Point2d& p, const cv::Point2d& q, const cv::Point2d& s) {
  const double d = 2 * (p.x * (q.y - s.y) + q.x * (s.y - p.y) + s.x * (p.y - q.y));
  if (std::abs(d) < 1e-9) return std::nullopt;
  const double pp = p.dot(p), qq = q.dot(q), ss = s.dot(s);
  const double a = (pp * (q.y - s.y) + qq * (s.y - p.y) + ss * (p.y - q.y)) / d;
  const double b = (pp * (s.x - q.x) + qq * (p.x - s.x) + ss * (q.x - p.x)) / d;
  return Fit{a, b, std::hypot(p.x - a, p.y - b)};
}

double distance_to(const Fit& f, const cv::Point2d& p) { return std::abs(std::hypot(p.x - f.a, p.y - f.b) - f.r); }

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  const auto k = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

// Stage 1: threshold, largest region, its outer contour off the image border, circle fit with outliers dropped.
std::optional<Fit> coarse_circle(const cv::Mat& gray, double min_level) {
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
  // Close dark scene content inside the disc (dark objects, chart lines) so the outer contour is mostly the circle.
  cv::morphologyEx(bin, bin, cv::MORPH_CLOSE, cv::getStructuringElement(cv::MORPH_ELLIPSE, {9, 9}));
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(bin, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  if (contours.empty()) return std::nullopt;
  const auto largest = std::max_element(contours.begin(), contours.end(), [](const auto& a, const auto& b) {
    return cv::contourArea(a) < cv::contourArea(b);
  });
  if (cv::contourArea(*largest) < 0.01 * static_cast<double>(gray.total())) return std::nullopt;
  std::vector<cv::Point2d> pts;
  for (const auto& p : *largest)
    if (p.x > 1 && p.y > 1 && p.x < gray.cols - 2 && p.y < gray.rows - 2) pts.emplace_back(p.x, p.y);
  auto fit = algebraic_fit(pts);
  if (!fit) return std::nullopt;
  Fit f = geometric_fit(pts, *fit);
  std::vector<cv::Point2d> kept;
  for (const auto& p : pts)
    if (distance_to(f, p) < 3) kept.push_back(p);
  if (kept.size() < 20) return std::nullopt;
  return geometric_fit(kept, f);
}

// Bilinear sample of a CV_32F image (the caller keeps (x, y) at least one pixel inside).
float sample(const cv::Mat& img, double x, double y) {
  const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
  const float fx = static_cast<float>(x - x0), fy = static_cast<float>(y - y0);
  const float* r0 = img.ptr<float>(y0);
  const float* r1 = img.ptr<float>(y0 + 1);
  return (r0[x0] * (1 - fx) + r0[x0 + 1] * fx) * (1 - fy) + (r1[x0] * (1 - fx) + r1[x0 + 1] * fx) * fy;
}

// Stage 2a: rim points along rays from `start`'s centre in `unit` (gray, CV_32F, 0..1, lightly blurred).
std::vector<cv::Point2d> rim_points(const cv::Mat& unit, const Fit& start) {
  constexpr int kRays = 720;
  constexpr double kStep = 0.25, kMargin = 2.0, kOuter = 3.0;  // px; kOuter: the stretch that must be dark
  const double W = unit.cols, H = unit.rows;
  if (start.a < kMargin || start.b < kMargin || start.a > W - 1 - kMargin || start.b > H - 1 - kMargin) return {};
  struct Ray {
    cv::Point2d dir;
    double r0;
    std::vector<float> s;
    double outer_mean = 0;
  };
  std::vector<Ray> rays(kRays);
  for (int k = 0; k < kRays; ++k) {
    Ray& ray = rays[static_cast<std::size_t>(k)];
    const double phi = 2 * 3.14159265358979323846 * k / kRays;
    ray.dir = {std::cos(phi), std::sin(phi)};
    // Distance along the ray to the sensor's border (less the margin).
    double exit = 1e9;
    if (ray.dir.x > 1e-12) exit = std::min(exit, (W - 1 - kMargin - start.a) / ray.dir.x);
    if (ray.dir.x < -1e-12) exit = std::min(exit, (kMargin - start.a) / ray.dir.x);
    if (ray.dir.y > 1e-12) exit = std::min(exit, (H - 1 - kMargin - start.b) / ray.dir.y);
    if (ray.dir.y < -1e-12) exit = std::min(exit, (kMargin - start.b) / ray.dir.y);
    ray.r0 = std::max(2.0, 0.3 * start.r);
    const int n = static_cast<int>((exit - ray.r0) / kStep);
    if (n < 40) continue;
    ray.s.resize(static_cast<std::size_t>(n));
    for (int j = 0; j < n; ++j) {
      const double r = ray.r0 + j * kStep;
      ray.s[static_cast<std::size_t>(j)] = sample(unit, start.a + r * ray.dir.x, start.b + r * ray.dir.y);
    }
    const int outer = static_cast<int>(kOuter / kStep);
    double sum = 0;
    for (int j = n - outer; j < n; ++j) sum += ray.s[static_cast<std::size_t>(j)];
    ray.outer_mean = sum / outer;
  }
  // Dark level and noise from the rays' outer ends: at least a quarter of them end outside the circle on any
  // usable capture, so the lower quartile of their means is the dark level.
  std::vector<double> ends;
  for (const auto& r : rays)
    if (!r.s.empty()) ends.push_back(r.outer_mean);
  if (ends.size() < 20) return {};
  const double dark = percentile(ends, 0.25);
  double ss = 0;
  long long count = 0;
  for (const auto& r : rays) {
    if (r.s.empty() || r.outer_mean > dark + 0.02) continue;
    for (std::size_t j = r.s.size() - static_cast<std::size_t>(kOuter / kStep); j < r.s.size(); ++j) {
      ss += (r.s[j] - r.outer_mean) * (r.s[j] - r.outer_mean);
      ++count;
    }
  }
  const double sigma = count > 1 ? std::sqrt(ss / static_cast<double>(count - 1)) : 0.0;
  const double lit = dark + std::max(0.05, 8 * sigma);  // a sample above this is inside the circle
  std::vector<cv::Point2d> pts;
  for (const auto& ray : rays) {
    if (ray.s.empty() || ray.outer_mean > dark + std::max(0.02, 4 * sigma)) continue;  // left the sensor while lit
    const int n = static_cast<int>(ray.s.size());
    const auto at = [&](int j) { return static_cast<double>(ray.s[static_cast<std::size_t>(j)]); };
    // Outermost run of three lit samples.
    int j = n - 1;
    while (j >= 2 && !(at(j) > lit && at(j - 1) > lit && at(j - 2) > lit)) --j;
    if (j < 2) continue;
    // The local lit level: the brightest sample up to 4 px inside; the edge is the half-way crossing outward of it.
    int jm = j;
    for (int i = j; i >= std::max(0, j - static_cast<int>(4 / kStep)); --i)
      if (at(i) > at(jm)) jm = i;
    const double half = (at(jm) + dark) / 2;
    if (at(jm) - dark < std::max(0.05, 10 * sigma)) continue;
    int e = jm;
    while (e + 1 < n && at(e + 1) >= half) ++e;
    if (e + 1 >= n || (n - 1 - e) * kStep < kOuter) continue;  // no dark stretch beyond the edge
    const double t = (at(e) - half) / (at(e) - at(e + 1));
    const double r = ray.r0 + (e + t) * kStep;
    pts.emplace_back(start.a + r * ray.dir.x, start.b + r * ray.dir.y);
  }
  return pts;
}

struct RobustFit {
  Fit fit;
  std::vector<cv::Point2d> inliers;
};

// Stage 2b: RANSAC over 3-point circles, then Gauss-Newton over the inliers with a tightened threshold.
std::optional<RobustFit> robust_fit(const std::vector<cv::Point2d>& pts, double max_radius) {
  if (pts.size() < 12) return std::nullopt;
  constexpr double kInlier = 1.0;  // px
  cv::RNG rng(0x5eedULL);          // fixed: the same image always gives the same circle
  const int n = static_cast<int>(pts.size());
  std::optional<Fit> best;
  int best_count = 0;
  for (int it = 0; it < 600; ++it) {
    const int i = rng.uniform(0, n), j = rng.uniform(0, n), k = rng.uniform(0, n);
    if (i == j || j == k || i == k) continue;
    const auto c = circle_through(pts[static_cast<std::size_t>(i)], pts[static_cast<std::size_t>(j)],
                                  pts[static_cast<std::size_t>(k)]);
    if (!c || c->r < 5 || c->r > max_radius) continue;
    int count = 0;
    for (const auto& p : pts) count += distance_to(*c, p) < kInlier;
    if (count > best_count) best_count = count, best = c;
  }
  if (!best || best_count < 10) return std::nullopt;
  Fit f = *best;
  std::vector<cv::Point2d> in;
  for (double threshold : {kInlier, kInlier, 0.0}) {
    if (threshold == 0) {
      // Last round: 3 robust standard deviations (MAD), between 0.3 and 1 px.
      std::vector<double> d;
      for (const auto& p : in) d.push_back(distance_to(f, p));
      threshold = std::clamp(3 * 1.4826 * percentile(d, 0.5), 0.3, kInlier);
    }
    in.clear();
    for (const auto& p : pts)
      if (distance_to(f, p) < threshold) in.push_back(p);
    if (in.size() < 10) return std::nullopt;
    f = geometric_fit(in, f);
  }
  return RobustFit{f, in};
}

}  // namespace

std::optional<ImageCircle> detect_image_circle(const cv::Mat& image, double min_level) {
  if (image.empty()) return std::nullopt;
  cv::Mat gray;
  if (image.channels() == 3)
    cv::cvtColor(image, gray, cv::COLOR_BGR2GRAY);
  else if (image.channels() == 1)
    gray = image;
  else
    return std::nullopt;
  if (gray.depth() != CV_8U && gray.depth() != CV_16U) return std::nullopt;
  const auto coarse = coarse_circle(stretch_to_8bit(gray), min_level);  // its threshold takes 8-bit
  if (!coarse) return std::nullopt;
  // 0..1 by the brightest pixel, so 8-bit, 16-bit and 10/12 bits in 16 behave alike; a light blur (sigma 1 px)
  // keeps noise from firing the lit/dark tests and leaves a blurred step's half-way point where it was.
  cv::Mat unit;
  double mx = 0;
  cv::minMaxLoc(gray, nullptr, &mx);
  gray.convertTo(unit, CV_32F, mx > 0 ? 1.0 / mx : 1.0);
  cv::GaussianBlur(unit, unit, {5, 5}, 1.0);
  Fit f = *coarse;
  std::optional<RobustFit> robust;
  std::size_t rays = 0;
  const double max_radius = 2 * std::hypot(gray.cols, gray.rows);
  for (int pass = 0; pass < 2; ++pass) {  // the second pass casts its rays from the better centre
    const auto pts = rim_points(unit, f);
    auto r = robust_fit(pts, max_radius);
    if (!r) break;
    robust = std::move(r);
    rays = pts.size();
    f = robust->fit;
  }
  if (!robust) return std::nullopt;
  double ss = 0;
  for (const auto& p : robust->inliers) ss += std::pow(distance_to(f, p), 2);
  ImageCircle c;
  c.centre = {f.a, f.b};
  c.radius = f.r;
  c.rms_px = std::sqrt(ss / static_cast<double>(robust->inliers.size()));
  c.edge_points = static_cast<int>(robust->inliers.size());
  c.rays = static_cast<int>(rays);
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
  out.calibration = {};
  out.calibration.method = LensCalibration::Method::CircleFit;
  out.calibration.rms_px = circle.rms_px;
  char detail[160];
  std::snprintf(detail, sizeof detail, "image circle r %.2f px at (%.2f, %.2f) px from %d rim points, FOV %.1f deg",
                circle.radius, circle.centre.x, circle.centre.y, circle.edge_points,
                circle_fov_deg > 0 ? circle_fov_deg : lens.fov_deg);
  out.calibration.detail = detail;
  return out;
}

}  // namespace bs::vision
