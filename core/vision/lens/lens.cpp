// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/lens/lens.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

namespace bs::vision {
namespace {

constexpr double kPi = 3.14159265358979323846;
double rad(double deg) { return deg * kPi / 180.0; }

}  // namespace

std::string_view to_string(LensType t) {
  static const char* names[] = {"equidistant",  "equisolid",   "stereographic",
                                "orthographic", "rectilinear", "kannala-brandt"};
  return names[static_cast<int>(t)];
}

LensType lens_type_from_string(std::string_view s) {
  for (int i = 0; i < 6; ++i)
    if (to_string(static_cast<LensType>(i)) == s) return static_cast<LensType>(i);
  throw std::invalid_argument("unknown lens model '" + std::string(s) +
                              "' (expected equidistant, equisolid, stereographic, orthographic, rectilinear or "
                              "kannala-brandt)");
}

// Rotation of rays by yaw (about the vertical z axis), pitch (about y) and roll (about the optical x axis).
cv::Matx33d view_rotation(const View& v) {
  const double y = rad(v.yaw_deg), p = rad(v.pitch_deg), r = rad(v.roll_deg);
  const cv::Matx33d yaw(std::cos(y), -std::sin(y), 0, std::sin(y), std::cos(y), 0, 0, 0, 1);
  const cv::Matx33d pitch(std::cos(p), 0, -std::sin(p), 0, 1, 0, std::sin(p), 0, std::cos(p));
  const cv::Matx33d roll(1, 0, 0, 0, std::cos(r), -std::sin(r), 0, std::sin(r), std::cos(r));
  return yaw * pitch * roll;
}

std::optional<double> Lens::radius(double theta) const {
  if (theta > rad(fov_deg) / 2 + 1e-12) return std::nullopt;
  const double f = 1.0 / r_pp;
  switch (type) {
    case LensType::Equidistant:
      return theta / r_pp;
    case LensType::Equisolid:
      return 2 * f * std::sin(theta / 2);
    case LensType::Stereographic:
      return 2 * f * std::tan(theta / 2);
    case LensType::Orthographic:
      if (theta > kPi / 2) return std::nullopt;
      return f * std::sin(theta);
    case LensType::Rectilinear:
      if (theta >= kPi / 2) return std::nullopt;
      return f * std::tan(theta);
    case LensType::KannalaBrandt: {
      const double t2 = theta * theta;
      return f * theta * (1 + t2 * (k[0] + t2 * (k[1] + t2 * (k[2] + t2 * k[3]))));
    }
  }
  return std::nullopt;
}

cv::Point2d Lens::centre() const { return {cx >= 0 ? cx : (width - 1) / 2.0, cy >= 0 ? cy : (height - 1) / 2.0}; }

void Lens::validate() const {
  if (!(r_pp > 0) || !std::isfinite(r_pp)) throw std::invalid_argument("lens r_pp must be > 0 radians per pixel");
  if (width <= 0 || height <= 0) throw std::invalid_argument("lens image size must be > 0");
  if (!(fov_deg > 0 && fov_deg <= 360)) throw std::invalid_argument("lens field of view must be in (0, 360] degrees");
  if (type == LensType::Rectilinear && fov_deg >= 180)
    throw std::invalid_argument("a rectilinear lens cannot see 180 degrees or more");
}

Lens Lens::paper() {
  Lens l;
  l.type = LensType::Equidistant;
  l.fov_deg = 195;
  l.width = 1280;
  l.height = 1024;
  l.r_pp = rad(195) / 1280;
  return l;
}

double View::focal_px() const { return std::hypot(width - 1.0, height - 1.0) / (2 * std::tan(rad(fov_deg) / 2)); }

void View::validate() const {
  if (width <= 0 || height <= 0) throw std::invalid_argument("output size must be > 0");
  if (!(fov_deg > 0 && fov_deg < 180))
    throw std::invalid_argument("a rectilinear output needs 0 < FOV < 180 degrees (tan(FOV/2) is infinite at 180)");
}

std::string_view to_string(LensCalibration::Method m) {
  switch (m) {
    case LensCalibration::Method::Manual:
      return "manual";
    case LensCalibration::Method::CircleFit:
      return "circle-fit";
    case LensCalibration::Method::Checkerboard:
      return "checkerboard";
    case LensCalibration::Method::LineFit:
      return "line-fit";
  }
  return "manual";
}

LensCalibration::Method calibration_method_from_string(std::string_view s) {
  for (auto m : {LensCalibration::Method::Manual, LensCalibration::Method::CircleFit,
                 LensCalibration::Method::Checkerboard, LensCalibration::Method::LineFit})
    if (to_string(m) == s) return m;
  throw std::invalid_argument("unknown calibration method '" + std::string(s) +
                              "' (manual, circle-fit, checkerboard, line-fit)");
}

std::string describe(const LensCalibration& c) {
  std::string out(to_string(c.method));
  if (c.method == LensCalibration::Method::Checkerboard)
    out += ", " + std::to_string(c.images_used) + " image" + (c.images_used == 1 ? "" : "s") +
           (c.images_rejected > 0 ? " (" + std::to_string(c.images_rejected) + " rejected)" : "");
  if (c.rms_px) {
    char buf[48];
    std::snprintf(buf, sizeof buf, ", RMS %.3g px", *c.rms_px);
    out += buf;
  }
  if (!c.detail.empty()) out += "; " + c.detail;
  return out;
}

static nlohmann::json calibration_to_json(const LensCalibration& c) {
  nlohmann::json j = {{"method", std::string(to_string(c.method))}};
  if (c.rms_px) j["rms_px"] = *c.rms_px;
  if (c.images_used > 0) j["images_used"] = c.images_used;
  if (c.images_rejected > 0) j["images_rejected"] = c.images_rejected;
  if (!c.detail.empty()) j["detail"] = c.detail;
  if (c.covered_deg) j["covered_deg"] = *c.covered_deg;
  if (c.rim_radius_se_px) j["rim_radius_se_px"] = *c.rim_radius_se_px;
  return j;
}

static LensCalibration calibration_from_json(const nlohmann::json& j) {
  if (!j.is_object()) throw std::invalid_argument("/lens/calibration: expected an object");
  LensCalibration c;
  if (j.contains("method")) {
    if (!j["method"].is_string()) throw std::invalid_argument("/lens/calibration/method: expected a string");
    try {
      c.method = calibration_method_from_string(j["method"].get<std::string>());
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("/lens/calibration/method: ") + e.what());
    }
  }
  if (j.contains("rms_px")) {
    if (!j["rms_px"].is_number() || j["rms_px"].get<double>() < 0)
      throw std::invalid_argument("/lens/calibration/rms_px: expected a number >= 0");
    c.rms_px = j["rms_px"].get<double>();
  }
  for (auto [key, field] : {std::pair{"images_used", &c.images_used}, std::pair{"images_rejected", &c.images_rejected}})
    if (j.contains(key)) {
      if (!j[key].is_number_integer() || j[key].get<long long>() < 0 || j[key].get<long long>() > 1000000)
        throw std::invalid_argument(std::string("/lens/calibration/") + key + ": expected a count");
      *field = j[key].get<int>();
    }
  if (j.contains("detail")) {
    if (!j["detail"].is_string()) throw std::invalid_argument("/lens/calibration/detail: expected a string");
    c.detail = j["detail"].get<std::string>();
  }
  if (j.contains("covered_deg")) {
    if (!j["covered_deg"].is_number() || !(j["covered_deg"].get<double>() > 0) || j["covered_deg"].get<double>() > 180)
      throw std::invalid_argument("/lens/calibration/covered_deg: expected degrees in (0, 180]");
    c.covered_deg = j["covered_deg"].get<double>();
  }
  if (j.contains("rim_radius_se_px")) {
    if (!j["rim_radius_se_px"].is_number() || !(j["rim_radius_se_px"].get<double>() >= 0) ||
        !std::isfinite(j["rim_radius_se_px"].get<double>()))
      throw std::invalid_argument("/lens/calibration/rim_radius_se_px: expected a number >= 0");
    c.rim_radius_se_px = j["rim_radius_se_px"].get<double>();
  }
  return c;
}

