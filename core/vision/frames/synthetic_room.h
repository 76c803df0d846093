// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A second synthetic scene with ground truth: the inside of a room (walls, floor and ceiling) whose surfaces carry
// a grid of dark lines and a few dark objects, seen through a lens from inside the room. Every ray hits a surface,
// so the whole image circle is lit, even beyond 90 degrees off the axis; dark lines and dark objects reach the
// rim. The grid lines are straight in 3D, so they also test straight-line calibration. Options add vignetting and
// sensor noise, so that image-circle fits are checked on captures that look like real ones.
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "vision/lens/lens.h"

namespace bs::vision {

struct RoomOptions {
  int bits = 8;            // 8: CV_8UC3; 10, 12 or 16: CV_16UC3 with values in the low `bits`
  double vignetting = 0;   // fraction of the brightness lost at the rim of the image circle, ~ (theta/theta_max)^2
  double noise = 0;        // Gaussian sensor noise, standard deviation as a fraction of full scale (also outside)
  double black_level = 0;  // dark offset of the sensor, fraction of full scale (outside the circle too)
  std::uint64_t seed = 1;  // noise and the camera's yaw inside the room
};

// Room geometry, in metres, camera at the origin looking along +x (y right, z up; the lens's ray space).
// Walls at x = +2.1 / -1.7, y = +1.6 / -1.9, floor z = -1.2, ceiling z = +1.5; grid lines every 0.5 m.
// Reflectance (0..1, BGR) of the surface the ray `dir` (need not be unit) hits, after yawing the room by `yaw_rad`.
cv::Vec3d room_colour(const cv::Vec3d& dir, double yaw_rad);

// Camera yaw inside the room that `seed` picks (so that different seeds put different walls and lines at the rim).
double room_yaw(std::uint64_t seed);

// The fisheye capture of the room: 4x4 supersampled (the circle's rim is exact to about 1/8 px), vignetting, then
// noise, then quantisation to `bits`.
cv::Mat render_room_fisheye(const Lens& lens, const RoomOptions& options = {});

// Straight 3D lines of the room's grid (segments, endpoints in the camera frame after the yaw), for tests of
// straight-line calibration: each is a segment on a wall between two corners of the room.
struct Segment3d {
  cv::Vec3d a, b;
};
std::vector<Segment3d> room_grid_lines(double yaw_rad);

}  // namespace bs::vision
