// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/lens/line_fit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "vision/lens/points_json.h"

namespace bs::vision {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Angle off the axis for a radius in pixels, not limited to the FOV; nullopt where the model has no inverse.
std::optional<double> theta_of_radius(const Lens& lens, double r) {
  const double t = r * lens.r_pp;  // radius in focal lengths
  switch (lens.type) {
    case LensType::Equidistant:
      return t;
    case LensType::Equisolid:
      if (t / 2 > 1) return std::nullopt;
      return 2 * std::asin(t / 2);
    case LensType::Stereographic:
      return 2 * std::atan(t / 2);
    case LensType::Orthographic:
      if (t > 1) return std::nullopt;
      return std::asin(t);
    case LensType::Rectilinear:
      return std::atan(t);
    case LensType::KannalaBrandt: {
      // Newton on theta (1 + k1 theta^2 + ... + k4 theta^8) = t, from theta = t; the polynomial must rise there.
      const auto& k = lens.k;
      double th = t;
      for (int i = 0; i < 40; ++i) {
        const double t2 = th * th;
        const double g = th * (1 + t2 * (k[0] + t2 * (k[1] + t2 * (k[2] + t2 * k[3])))) - t;
        const double dg = 1 + t2 * (3 * k[0] + t2 * (5 * k[1] + t2 * (7 * k[2] + t2 * 9 * k[3])));
        if (!(dg > 1e-6)) return std::nullopt;
        const double step = g / dg;
        th -= step;
        if (!(th >= 0 && th < kPi)) return std::nullopt;
        if (std::abs(step) < 1e-13) return th;
      }
      return std::nullopt;
    }
  }
  return std::nullopt;
}

// Kannala-Brandt radius at theta without the FOV limit of Lens::radius.
double kb_radius(const Lens& lens, double theta) {
  const double t2 = theta * theta;
  const auto& k = lens.k;
  return theta * (1 + t2 * (k[0] + t2 * (k[1] + t2 * (k[2] + t2 * k[3])))) / lens.r_pp;
}

// Signed distances in source pixels of every point from the image of its line's best plane through the centre
// (a great circle): the ray's distance n.v from the plane over the gradient of n.v with respect to the pixel, i.e.
// the first-order distance to the curve. Pixels, not angles: an angle cost would favour lenses that squeeze the
// rays (smaller angles for the same click noise), which the scale lines cannot see makes free to choose. False when
// a point has no ray. Lines with fewer than 3 points are skipped.
bool plane_distances(const Lens& lens, const std::vector<PickedLine>& lines, std::vector<double>& out,
                     std::string* error = nullptr) {
  out.clear();
  std::vector<cv::Vec3d> rays;
  for (std::size_t li = 0; li < lines.size(); ++li) {
    const auto& line = lines[li];
    if (line.size() < 3) continue;
    rays.clear();
    for (std::size_t pi = 0; pi < line.size(); ++pi) {
      const auto v = pixel_to_ray(lens, line[pi]);
      if (!v) {
        if (error)
          *error =
              "line " + std::to_string(li + 1) + ", point " + std::to_string(pi + 1) + ": the lens has no ray there";
        return false;
      }
      rays.push_back(*v);
    }
    cv::Matx33d m = cv::Matx33d::zeros();
    for (const auto& v : rays) m += v * v.t();
    cv::Mat values, vectors;
    cv::eigen(cv::Mat(m), values, vectors);  // descending: the last row is the plane's normal
    cv::Vec3d n(vectors.at<double>(2, 0), vectors.at<double>(2, 1), vectors.at<double>(2, 2));
    // A fixed orientation (from the first to the last point), so the residuals' signs do not flip between the
    // Jacobian's evaluations.
    if (n.dot(rays.front().cross(rays.back())) < 0) n = -n;
    constexpr double h = 1e-3;  // px, for the gradient
    for (std::size_t pi = 0; pi < line.size(); ++pi) {
      const auto vx = pixel_to_ray(lens, line[pi] + cv::Point2d(h, 0));
      const auto vy = pixel_to_ray(lens, line[pi] + cv::Point2d(0, h));
      if (!vx || !vy) return false;
      const double d = n.dot(rays[pi]);
      const double gx = (n.dot(*vx) - d) / h, gy = (n.dot(*vy) - d) / h;
      const double g = std::hypot(gx, gy);
      if (!(g > 1e-12)) return false;
      out.push_back(d / g);
    }
  }
  return true;
}

using Params = std::array<double, 7>;  // r_pp, cx, cy, k1..k4

Lens with_params(Lens lens, const Params& p) {
  lens.r_pp = p[0];
  lens.cx = p[1];
  lens.cy = p[2];
  for (int i = 0; i < 4; ++i) lens.k[static_cast<std::size_t>(i)] = p[static_cast<std::size_t>(3 + i)];
  return lens;
}

}  // namespace

