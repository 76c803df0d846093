// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/lens_calibrate.h"

#include <cstdio>
#include <filesystem>

#include "common/args.h"
#include "vision/lens/checkerboard_calibration.h"
#include "vision/lens/tuner_state.h"

namespace bs::cli {

int lens_calibrate(const std::vector<std::string>& raw, std::ostream& out, std::ostream& err) {
  const ParsedArgs args = parse_args(raw, {}, {"--board", "--square", "--model", "--lens", "--fov", "--out"});
  if (args.positional.empty()) throw UsageError("lens calibrate needs the checkerboard IMAGES");
  const auto board_arg = args.value("--board");
  const auto square_arg = args.value("--square");
  if (!board_arg || !square_arg) throw UsageError("lens calibrate needs --board COLSxROWS (squares) and --square MM");
  const auto out_path = args.value("--out");
  if (!out_path) throw UsageError("lens calibrate needs --out LENS.json");
  vision::Checkerboard board;
  vision::CalibrationModel model;
  try {
    board = vision::parse_board(*board_arg, args.number("--square", 0));
    model = vision::calibration_model_from_string(args.value("--model").value_or("kannala-brandt"));
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  vision::TunerParams p;
  if (const auto base = args.value("--lens")) p = vision::load_tuner_json(*base);
  if (const auto fov = args.value("--fov")) {
    p.lens.fov_deg = args.number("--fov", 0);
    if (!(p.lens.fov_deg > 0 && p.lens.fov_deg <= 360)) throw UsageError("--fov must be in (0, 360] degrees");
  }

  std::vector<vision::CalibrationImage> images;
  for (const auto& path : args.positional)
    images.push_back({std::filesystem::path(path).filename().string(), path, {}});
  const std::size_t n = images.size();
  std::size_t seen = 0;
  const auto result =
      vision::calibrate_checkerboard(images, board, model, p.lens, nullptr, [&](double, std::string_view step) {
        if (step.rfind("corners: ", 0) == 0) err << "[" << ++seen << "/" << n << "] " << step << '\n';
      });

  char line[512];
  std::size_t name_width = 5;
  for (const auto& r : result.images) name_width = std::max(name_width, r.name.size());
  const int w = static_cast<int>(name_width);
  std::snprintf(line, sizeof line, "%-*s  %8s  %11s\n", w, "image", "RMS (px)", "max angle");
  out << line;
  for (const auto& r : result.images) {
    if (r.used)
      std::snprintf(line, sizeof line, "%-*s  %8.3f  %9.1f deg\n", w, r.name.c_str(), *r.rms_px, r.max_theta_deg);
    else
      std::snprintf(line, sizeof line, "%-*s  rejected: %s\n", w, r.name.c_str(), r.rejected.c_str());
    out << line;
  }
  const auto& l = result.lens;
  std::snprintf(line, sizeof line,
                "%s lens from %d of %zu images: RMS %.3f px\n"
                "  focal %.3f px (r_pp %.8g rad/px), principal point (%.2f, %.2f) px, k %.6g %.6g %.6g %.6g\n"
                "  free fit: fx %.3f px, fy %.3f px (fy/fx %.5f), RMS %.3f px; FOV %.1f deg (not measured by a "
                "checkerboard: from --fov or --lens)\n",
                std::string(vision::to_string(l.type)).c_str(), result.used(), n, result.rms_px, 1 / l.r_pp, l.r_pp,
                l.cx, l.cy, l.k[0], l.k[1], l.k[2], l.k[3], result.fx, result.fy, result.fy / result.fx,
                result.free_rms_px, l.fov_deg);
  out << line;
  // Issue #43.8: where the fit holds (the corners' angle) and how it compares with the images' own rim.
  std::snprintf(line, sizeof line, "  corners up to %.1f deg off the axis (beyond it the model is extrapolated)",
                l.calibration.covered_deg.value_or(result.max_theta_deg));
  out << line;
  if (l.calibration.rim_radius_se_px) {
    std::snprintf(line, sizeof line, "; FOV circle radius SE %.2f px (leave-one-image-out)",
                  *l.calibration.rim_radius_se_px);
    out << line;
  }
  out << '\n';
  if (result.rim) {
    std::snprintf(line, sizeof line,
                  "  FOV circle: radius %.1f px at (%.1f, %.1f); images' rim: radius %.1f px at (%.1f, %.1f)%s\n",
                  result.rim->fitted_radius_px, result.rim->fitted_centre.x, result.rim->fitted_centre.y,
                  result.rim->rim_radius_px, result.rim->rim_centre.x, result.rim->rim_centre.y,
                  result.rim->disagrees ? " (they disagree: see the warning)" : " (they agree)");
    out << line;
  }
  for (const auto& warning : result.warnings) out << "warning: " << warning << '\n';
  p.lens = l;
  vision::save_tuner_json(p, *out_path);
  out << "wrote " << *out_path << '\n';
  return 0;
}

}  // namespace bs::cli
