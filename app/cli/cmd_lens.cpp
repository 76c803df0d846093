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
#include "vision/line_fit.h"
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
  std::snprintf(
      line, sizeof line,
      "image circle: centre (%.2f, %.2f) px, radius %.2f px (fit RMS %.3f px over %d edge points)\n"
      "proposed %s lens: principal point (%.2f, %.2f) px, r_pp %.6g rad/px (focal %.2f px) for %.1f deg FOV\n",
      circle->centre.x, circle->centre.y, circle->radius, circle->rms_px, circle->edge_points,
      std::string(vision::to_string(p.lens.type)).c_str(), p.lens.cx, p.lens.cy, p.lens.r_pp, 1 / p.lens.r_pp,
      p.lens.fov_deg);
  out << line << "calibration: " << vision::describe(p.lens.calibration) << '\n';
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

int lens_refine_lines(const std::vector<std::string>& raw, std::ostream& out) {
  const ParsedArgs args = parse_args(raw, {}, {"--out", "--circle-radius", "--fix"});
  if (args.positional.size() != 2) throw UsageError("lens refine-lines needs LENS.json and LINES.json");
  const std::string lens_path = args.positional[0], lines_path = args.positional[1];
  vision::TunerParams p = vision::load_tuner_json(lens_path);
  const auto lines = vision::load_lines_json(lines_path);
  vision::LineFitOptions options;
  options.circle_radius_px = args.number("--circle-radius", 0);
  if (options.circle_radius_px < 0) throw UsageError("--circle-radius must be > 0 pixels");
  if (const auto fix = args.value("--fix")) {
    try {
      options.fixed = vision::fixed_parameters_from_string(*fix);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--fix: ") + e.what());
    }
  }
  vision::LineFitResult fit;
  try {
    fit = vision::fit_lens_to_lines(p.lens, lines, options);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(lines_path + ": " + e.what());
  }
  const auto& l = fit.lens;
  char text[512];
  std::snprintf(text, sizeof text,
                "%d lines, %d points; straightness RMS %.3f px before, %.3f px after (max %.3f -> %.3f px; distance "
                "of the points from their fitted lines' image curves, source pixels), %d iterations\n"
                "kannala-brandt lens: principal point (%.2f, %.2f) px, r_pp %.6g rad/px (focal %.2f px), "
                "k = (%.5g, %.5g, %.5g, %.5g)\n",
                fit.after.lines, fit.after.points, fit.before.rms_px, fit.after.rms_px, fit.before.max_px,
                fit.after.max_px, fit.iterations, l.cx, l.cy, l.r_pp, 1 / l.r_pp, l.k[0], l.k[1], l.k[2], l.k[3]);
  out << text << "calibration: " << vision::describe(l.calibration) << '\n';
  p.lens = l;
  if (const auto o = args.value("--out")) {
    vision::save_tuner_json(p, *o);
    out << "wrote " << *o << '\n';
  }
  return 0;
}

int lens_show(const std::vector<std::string>& raw, std::ostream& out) {
  const ParsedArgs args = parse_args(raw, {}, {});
  if (args.positional.size() != 1) throw UsageError("lens show needs one LENS.json");
  const vision::TunerParams p = vision::load_tuner_json(args.positional[0]);
  const auto& l = p.lens;
  const cv::Point2d c = l.centre();
  char text[512];
  std::snprintf(text, sizeof text,
                "%s lens, %dx%d px source, %.1f deg FOV: principal point (%.2f, %.2f) px, r_pp %.6g rad/px (focal "
                "%.2f px), k = (%.5g, %.5g, %.5g, %.5g)\nview: %dx%d px, %.1f deg FOV, yaw %.1f, pitch %.1f, roll "
                "%.1f deg; %zu mask polygon(s)\n",
                std::string(vision::to_string(l.type)).c_str(), l.width, l.height, l.fov_deg, c.x, c.y, l.r_pp,
                1 / l.r_pp, l.k[0], l.k[1], l.k[2], l.k[3], p.view.width, p.view.height, p.view.fov_deg, p.view.yaw_deg,
                p.view.pitch_deg, p.view.roll_deg, p.masks.size());
  out << text << "calibration: " << vision::describe(l.calibration) << '\n';
  return 0;
}

const CommandRegistrar registrar({
    "lens",
    "lens calibration helpers (lens circle | lens calibrate | lens refine-lines | lens show | lens export-lut | lens "
    "line)",
    "usage: benchscope-cli lens circle IMAGE [--lens LENS.json] [--min-level L] [--circle-fov DEG] [--out LENS.json]\n"
    "       benchscope-cli lens calibrate IMAGE... --board COLSxROWS --square MM --out LENS.json\n"
    "         [--model kannala-brandt|equidistant] [--lens BASE.json] [--fov DEG]\n"
    "       benchscope-cli lens refine-lines LENS.json LINES.json [--out LENS.json] [--circle-radius PX]\n"
    "         [--fix r_pp,cx,cy,centre,k1,k2,k3,k4]\n"
    "       benchscope-cli lens show LENS.json\n"
    "       benchscope-cli lens export-lut OUT.bslut [--lens LENS.json]\n"
    "       benchscope-cli lens line X,Y X,Y X,Y...\n"
    "  circle: detects the fisheye image circle (rim points along rays, robust fit that ignores the sensor's cut\n"
    "  and dark objects at the rim) and proposes principal point and r_pp for the lens model (default the paper's\n"
    "  lens); calibrate: checkerboard calibration with OpenCV (findChessboardCornersSB, cv::fisheye); COLSxROWS\n"
    "  counts squares (10x7 squares = 9x6 inner corners); prints each image's RMS reprojection error or why it was\n"
    "  rejected; the field of view (not measured by a board) comes from --fov or the --lens file (default 195);\n"
    "  refine-lines: fits a Kannala-Brandt lens (r_pp, principal point, k1..k4) so that the points of\n"
    "  LINES.json (source pixels along lines straight in the world; docs/cli.md) become straight, keeping the image\n"
    "  circle's rim (the start lens's, or --circle-radius) and the --fix'ed parameters; show: the lens and how it\n"
    "  was obtained; export-lut: writes the view's lookup table (docs/lut-format.md); line: RMS and max distance in\n"
    "  pixels of clicked points from their best-fit straight line.",
    [](const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
      const std::vector<std::string> rest(args.empty() ? args.end() : args.begin() + 1, args.end());
      if (!args.empty() && args[0] == "circle") return lens_circle(rest, out);
      if (!args.empty() && args[0] == "calibrate") return lens_calibrate(rest, out, err);
      if (!args.empty() && args[0] == "export-lut") return lens_export_lut(rest, out);
      if (!args.empty() && args[0] == "line") return lens_line(rest, out);
      if (!args.empty() && args[0] == "refine-lines") return lens_refine_lines(rest, out);
      if (!args.empty() && args[0] == "show") return lens_show(rest, out);
      throw UsageError(
          "expected 'lens circle', 'lens calibrate', 'lens refine-lines', 'lens show', 'lens export-lut' or 'lens "
          "line'");
    },
});

}  // namespace
}  // namespace bs::cli