nlohmann::json lens_to_json(const Lens& lens, const View& view) {
  return {{"format", "benchscope-lens"},
          {"version", 1},
          {"lens",
           {{"model", std::string(to_string(lens.type))},
            {"r_pp", lens.r_pp},
            {"k", lens.k},
            {"cx", lens.cx},
            {"cy", lens.cy},
            {"fov_deg", lens.fov_deg},
            {"width", lens.width},
            {"height", lens.height},
            {"calibration", calibration_to_json(lens.calibration)}}},
          {"view",
           {{"width", view.width},
            {"height", view.height},
            {"fov_deg", view.fov_deg},
            {"yaw_deg", view.yaw_deg},
            {"pitch_deg", view.pitch_deg},
            {"roll_deg", view.roll_deg}}}};
}

std::pair<Lens, View> lens_from_json(const nlohmann::json& j) {
  auto need = [](const nlohmann::json& o, const char* key, const std::string& at) -> const nlohmann::json& {
    if (!o.is_object() || !o.contains(key)) throw std::invalid_argument(at + "/" + key + ": missing");
    return o.at(key);
  };
  auto number = [&](const nlohmann::json& o, const char* key, const std::string& at) {
    const auto& v = need(o, key, at);
    if (!v.is_number()) throw std::invalid_argument(at + "/" + key + ": expected a number");
    return v.get<double>();
  };
  if (!j.is_object() || j.value("format", "") != "benchscope-lens")
    throw std::invalid_argument("/format: not a BenchScope lens file");
  const auto& l = need(j, "lens", "");
  const auto& v = need(j, "view", "");
  Lens lens;
  const auto& model = need(l, "model", "/lens");
  if (!model.is_string()) throw std::invalid_argument("/lens/model: expected a string");
  lens.type = lens_type_from_string(model.get<std::string>());
  lens.r_pp = number(l, "r_pp", "/lens");
  if (l.contains("k")) {
    if (!l["k"].is_array() || l["k"].size() != 4) throw std::invalid_argument("/lens/k: expected 4 numbers");
    for (int i = 0; i < 4; ++i) lens.k[static_cast<std::size_t>(i)] = l["k"][static_cast<std::size_t>(i)].get<double>();
  }
  lens.cx = number(l, "cx", "/lens");
  lens.cy = number(l, "cy", "/lens");
  lens.fov_deg = number(l, "fov_deg", "/lens");
  lens.width = static_cast<int>(number(l, "width", "/lens"));
  lens.height = static_cast<int>(number(l, "height", "/lens"));
  if (l.contains("calibration")) lens.calibration = calibration_from_json(l["calibration"]);
  View view;
  view.width = static_cast<int>(number(v, "width", "/view"));
  view.height = static_cast<int>(number(v, "height", "/view"));
  view.fov_deg = number(v, "fov_deg", "/view");
  view.yaw_deg = number(v, "yaw_deg", "/view");
  view.pitch_deg = number(v, "pitch_deg", "/view");
  view.roll_deg = number(v, "roll_deg", "/view");
  lens.validate();
  view.validate();
  return {lens, view};
}