std::array<bool, 7> fixed_parameters_from_string(const std::string& names) {
  std::array<bool, 7> fixed{};
  static const char* kNames[] = {"r_pp", "cx", "cy", "k1", "k2", "k3", "k4"};
  std::size_t pos = 0;
  while (pos <= names.size()) {
    const std::size_t comma = std::min(names.find(',', pos), names.size());
    const std::string name = names.substr(pos, comma - pos);
    pos = comma + 1;
    if (name.empty()) continue;
    if (name == "centre" || name == "center") {
      fixed[1] = fixed[2] = true;
      continue;
    }
    const auto it = std::find(std::begin(kNames), std::end(kNames), name);
    if (it == std::end(kNames))
      throw std::invalid_argument("unknown lens parameter '" + name + "' (r_pp, cx, cy, centre, k1, k2, k3, k4)");
    fixed[static_cast<std::size_t>(it - std::begin(kNames))] = true;
  }
  return fixed;
}

std::optional<cv::Vec3d> pixel_to_ray(const Lens& lens, const cv::Point2d& px) {
  const cv::Point2d c = lens.centre();
  const double dx = px.x - c.x, dz = c.y - px.y;  // screen +z up
  const double r = std::hypot(dx, dz);
  if (r < 1e-12) return cv::Vec3d(1, 0, 0);
  const auto theta = theta_of_radius(lens, r);
  if (!theta) return std::nullopt;
  const double s = std::sin(*theta);
  return cv::Vec3d(std::cos(*theta), s * dx / r, s * dz / r);
}

std::optional<cv::Point2d> view_pixel_of(const Lens& lens, const View& view, const cv::Point2d& source_px) {
  const auto v = pixel_to_ray(lens, source_px);
  if (!v) return std::nullopt;
  const cv::Vec3d o = view_rotation(view).t() * *v;  // lens rays -> the view's camera frame
  if (o[0] <= 1e-9) return std::nullopt;
  const double f = view.focal_px();
  return cv::Point2d((view.width - 1) / 2.0 + f * o[1] / o[0], (view.height - 1) / 2.0 - f * o[2] / o[0]);
}

