// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli lens: the reprojection tuner's headless side. Detect the image circle of a fisheye frame and
// propose principal point + r_pp, export a lookup table, measure a straight line's residual.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "args.h"
#include "command.h"
#include "lens_calibrate.h"
#include "vision/circle_detect.h"
#include "vision/straight_line.h"
#include "vision/tuner_state.h"

namespace bs::cli {
namespace {

vision::TunerParams load_params(const std::optional<std::string>& path) {
  if (!path) return {};
  return vision::load_tuner_json(*path);
}

int lens_circle(const std::vector<std::string>& raw, std::ostream& out) {
  const ParsedArgs args = parse_args(raw, {}, {"--lens", "--min-level", "--out", "--circle-fov"});
  if (args.positional.size() != 1) throw UsageError("lens circle needs one IMAGE (PNG, JPEG, TIFF...)");
  const std::string image_path = args.positional[0];
  const cv::Mat image = cv::imread(image_path, cv::IMREAD_ANYDEPTH | cv::IMREAD_COLOR);
  if (image.empty()) throw std::runtime_error(image_path + ": cannot read the image");
  vision::TunerParams p = load_params(args.value("--lens"));
  p.lens.width = image.cols;
  p.lens.height = image.rows;
  const auto circle = vision::detect_image_circle(image, args.number("--min-level", 20));
  if (!circle) throw std::runtime_error(image_path + ": no image circle found (no bright disc above the threshold)");
  const double circle_fov = args.number("--circle-fov", 0);
  if (circle_fov < 0 || circle_fov > 360) throw UsageError("--circle-fov must be in (0, 360] degrees");
  p.lens = vision::propose_lens(p.lens, *circle, circle_fov);
  char line[256];
  std::snprintf(line, sizeof line,
                "image circle: centre (%.2f, %.2f) px, radius %.2f px (fit RMS %.3f px over %d edge points)\n"
                "proposed %s lens: principal point (%.2f, %.2f) px, r_pp %.6g rad/px (focal %.2f px) for %.1f deg FOV\n",
                circle->centre.x, circle->centre.y, circle->radius, circle->rms_px, circle->edge_points,
                std::string(vision::to_string(p.lens.type)).c_str(), p.lens.cx, p.lens.cy, p.lens.r_pp,
                1 / p.lens.r_pp, p.lens.fov_deg);
  out << line;
  if (const auto o = args.value("--out")) {
    vision::save_tuner_json(p, *o);
    out << "wrote " << *o << '\n';
  }
  return 0;
}

int lens_export_lut(const std::vector<std::string>& raw, std::ostream& out) {
  const ParsedArgs args = parse_args(raw, {}, {"--lens"});
  if (args.positional.size() != 1) throw UsageError("lens export-lut needs the OUTPUT path");
  const vision::TunerParams p = load_params(args.value("--lens"));
  const cv::Mat map = vision::build_reprojection_map(p.lens, p.view);
  vision::export_lut(map, p, args.positional[0]);
  out << "wrote " << args.positional[0] << ": " << map.cols << "x" << map.rows
      << " float32 (x, y) source positions (docs/lut-format.md)\n";
  return 0;
}

int lens_line(const std::vector<std::string>& raw, std::ostream& out) {
  // Points as "x,y" arguments in output-image pixels.
  const ParsedArgs args = parse_args(raw, {}, {});
  std::vector<cv::Point2d> pts;
  for (const auto& s : args.positional) {
    double x = 0, y = 0;
    char extra = 0;
    if (std::sscanf(s.c_str(), "%lf,%lf%c", &x, &y, &extra) != 2) throw UsageError("point '" + s + "': expected X,Y");
    pts.emplace_back(x, y);
  }
  try {
    const auto r = vision::line_residual(pts);
    char line[160];
    std::snprintf(line, sizeof line, "straight-line residual over %d points: RMS %.3f px, max %.3f px\n", r.points,
                  r.rms_px, r.max_px);
    out << line;
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  return 0;
}

const CommandRegistrar registrar({
    "lens",
    "lens calibration helpers (lens circle | lens calibrate | lens export-lut | lens line)",
    "usage: benchscope-cli lens circle IMAGE [--lens LENS.json] [--min-level L] [--circle-fov DEG] [--out LENS.json]\n"
    "       benchscope-cli lens calibrate IMAGE... --board COLSxROWS --square MM --out LENS.json\n"
    "         [--model kannala-brandt|equidistant] [--lens BASE.json] [--fov DEG]\n"
    "       benchscope-cli lens export-lut OUT.bslut [--lens LENS.json]\n"
    "       benchscope-cli lens line X,Y X,Y X,Y...\n"
    "  circle: detects the fisheye image circle and proposes principal point and r_pp for the lens model\n"
    "  (default the paper's lens); export-lut: writes the view's lookup table (docs/lut-format.md); line: RMS and\n"
    "  max distance in pixels of clicked points from their best-fit straight line.\n"
    "  calibrate: checkerboard calibration with OpenCV (findChessboardCornersSB, cv::fisheye); COLSxROWS counts\n"
    "  squares (10x7 squares = 9x6 inner corners); prints each image's RMS reprojection error or why it was\n"
    "  rejected; the field of view (not measured by a board) comes from --fov or the --lens file (default 195).",
    [](const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
      const std::vector<std::string> rest(args.empty() ? args.end() : args.begin() + 1, args.end());
      if (!args.empty() && args[0] == "circle") return lens_circle(rest, out);
      if (!args.empty() && args[0] == "calibrate") return lens_calibrate(rest, out, err);
      if (!args.empty() && args[0] == "export-lut") return lens_export_lut(rest, out);
      if (!args.empty() && args[0] == "line") return lens_line(rest, out);
      throw UsageError("expected 'lens circle', 'lens calibrate', 'lens export-lut' or 'lens line'");
    },
});

}  // namespace
}  // namespace bs::cli
