// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/lens/fisheye_opencv.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "vision/frames/synthetic.h"

namespace bs::vision {

cv::Matx33d OpenCvFisheye::camera_matrix() const { return {fx, 0, cx, 0, fy, cy, 0, 0, 1}; }

cv::Vec4d OpenCvFisheye::distortion() const { return {k[0], k[1], k[2], k[3]}; }

OpenCvFisheye OpenCvFisheye::from(const cv::Matx33d& K, const cv::Vec4d& D) {
  OpenCvFisheye c;
  c.fx = K(0, 0);
  c.fy = K(1, 1);
  c.cx = K(0, 2);
  c.cy = K(1, 2);
  c.k = {D[0], D[1], D[2], D[3]};
  return c;
}

OpenCvFisheye to_opencv_fisheye(const Lens& lens) {
  if (lens.type != LensType::Equidistant && lens.type != LensType::KannalaBrandt)
    throw std::invalid_argument("a " + std::string(to_string(lens.type)) +
                                " lens is not an OpenCV fisheye camera (equidistant or kannala-brandt only)");
  lens.validate();
  OpenCvFisheye c;
  c.fx = c.fy = 1.0 / lens.r_pp;
  const cv::Point2d centre = lens.centre();
  c.cx = centre.x;
  c.cy = centre.y;
  if (lens.type == LensType::KannalaBrandt) c.k = lens.k;
  return c;
}

Lens lens_from_opencv_fisheye(const OpenCvFisheye& cam, const Lens& base) {
  if (!(cam.fx > 0) || !(cam.fy > 0)) throw std::invalid_argument("OpenCV fisheye camera: fx and fy must be > 0");
  Lens lens = base;
  lens.r_pp = 1.0 / std::sqrt(cam.fx * cam.fy);
  lens.cx = cam.cx;
  lens.cy = cam.cy;
  lens.k = cam.k;
  lens.type = cam.k == std::array<double, 4>{} ? LensType::Equidistant : LensType::KannalaBrandt;
  return lens;
}

std::optional<cv::Point2d> project_camera_point(const Lens& lens, const cv::Vec3d& p) {
  const double n = cv::norm(p);
  if (!(n > 0)) return std::nullopt;
  const double theta = std::acos(std::clamp(p[2] / n, -1.0, 1.0));
  const auto r = lens.radius(theta);
  if (!r) return std::nullopt;
  const double rho = std::hypot(p[0], p[1]);
  const cv::Point2d c = lens.centre();
  if (!(rho > 0)) return c;
  // OpenCV's +y is down, as image rows are: no flip here (BenchScope's +z up becomes -y).
  return cv::Point2d(c.x + *r * p[0] / rho, c.y + *r * p[1] / rho);
}

std::optional<cv::Vec3d> camera_ray(const Lens& lens, cv::Point2d px) {
  const cv::Point2d c = lens.centre();
  const double dx = px.x - c.x, dy = px.y - c.y, r = std::hypot(dx, dy);
  const auto theta = lens_theta(lens, r);
  if (!theta) return std::nullopt;
  const double s = std::sin(*theta);
  return r > 0 ? cv::Vec3d(s * dx / r, s * dy / r, std::cos(*theta)) : cv::Vec3d(0, 0, 1);
}

}  // namespace bs::vision