Lens to_kannala_brandt(const Lens& lens) {
  if (lens.type == LensType::KannalaBrandt) return lens;
  Lens out = lens;
  out.type = LensType::KannalaBrandt;
  out.k = {};
  if (lens.type == LensType::Equidistant) return out;
  // r(theta) = a1 theta + a2 theta^3 + ... + a5 theta^9 in least squares over the FOV; r_pp = 1/a1, k = a/a1.
  const double top = std::min(lens.fov_deg * kPi / 360, lens.type == LensType::Rectilinear ? kPi / 2 - 0.05 : kPi);
  std::vector<std::array<double, 6>> rows;
  for (int i = 1; i <= 200; ++i) {
    const double th = top * i / 200.0;
    if (const auto r = lens.radius(th))
      rows.push_back({th, std::pow(th, 3), std::pow(th, 5), std::pow(th, 7), std::pow(th, 9), *r});
  }
  if (rows.size() < 10) return out;
  cv::Mat A(static_cast<int>(rows.size()), 5, CV_64F), b(static_cast<int>(rows.size()), 1, CV_64F), a;
  for (int i = 0; i < A.rows; ++i) {
    for (int j = 0; j < 5; ++j) A.at<double>(i, j) = rows[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
    b.at<double>(i) = rows[static_cast<std::size_t>(i)][5];
  }
  cv::solve(A, b, a, cv::DECOMP_SVD);
  const double a1 = a.at<double>(0);
  if (!(a1 > 0)) return out;
  out.r_pp = 1 / a1;
  for (int j = 0; j < 4; ++j) out.k[static_cast<std::size_t>(j)] = a.at<double>(j + 1) / a1;
  return out;
}

LineStraightness line_straightness(const Lens& lens, const std::vector<PickedLine>& lines) {
  std::vector<double> d;
  std::string error;
  if (!plane_distances(lens, lines, d, &error)) throw std::invalid_argument(error);
  if (d.empty()) throw std::invalid_argument("no line has 3 or more points");
  LineStraightness s;
  double ss = 0;
  for (double v : d) {
    ss += v * v;
    s.max_px = std::max(s.max_px, std::abs(v));
  }
  s.rms_px = std::sqrt(ss / static_cast<double>(d.size()));
  s.points = static_cast<int>(d.size());
  for (const auto& l : lines) s.lines += l.size() >= 3;
  return s;
}

namespace {

LineFitResult fit_once(const Lens& start_lens, const std::vector<PickedLine>& lines, const LineFitOptions& options) {
  int usable = 0;
  for (const auto& l : lines) usable += l.size() >= 3;
  if (usable < 3)
    throw std::invalid_argument("a line fit needs at least 3 lines of 3 or more points (got " + std::to_string(usable) +
                                ")");
  Lens start = to_kannala_brandt(start_lens);
  const cv::Point2d c0 = start.centre();
  start.cx = c0.x;
  start.cy = c0.y;
  const double theta_max = start.fov_deg * kPi / 360;
  const double rim = options.circle_radius_px > 0 ? options.circle_radius_px : kb_radius(start, theta_max);
  // 0.1 px of rim radius weighs as much as 1 px of line residual: the rim is measured far better than clicks are.
  constexpr double kRimWeight = 10;

  const auto residuals = [&](const Params& p, std::vector<double>& r) {
    if (!(p[0] > 0)) return false;
    const Lens l = with_params(start, p);
    if (!plane_distances(l, lines, r)) return false;
    r.push_back(kRimWeight * (kb_radius(l, theta_max) - rim));
    return true;
  };
  const auto cost_of = [](const std::vector<double>& r) {
    double s = 0;
    for (double v : r) s += v * v;
    return s;
  };

  Params p{start.r_pp, start.cx, start.cy, start.k[0], start.k[1], start.k[2], start.k[3]};
  std::vector<double> r, r_try;
  std::string error;
  {
    std::vector<double> d;
    if (!plane_distances(start, lines, d, &error)) throw std::invalid_argument(error);
  }
  if (!residuals(p, r)) throw std::invalid_argument("the start lens has no ray for some picked point");
  double cost = cost_of(r);
  double mu = 1e-3;
  const std::array<double, 7> steps{1e-7 * start.r_pp, 1e-4, 1e-4, 1e-7, 1e-7, 1e-7, 1e-7};
  LineFitResult result;
  int it = 0;
  for (; it < options.max_iterations; ++it) {
    const int m = static_cast<int>(r.size());
    cv::Mat J = cv::Mat::zeros(m, 7, CV_64F);
    for (int j = 0; j < 7; ++j) {
      if (options.fixed[static_cast<std::size_t>(j)]) continue;
      Params q = p;
      q[static_cast<std::size_t>(j)] += steps[static_cast<std::size_t>(j)];
      if (!residuals(q, r_try) || static_cast<int>(r_try.size()) != m) {
        q[static_cast<std::size_t>(j)] = p[static_cast<std::size_t>(j)] - steps[static_cast<std::size_t>(j)];
        if (!residuals(q, r_try)) throw std::runtime_error("line fit: the lens model breaks down at the current step");
        for (int i = 0; i < m; ++i)
          J.at<double>(i, j) = (r[static_cast<std::size_t>(i)] - r_try[static_cast<std::size_t>(i)]) /
                               steps[static_cast<std::size_t>(j)];
      } else {
        for (int i = 0; i < m; ++i)
          J.at<double>(i, j) = (r_try[static_cast<std::size_t>(i)] - r[static_cast<std::size_t>(i)]) /
                               steps[static_cast<std::size_t>(j)];
      }
    }
    cv::Mat A = J.t() * J;
    cv::Mat g = J.t() * cv::Mat(r);
    for (int j = 0; j < 7; ++j)
      if (options.fixed[static_cast<std::size_t>(j)]) A.at<double>(j, j) = 1;  // its step solves to 0
    bool accepted = false;
    double new_cost = cost;
    while (mu < 1e12) {
      cv::Mat D = A.clone();
      for (int j = 0; j < 7; ++j) D.at<double>(j, j) += mu * std::max(A.at<double>(j, j), 1e-12);
      cv::Mat delta;
      if (!cv::solve(D, -g, delta, cv::DECOMP_CHOLESKY)) {
        mu *= 4;
        continue;
      }
      Params q = p;
      for (int j = 0; j < 7; ++j) q[static_cast<std::size_t>(j)] += delta.at<double>(j);
      if (residuals(q, r_try) && r_try.size() == r.size() && (new_cost = cost_of(r_try)) < cost) {
        p = q;
        r.swap(r_try);
        mu = std::max(mu / 3, 1e-12);
        accepted = true;
        break;
      }
      mu *= 4;
    }
    if (!accepted) break;  // no step lowers the cost: a minimum
    const bool small = cost - new_cost < 1e-12 * cost + 1e-20;
    cost = new_cost;
    if (small) break;
  }
  result.iterations = it;
  result.lens = with_params(start, p);
  result.lens.validate();
  result.before = line_straightness(start, lines);
  result.after = line_straightness(result.lens, lines);
  auto& cal = result.lens.calibration;
  cal = {};
  cal.method = LensCalibration::Method::LineFit;
  cal.rms_px = result.after.rms_px;
  char detail[256];
  std::snprintf(detail, sizeof detail,
                "%d lines, %d points; straightness RMS %.3g px before, %.3g px after (max %.3g -> %.3g px); "
                "image circle r %.2f px held",
                result.after.lines, result.after.points, result.before.rms_px, result.after.rms_px,
                result.before.max_px, result.after.max_px, rim);
  cal.detail = detail;
  return result;
}

}  // namespace

LineFitResult fit_lens_to_lines(const Lens& start, const std::vector<PickedLine>& lines,
                                const LineFitOptions& options) {
  LineFitResult fit = fit_once(start, lines, options);
  if (!(options.reject_lines > 0)) return fit;
  std::vector<int> rejected;
  for (int round = 0; round < 4; ++round) {
    // Every line's straightness under this fit, the dropped ones too (a better lens may take them back).
    std::vector<double> rms(lines.size(), -1), usable;
    for (std::size_t i = 0; i < lines.size(); ++i) {
      if (lines[i].size() < 3) continue;
      try {
        rms[i] = line_straightness(fit.lens, {lines[i]}).rms_px;
        usable.push_back(rms[i]);
      } catch (const std::invalid_argument&) {
        rms[i] = std::numeric_limits<double>::infinity();  // a point without a ray under this lens
      }
    }
    if (usable.empty()) break;
    std::nth_element(usable.begin(), usable.begin() + static_cast<std::ptrdiff_t>(usable.size() / 2), usable.end());
    const double limit = std::max(options.reject_lines * usable[usable.size() / 2], 0.1);
    std::vector<int> out;
    std::vector<PickedLine> kept;
    for (std::size_t i = 0; i < lines.size(); ++i) {
      if (rms[i] > limit)
        out.push_back(static_cast<int>(i));
      else
        kept.push_back(lines[i]);
    }
    if (out == rejected) break;
    int kept_usable = 0;
    for (const auto& l : kept) kept_usable += l.size() >= 3;
    if (kept_usable < 3) break;
    fit = fit_once(start, kept, options);
    rejected = out;
  }
  fit.rejected_lines = rejected;
  if (!rejected.empty()) {
    char more[160];
    std::snprintf(more, sizeof more, "; %zu line(s) left out (straightness RMS over %.3g x the median line's)",
                  rejected.size(), options.reject_lines);
    fit.lens.calibration.detail += more;
  }
  return fit;
}

nlohmann::json lines_to_json(const std::vector<PickedLine>& lines, int width, int height) {
  nlohmann::json arr = nlohmann::json::array();
  for (const auto& l : lines) {
    nlohmann::json pts = nlohmann::json::array();
    for (const auto& p : l) pts.push_back({p.x, p.y});
    arr.push_back(pts);
  }
  nlohmann::json j = {{"format", "benchscope-lines"}, {"version", 1}, {"lines", arr}};
  if (width > 0 && height > 0) j["width"] = width, j["height"] = height;
  return j;
}

std::vector<PickedLine> lines_from_json(const nlohmann::json& j) {
  if (!j.is_object() || j.value("format", "") != "benchscope-lines")
    throw std::invalid_argument("/format: not a BenchScope lines file (expected \"benchscope-lines\")");
  if (!j.contains("lines") || !j["lines"].is_array()) throw std::invalid_argument("/lines: expected an array");
  std::vector<PickedLine> out;
  const auto& arr = j["lines"];
  for (std::size_t i = 0; i < arr.size(); ++i)
    out.push_back(points_from_json<double>(arr[i], "/lines/" + std::to_string(i), /*finite=*/true));
  return out;
}

void save_lines_json(const std::vector<PickedLine>& lines, int width, int height, const std::filesystem::path& path) {
  std::ofstream f(path);
  if (!f) throw std::runtime_error(path.string() + ": cannot open for writing");
  f << lines_to_json(lines, width, height).dump() << '\n';
  if (!f) throw std::runtime_error(path.string() + ": write failed");
}

std::vector<PickedLine> load_lines_json(const std::filesystem::path& path) {
  std::ifstream f(path);
  if (!f) throw std::runtime_error(path.string() + ": cannot open");
  try {
    return lines_from_json(nlohmann::json::parse(f));
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path.string() + ": not valid JSON: " + e.what());
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
}

}  // namespace bs::vision
