// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/frames/synthetic_checkerboard.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

#include <opencv2/imgproc.hpp>

#include "vision/frames/synthetic.h"
#include "vision/lens/fisheye_opencv.h"

namespace bs::vision {
namespace {

constexpr double kPi = 3.14159265358979323846;
double rad(double deg) { return deg * kPi / 180.0; }

// theta(r) sampled every 1/16 px and interpolated linearly: the inverse lens model is solved by bisection once
// per table entry instead of once per sample (the interpolation error is far below 1e-6 rad for these models).
class InverseRadius {
 public:
  explicit InverseRadius(const Lens& lens) {
    const auto rmax = lens.radius(rad(lens.fov_deg) / 2);
    rmax_ = rmax ? *rmax : 0;
    const auto n = static_cast<std::size_t>(std::ceil(rmax_ * kPerPx)) + 2;
    table_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const auto t = lens_theta(lens, std::min(rmax_, static_cast<double>(i) / kPerPx));
      table_[i] = t ? *t : rad(lens.fov_deg) / 2;
    }
  }
  std::optional<double> theta(double r) const {
    if (r > rmax_) return std::nullopt;
    const double x = r * kPerPx;
    const auto i = static_cast<std::size_t>(x);
    const double f = x - static_cast<double>(i);
    return table_[i] + f * (table_[i + 1] - table_[i]);
  }

 private:
  static constexpr double kPerPx = 16;
  double rmax_ = 0;
  std::vector<double> table_;
};

// The board's point, in the camera frame, for board coordinates (u right, v down) in millimetres from its centre.
cv::Vec3d board_point(const BoardPose& pose, const cv::Matx33d& R, double u, double v) {
  return R * cv::Vec3d(0, u, -v) + cv::Vec3d(pose.tx_mm, pose.ty_mm, pose.tz_mm);
}

}  // namespace

cv::Matx33d BoardPose::rotation() const {
  const double a = rad(rx_deg), b = rad(ry_deg), c = rad(rz_deg);
  const cv::Matx33d Rx(1, 0, 0, 0, std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a));
  const cv::Matx33d Ry(std::cos(b), 0, std::sin(b), 0, 1, 0, -std::sin(b), 0, std::cos(b));
  const cv::Matx33d Rz(std::cos(c), -std::sin(c), 0, std::sin(c), std::cos(c), 0, 0, 0, 1);
  return Rz * Ry * Rx;
}

BoardPose parse_pose(std::string_view text) {
  BoardPose p;
  char extra = 0;
  const std::string s(text);
  if (std::sscanf(s.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf%c", &p.rx_deg, &p.ry_deg, &p.rz_deg, &p.tx_mm, &p.ty_mm, &p.tz_mm,
                  &extra) != 6)
    throw std::invalid_argument("pose '" + s + "': expected rx,ry,rz,tx,ty,tz (degrees, millimetres)");
  for (double v : {p.rx_deg, p.ry_deg, p.rz_deg, p.tx_mm, p.ty_mm, p.tz_mm})
    if (!std::isfinite(v)) throw std::invalid_argument("pose '" + s + "': not a finite number");
  if (std::hypot(p.tx_mm, p.ty_mm, p.tz_mm) < 1e-6)
    throw std::invalid_argument("pose '" + s + "': the board's centre cannot be at the camera");
  return p;
}

std::vector<BoardPose> load_poses(const std::filesystem::path& path) {
  std::ifstream f(path);
  if (!f) throw std::runtime_error(path.string() + ": cannot open the poses file");
  std::vector<BoardPose> poses;
  std::string line;
  for (int n = 1; std::getline(f, line); ++n) {
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    const auto last = line.find_last_not_of(" \t\r");
    try {
      poses.push_back(parse_pose(std::string_view(line).substr(first, last - first + 1)));
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(path.string() + ":" + std::to_string(n) + ": " + e.what());
    }
  }
  if (poses.empty()) throw std::runtime_error(path.string() + ": no poses (one rx,ry,rz,tx,ty,tz per line)");
  return poses;
}

