// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli lens: the reprojection tuner's headless side. Detect the image circle of a fisheye frame and
// propose principal point + r_pp, export a lookup table, measure a straight line's residual, propose long edges
// that are candidates for world-straight lines and fit the lens to them.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "common/args.h"
#include "common/command.h"
#include "common/import_error.h"
#include "common/subcommand.h"
#include "image_files/image_files.h"
#include "vision/frames/frame_image.h"
#include "vision/lens/circle_detect.h"
#include "vision/lens/edge_proposals.h"
#include "vision/lens/lens_limits.h"
#include "vision/lens/line_fit.h"
#include "vision/lens/straight_line.h"
#include "vision/lens/tuner_state.h"
#include "vision/lens_calibrate.h"
#include "vision/reproject/triptych.h"
#include "workspace/registry.h"

namespace bs::cli {
namespace {

vision::TunerParams load_params(const std::optional<std::string>& path) {
  if (!path) return {};
  return vision::load_tuner_json(*path);
}

// A fisheye image as 8-bit BGR: an image file OpenCV reads, or a capture BenchScope imports (a .raw with its
// sidecar, PGM/PPM...), demosaiced. `recorded` gets the lens recorded with a capture, when it has one.
cv::Mat read_fisheye(const std::string& path, std::optional<vision::Lens>* recorded = nullptr) {
  cv::Mat image = bs::image_files::read(path, cv::IMREAD_ANYDEPTH | cv::IMREAD_COLOR);
  if (!image.empty()) return image;
  ImportBatch batch;
  try {
    batch = import_file(path, CancelToken{});
  } catch (const ImportError& e) {
    throw std::runtime_error(
        path + ": cannot read the image (not an image file OpenCV reads, and as a capture: " + e.reason() + ")");
  }
  if (batch.frames.empty()) throw std::runtime_error(path + ": holds no frame (" + batch.format + ")");
  const Frame& frame = batch.frames.front();
  const cv::Mat raw = vision::frame_to_mat(frame);
  const cv::Mat rgb = vision::demosaic_frame(raw, frame, vision::DemosaicMethod::Bilinear);
  if (recorded) {
    const vision::FrameLens fl = vision::lens_for_frame(frame);
    if (fl.from_frame) *recorded = fl.lens;
  }
  return vision::window_to_8bit(rgb, 0, vision::full_scale(frame));
}

int lens_circle(const std::vector<std::string>& raw, std::ostream& out) {
  const ParsedArgs args = parse_args(raw, {}, {"--lens", "--min-level", "--out", "--circle-fov"});
  if (args.positional.size() != 1)
    throw UsageError("lens circle needs one IMAGE (PNG, JPEG, TIFF..., or a .raw capture with its sidecar)");
  const std::string image_path = args.positional[0];
  std::optional<vision::Lens> recorded;
  const cv::Mat image = read_fisheye(image_path, &recorded);
  vision::TunerParams p = load_params(args.value("--lens"));
  if (!args.value("--lens") && recorded) p.lens = *recorded;  // the capture's own lens is the starting point
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
  // As the Lens tab's Detect circle: a proposal more than 2 % off the capture's recorded lens says so.
  if (recorded && recorded->r_pp > 0) {
    const double off = std::abs(p.lens.r_pp - recorded->r_pp) / recorded->r_pp;
    if (off > 0.02) {
      std::snprintf(line, sizeof line,
                    "warning: the proposed r_pp %.7f rad/px is %.1f %% off the lens recorded with the capture (%.7f "
                    "rad/px): the visible disc may span less than the lens FOV; give it with --circle-fov DEG\n",
                    p.lens.r_pp, off * 100, recorded->r_pp);
      out << line;
    }
  }
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

cv::Mat read_image(const std::string& path) { return read_fisheye(path); }

// Proposals in `image` under `lens` (its size must match the image's: the lens was calibrated on that sensor).
vision::LineProposals propose_in(const cv::Mat& image, const vision::Lens& lens, const std::string& image_path,
                                 const ParsedArgs& args) {
  if (lens.width != image.cols || lens.height != image.rows)
    throw std::runtime_error(image_path + ": " + std::to_string(image.cols) + "x" + std::to_string(image.rows) +
                             " px, but the lens is for " + std::to_string(lens.width) + "x" +
                             std::to_string(lens.height) + " px images");
  vision::LineProposalOptions o;
  o.min_length_px = args.number("--min-length", o.min_length_px);
  o.max_bend_px = args.number("--max-bend", o.max_bend_px);
  o.max_lines = static_cast<int>(args.number("--max-lines", o.max_lines));
  if (o.min_length_px < 0) throw UsageError("--min-length must be >= 0 pixels");
  if (o.max_bend_px < 0) throw UsageError("--max-bend must be >= 0 pixels");
  return vision::propose_lines(image, lens, o);
}

int lens_propose_lines(const std::vector<std::string>& raw, std::ostream& out) {
  const ParsedArgs args = parse_args(raw, {"--json"}, {"--lens", "--out", "--min-length", "--max-bend", "--max-lines"});
  if (args.positional.size() != 1) throw UsageError("lens propose-lines needs one IMAGE (PNG, JPEG, TIFF...)");
  const auto lens_path = args.value("--lens");
  if (!lens_path) throw UsageError("lens propose-lines needs --lens LENS.json (the current lens estimate)");
  const std::string image_path = args.positional[0];
  const cv::Mat image = read_image(image_path);
  const vision::TunerParams p = vision::load_tuner_json(*lens_path);
  const auto proposals = propose_in(image, p.lens, image_path, args);
  const auto lines = vision::proposal_points(proposals);
  if (args.has("--json")) {
    nlohmann::json j = vision::lines_to_json(lines, image.cols, image.rows);
    nlohmann::json stats = nlohmann::json::array();
    for (const auto& l : proposals.lines)
      stats.push_back({{"length_px", l.length_px},
                       {"rms_px", l.rms_px},
                       {"bend_px", l.bend_px},
                       {"edge_pixels", l.edge_pixels},
                       {"outliers", l.outliers}});
    j["proposals"] = stats;
    j["edge_pixels"] = proposals.edge_pixels;
    j["rejected_bent"] = proposals.rejected_bent;
    j["rejected_short"] = proposals.rejected_short;
    out << j.dump(2) << '\n';
  } else {
    char text[256];
    std::snprintf(text, sizeof text,
                  "%zu proposed lines from %d edge pixels (%d rejected as bent, %d as short or rough)\n",
                  proposals.lines.size(), proposals.edge_pixels, proposals.rejected_bent, proposals.rejected_short);
    out << text;
    for (std::size_t i = 0; i < proposals.lines.size(); ++i) {
      const auto& l = proposals.lines[i];
      std::snprintf(text, sizeof text,
                    "line %zu: %zu points, %.0f px long, (%.1f, %.1f) -> (%.1f, %.1f), RMS %.3f px, bend %.2f px, "
                    "%d outliers dropped\n",
                    i + 1, l.points.size(), l.length_px, l.points.front().x, l.points.front().y, l.points.back().x,
                    l.points.back().y, l.rms_px, l.bend_px, l.outliers);
      out << text;
    }
  }
  if (const auto o = args.value("--out")) {
    vision::save_lines_json(lines, image.cols, image.rows, *o);
    if (!args.has("--json")) out << "wrote " << *o << '\n';
  }
  return 0;
}

int lens_refine_lines(const std::vector<std::string>& raw, std::ostream& out) {
  const ParsedArgs args = parse_args(raw, {},
                                     {"--out", "--circle-radius", "--fix", "--propose", "--min-length", "--max-bend",
                                      "--max-lines", "--reject-lines"});
  const auto propose = args.value("--propose");
  if (propose ? args.positional.size() != 1 : args.positional.size() != 2)
    throw UsageError("lens refine-lines needs LENS.json and LINES.json, or LENS.json --propose IMAGE");
  if (!propose)
    for (const char* o : {"--min-length", "--max-bend", "--max-lines"})
      if (args.value(o)) throw UsageError(std::string(o) + " is for --propose");
  const std::string lens_path = args.positional[0];
  const std::string lines_path = propose ? *propose : args.positional[1];
  vision::TunerParams p = vision::load_tuner_json(lens_path);
  std::vector<vision::PickedLine> lines;
  if (propose) {
    // The proposals under the lens file's lens, instead of clicked points.
    const auto proposals = propose_in(read_image(*propose), p.lens, *propose, args);
    lines = vision::proposal_points(proposals);
    out << "proposed " << lines.size() << " lines in " << *propose << '\n';
  } else {
    lines = vision::load_lines_json(lines_path);
  }
  vision::LineFitOptions options;
  options.circle_radius_px = args.number("--circle-radius", 0);
  if (options.circle_radius_px < 0) throw UsageError("--circle-radius must be > 0 pixels");
  // Proposals always hold a few edges that are no lines of the world (line_fit.h): rejected by default there.
  options.reject_lines = args.number("--reject-lines", propose ? 3 : 0);
  if (options.reject_lines < 0) throw UsageError("--reject-lines must be >= 0 (0: keep every line)");
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
  if (!fit.rejected_lines.empty()) {
    out << fit.rejected_lines.size() << " line(s) left out (straightness RMS over " << options.reject_lines
        << "x the median line's under the fitted lens):";
    for (const int i : fit.rejected_lines) out << ' ' << i + 1;
    out << '\n';
  }
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
  // Issue #43.8: the view against the angle a checkerboard's corners covered.
  if (const std::string note = vision::extrapolation_note(l, p.view); !note.empty()) out << "warning: " << note << '\n';
  return 0;
}

const CommandRegistrar registrar({
    "lens",
    "lens calibration helpers (lens circle | lens calibrate | lens refine-lines | lens propose-lines | lens show | "
    "lens export-lut | lens line)",
    "usage: benchscope-cli lens circle IMAGE [--lens LENS.json] [--min-level L] [--circle-fov DEG] [--out LENS.json]\n"
    "       benchscope-cli lens calibrate IMAGE... --board COLSxROWS --square MM --out LENS.json\n"
    "         [--model kannala-brandt|equidistant] [--lens BASE.json] [--fov DEG]\n"
    "       benchscope-cli lens refine-lines LENS.json (LINES.json | --propose IMAGE) [--out LENS.json]\n"
    "         [--circle-radius PX] [--fix r_pp,cx,cy,centre,k1,k2,k3,k4] [--reject-lines F]\n"
    "       benchscope-cli lens propose-lines IMAGE --lens LENS.json [--json] [--out LINES.json] [--min-length PX]\n"
    "         [--max-bend PX] [--max-lines N]\n"
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
    "  circle's rim (the start lens's, or --circle-radius) and the --fix'ed parameters; --propose IMAGE fits to the\n"
    "  lines propose-lines finds in IMAGE instead (its options apply); --reject-lines F leaves out lines straight\n"
    "  to worse than F times the median line (default 3 with --propose, else 0: none); propose-lines: long\n"
    "  edges of IMAGE that are straight in the world to within --max-bend pixels (default 6) under the LENS.json\n"
    "  lens, at least --min-length pixels long (default 80), the --max-lines longest (default 80), printed or as\n"
    "  JSON (the lines file plus per-line statistics), --out writes the lines file; show: the lens and how it was\n"
    "  obtained; export-lut: writes the view's lookup table (docs/lut-format.md); line: RMS and max distance in\n"
    "  pixels of clicked points from their best-fit straight line.",
    [](const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
      return run_subcommand("lens",
                            {{"circle", out_only<lens_circle>},
                             {"calibrate", lens_calibrate},
                             {"refine-lines", out_only<lens_refine_lines>},
                             {"propose-lines", out_only<lens_propose_lines>},
                             {"show", out_only<lens_show>},
                             {"export-lut", out_only<lens_export_lut>},
                             {"line", out_only<lens_line>}},
                            args, out, err);
    },
});

}  // namespace
}  // namespace bs::cli