std::optional<cv::Point2d> source_of(const Lens& lens, const View& view, double x, double y) {
  // Screen-centred output coordinates, +y up.
  const double sx = x - (view.width - 1) / 2.0;
  const double sy = (view.height - 1) / 2.0 - y;
  cv::Vec3d v(view.focal_px(), sx, sy);
  v = view_rotation(view) * (v / cv::norm(v));
  const double theta = std::acos(std::clamp(v[0], -1.0, 1.0));
  const auto r = lens.radius(theta);
  if (!r) return std::nullopt;
  // v_out = r(theta) * v_yz / |v_yz| (paper: alpha = theta / (r_pp sin theta), |v_yz| = sin theta); (0, 0) at theta 0.
  const double len = std::hypot(v[1], v[2]);
  const double ox = len > 0 ? *r * v[1] / len : 0.0, oy = len > 0 ? *r * v[2] / len : 0.0;
  const cv::Point2d c = lens.centre();
  const cv::Point2d src(c.x + ox, c.y - oy);  // screen +y up -> image rows grow downwards
  if (src.x < 0 || src.y < 0 || src.x > lens.width - 1 || src.y > lens.height - 1) return std::nullopt;
  return src;
}

cv::Mat build_reprojection_map(const Lens& lens, const View& view) {
  lens.validate();
  view.validate();
  cv::Mat map(view.height, view.width, CV_32FC2);
#pragma omp parallel for schedule(static)
  for (int y = 0; y < view.height; ++y) {
    auto* row = map.ptr<cv::Vec2f>(y);
    for (int x = 0; x < view.width; ++x) {
      const auto s = source_of(lens, view, x, y);
      row[x] = s ? cv::Vec2f(static_cast<float>(s->x), static_cast<float>(s->y)) : cv::Vec2f(-1, -1);
    }
  }
  return map;
}