cv::Mat render_checkerboard(const Lens& lens, const BoardPose& pose, const CheckerboardRender& how) {
  lens.validate();
  how.board.validate();
  if (how.bits != 8 && how.bits != 10 && how.bits != 12 && how.bits != 16)
    throw std::invalid_argument("checkerboard render: bits must be 8, 10, 12 or 16");
  if (how.supersample < 1 || how.supersample > 16)
    throw std::invalid_argument("checkerboard render: supersample must be 1 to 16");
  const InverseRadius inverse(lens);
  const cv::Matx33d R = pose.rotation();
  const cv::Vec3d t(pose.tx_mm, pose.ty_mm, pose.tz_mm);
  const cv::Vec3d normal = R * cv::Vec3d(1, 0, 0);
  const double n_dot_t = normal.dot(t);
  const cv::Matx33d Rt = R.t();
  const double sq = how.board.square_mm, half_w = how.board.cols * sq / 2, half_h = how.board.rows * sq / 2;
  constexpr double kDark = 0.08, kWhite = 0.92, kBackground = 0.45, kOutside = 0.0;
  const cv::Point2d c = lens.centre();
  const int n = how.supersample;

  cv::Mat grey(lens.height, lens.width, CV_32F);
#pragma omp parallel for schedule(dynamic, 8)
  for (int row = 0; row < lens.height; ++row) {
    auto* out = grey.ptr<float>(row);
    for (int col = 0; col < lens.width; ++col) {
      double sum = 0;
      for (int sy = 0; sy < n; ++sy)
        for (int sx = 0; sx < n; ++sx) {
          const double px = col + (sx + 0.5) / n - 0.5, py = row + (sy + 0.5) / n - 0.5;
          const double dx = px - c.x, dz = c.y - py;  // BenchScope screen frame: +z up
          const double r = std::hypot(dx, dz);
          const auto theta = inverse.theta(r);
          if (!theta) {
            sum += kOutside;
            continue;
          }
          const double s = std::sin(*theta);
          const cv::Vec3d d(std::cos(*theta), r > 0 ? s * dx / r : 0, r > 0 ? s * dz / r : 0);
          const double n_dot_d = normal.dot(d);
          const double along = std::abs(n_dot_d) > 1e-12 ? n_dot_t / n_dot_d : -1;
          if (!(along > 0)) {
            sum += kBackground;
            continue;
          }
          const cv::Vec3d local = Rt * (along * d - t);
          const double u = local[1], v = -local[2];
          if (std::abs(u) <= half_w && std::abs(v) <= half_h) {
            const auto i = static_cast<long>(std::floor((u + half_w) / sq)),
                       j = static_cast<long>(std::floor((v + half_h) / sq));
            sum += ((i + j) % 2 == 0) ? kDark : kWhite;
          } else if (std::abs(u) <= half_w + sq && std::abs(v) <= half_h + sq) {
            sum += kWhite;  // the quiet zone findChessboardCornersSB needs around the squares
          } else {
            sum += kBackground;
          }
        }
      out[col] = static_cast<float>(sum / (n * n));
    }
  }
  if (how.blur_sigma_px > 0) cv::GaussianBlur(grey, grey, cv::Size(), how.blur_sigma_px);
  const double scale = how.bits > 8 ? (1 << how.bits) - 1 : 255.0;
  grey *= scale;
  if (how.noise_sigma > 0) {
    cv::Mat noise(grey.size(), CV_32F);
    cv::RNG rng(how.seed);
    rng.fill(noise, cv::RNG::NORMAL, 0.0, how.noise_sigma);
    grey += noise;
  }
  cv::Mat out;
  grey.convertTo(out, how.bits > 8 ? CV_16U : CV_8U);  // rounds and saturates
  if (how.bits > 8 && how.bits < 16) cv::min(out, scale, out);
  return out;
}

std::vector<std::optional<cv::Point2d>> board_corner_truth(const Lens& lens, const BoardPose& pose,
                                                           const Checkerboard& board) {
  const cv::Matx33d R = pose.rotation();
  std::vector<std::optional<cv::Point2d>> out;
  const double sq = board.square_mm;
  const cv::Size inner = board.inner_corners();
  for (int j = 0; j < inner.height; ++j)
    for (int i = 0; i < inner.width; ++i) {
      const double u = (i + 1) * sq - board.cols * sq / 2, v = (j + 1) * sq - board.rows * sq / 2;
      const cv::Vec3d p = board_point(pose, R, u, v);
      out.push_back(project_camera_point(lens, cv::Vec3d(p[1], -p[2], p[0])));  // BenchScope -> OpenCV camera frame
    }
  return out;
}

}  // namespace bs::vision
