// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/frames/synthetic_room.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "vision/frames/synthetic.h"

namespace bs::vision {
namespace {

constexpr double kPi = 3.14159265358979323846;
// The room's planes: x = kFront / -kBack, y = kRight / -kLeft, z = kCeiling / -kFloor (metres).
constexpr double kFront = 2.1, kBack = 1.7, kRight = 1.6, kLeft = 1.9, kCeiling = 1.5, kFloor = 1.2;
constexpr double kGrid = 0.5, kLineHalfWidth = 0.012;

// Distance of v from the nearest multiple of the grid spacing.
double grid_distance(double v) {
  const double m = std::fmod(std::abs(v), kGrid);
  return std::min(m, kGrid - m);
}

// Room point (unyawed frame) -> reflectance. (u, v) are the surface's in-plane coordinates.
cv::Vec3d surface_colour(int face, double u, double v) {
  // Dark objects: a cabinet on the right wall and a screen on the left wall, both at the camera's height so they
  // sit on the rim of a wide lens's circle; a dark rug on the floor.
  if (face == 2 && u > -0.8 && u < 0.6 && v > -kFloor && v < 0.3) return {0.04, 0.04, 0.05};
  if (face == 3 && u > -0.5 && u < 0.9 && v > -0.1 && v < 0.9) return {0.03, 0.03, 0.03};
  if (face == 4 && u > -0.9 && u < 0.7 && v > -1.0 && v < 0.4) return {0.08, 0.06, 0.10};
  if (grid_distance(u) < kLineHalfWidth || grid_distance(v) < kLineHalfWidth) return {0.06, 0.06, 0.06};
  // Light surfaces with a gentle texture (plaster, wood), so edges inside the circle are not all the same strength.
  const double tex = 0.07 * std::sin(3.1 * u + 0.7) * std::cos(2.3 * v) + 0.03 * std::sin(17.0 * u + 11.0 * v);
  switch (face) {
    case 4:
      return {0.32 + tex, 0.42 + tex, 0.55 + tex};  // floor: wood
    case 5:
      return {0.86 + tex, 0.86 + tex, 0.84 + tex};  // ceiling
    default:
      return {0.70 + tex, 0.74 + tex, 0.76 + tex};
  }
}

}  // namespace

double room_yaw(std::uint64_t seed) {
  // A fixed, well-spread sequence of yaws: the golden-angle step, so consecutive seeds see different walls.
  return std::fmod(static_cast<double>(seed) * 2.39996322972865332, 2 * kPi) - kPi;
}

cv::Vec3d room_colour(const cv::Vec3d& dir_camera, double yaw_rad) {
  // Camera ray -> room frame: the camera is yawed by yaw_rad inside the room.
  const double c = std::cos(yaw_rad), s = std::sin(yaw_rad);
  const cv::Vec3d d(c * dir_camera[0] - s * dir_camera[1], s * dir_camera[0] + c * dir_camera[1], dir_camera[2]);
  double t = std::numeric_limits<double>::infinity();
  int face = -1;
  const auto consider = [&](double component, double plus, double minus, int face_plus, int face_minus) {
    if (component > 0 && plus / component < t) t = plus / component, face = face_plus;
    if (component < 0 && -minus / component < t) t = -minus / component, face = face_minus;
  };
  consider(d[0], kFront, kBack, 0, 1);
  consider(d[1], kRight, kLeft, 2, 3);
  consider(d[2], kCeiling, kFloor, 5, 4);
  if (face < 0) return {0, 0, 0};
  const cv::Vec3d p = d * t;
  switch (face) {
    case 0:
    case 1:
      return surface_colour(face, p[1], p[2]);
    case 2:
    case 3:
      return surface_colour(face, p[0], p[2]);
    default:
      return surface_colour(face, p[0], p[1]);
  }
}

std::vector<Segment3d> room_grid_lines(double yaw_rad) {
  // The vertical grid lines of the four walls and the horizontal ones at a few heights, each running corner to
  // corner (dark objects cover parts of them in the image; the 3D line is still straight).
  std::vector<Segment3d> room;
  for (double y = -1.5; y <= 1.5 + 1e-9; y += kGrid) {
    room.push_back({{kFront, y, -kFloor}, {kFront, y, kCeiling}});
    room.push_back({{-kBack, y, -kFloor}, {-kBack, y, kCeiling}});
  }
  for (double x = -1.5; x <= 2.0 + 1e-9; x += kGrid) {
    room.push_back({{x, kRight, -kFloor}, {x, kRight, kCeiling}});
    room.push_back({{x, -kLeft, -kFloor}, {x, -kLeft, kCeiling}});
  }
  for (double z : {-1.0, -0.5, 0.5, 1.0}) {
    room.push_back({{kFront, -kLeft, z}, {kFront, kRight, z}});
    room.push_back({{-kBack, -kLeft, z}, {-kBack, kRight, z}});
    room.push_back({{-kBack, kRight, z}, {kFront, kRight, z}});
    room.push_back({{-kBack, -kLeft, z}, {kFront, -kLeft, z}});
  }
  // Room frame -> camera frame (inverse of the yaw in room_colour).
  const double c = std::cos(yaw_rad), s = std::sin(yaw_rad);
  const auto to_camera = [&](const cv::Vec3d& p) { return cv::Vec3d(c * p[0] + s * p[1], -s * p[0] + c * p[1], p[2]); };
  for (auto& seg : room) seg = {to_camera(seg.a), to_camera(seg.b)};
  return room;
}

cv::Mat render_room_fisheye(const Lens& lens, const RoomOptions& o) {
  lens.validate();
  if (o.bits != 8 && o.bits != 10 && o.bits != 12 && o.bits != 16)
    throw std::invalid_argument("room render: bits must be 8, 10, 12 or 16");
  const double theta_max = lens.fov_deg * kPi / 360.0;
  const auto rim = lens.radius(theta_max);
  if (!rim) throw std::invalid_argument("room render: the lens model cannot image its own field of view");
  const double r_max = *rim;
  // theta(r) as a table at 1/64 px (linear interpolation between entries is far below 1/100 px off), so the
  // inverse lens model is solved ~64 * r_max times instead of once per sample.
  constexpr double kStep = 1.0 / 64;
  std::vector<double> theta_of(static_cast<std::size_t>(r_max / kStep) + 2);
  for (std::size_t i = 0; i < theta_of.size(); ++i)
    theta_of[i] = lens_theta(lens, std::min(r_max, static_cast<double>(i) * kStep)).value_or(theta_max);
  const double yaw = room_yaw(o.seed);
  const cv::Point2d c = lens.centre();
  cv::Mat linear(lens.height, lens.width, CV_32FC3);
#pragma omp parallel for schedule(dynamic, 8)
  for (int row = 0; row < lens.height; ++row) {
    auto* out = linear.ptr<cv::Vec3f>(row);
    for (int col = 0; col < lens.width; ++col) {
      // 4x4 samples near the rim, where the coverage sets the edge position; 2x2 elsewhere.
      const double r_pixel = std::hypot(col - c.x, row - c.y);
      if (r_pixel > r_max + 1.5) {
        out[col] = cv::Vec3f(0, 0, 0);
        continue;
      }
      const int n = std::abs(r_pixel - r_max) < 1.5 ? 4 : 2;
      cv::Vec3d sum(0, 0, 0);
      for (int sy = 0; sy < n; ++sy)
        for (int sx = 0; sx < n; ++sx) {
          const double px = col - 0.5 + (sx + 0.5) / n, py = row - 0.5 + (sy + 0.5) / n;
          const double dx = px - c.x, dz = c.y - py;  // screen +z up
          const double r = std::hypot(dx, dz);
          if (r > r_max) continue;
          const double fi = r / kStep;
          const auto i = static_cast<std::size_t>(fi);
          const double theta = theta_of[i] + (fi - static_cast<double>(i)) * (theta_of[i + 1] - theta_of[i]);
          const double st = std::sin(theta);
          const cv::Vec3d dir(std::cos(theta), r > 0 ? st * dx / r : 0, r > 0 ? st * dz / r : 0);
          const double t = theta / theta_max;
          sum += room_colour(dir, yaw) * (1 - o.vignetting * t * t);
        }
      out[col] = cv::Vec3f(sum * (1.0 / (n * n)));
    }
  }
  const double full = o.bits > 8 ? (1 << o.bits) - 1 : 255.0;
  if (o.noise > 0) {
    cv::Mat noise(linear.size(), CV_32FC3);
    cv::RNG rng(o.seed * 7919 + 17);
    rng.fill(noise, cv::RNG::NORMAL, 0.0, o.noise);
    linear += noise;
  }
  if (o.black_level > 0) linear += cv::Scalar::all(o.black_level);
  cv::Mat result;
  // convertTo rounds and saturates, which is what a sensor's ADC does to values outside its range.
  linear.convertTo(result, o.bits > 8 ? CV_16UC3 : CV_8UC3, full);
  if (o.bits > 8 && o.bits < 16) cv::min(result, cv::Scalar::all(full), result);
  return result;
}

}  // namespace bs::vision