cv::Mat reproject(const cv::Mat& src, const cv::Mat& map, const cv::Mat& mask, const cv::Scalar& fill) {
  if (map.type() != CV_32FC2) throw std::invalid_argument("reproject needs a CV_32FC2 map");
  if (!mask.empty() && (mask.size() != src.size() || mask.type() != CV_8UC1))
    throw std::invalid_argument("the mask must be CV_8UC1 and as large as the source image");
  cv::Mat out;
  cv::remap(src, out, map, cv::noArray(), cv::INTER_LINEAR, cv::BORDER_CONSTANT, fill);
  if (!mask.empty()) {
    // A masked source pixel (the robot's own body) must not bleed into the view: fill every output sampling it.
    cv::Mat masked;
    cv::remap(mask, masked, map, cv::noArray(), cv::INTER_NEAREST, cv::BORDER_CONSTANT, cv::Scalar(0));
    out.setTo(fill, masked);
  }
  return out;
}

ReprojectionLut::ReprojectionLut(const Lens& lens, const View& view)
    : map_(build_reprojection_map(lens, view)), source_(lens.width, lens.height) {
  cv::convertMaps(map_, cv::noArray(), fixed_xy_, fixed_fraction_, CV_16SC2);
}

cv::Mat ReprojectionLut::apply(const cv::Mat& src, const cv::Mat& mask, const cv::Scalar& fill) const {
  if (src.size() != source_)
    throw std::invalid_argument("the source image is " + std::to_string(src.cols) + "x" + std::to_string(src.rows) +
                                " but the lens is " + std::to_string(source_.width) + "x" +
                                std::to_string(source_.height));
  if (!mask.empty() && (mask.size() != src.size() || mask.type() != CV_8UC1))
    throw std::invalid_argument("the mask must be CV_8UC1 and as large as the source image");
  cv::Mat out;
  cv::remap(src, out, fixed_xy_, fixed_fraction_, cv::INTER_LINEAR, cv::BORDER_CONSTANT, fill);
  if (!mask.empty()) {
    cv::Mat masked;
    cv::remap(mask, masked, map_, cv::noArray(), cv::INTER_NEAREST, cv::BORDER_CONSTANT, cv::Scalar(0));
    out.setTo(fill, masked);
  }
  return out;
}

}  // namespace bs::vision
