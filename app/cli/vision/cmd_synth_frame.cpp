// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli synth-frame: a synthetic capture with ground truth, to check a lens setup or feed the tests.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "common/args.h"
#include "common/command.h"
#include "image_files/image_files.h"
#include "model/raw_sidecar.h"
#include "vision/frames/synthetic.h"
#include "vision/frames/synthetic_room.h"
#include "vision/lens/line_fit.h"
#include "vision/synth_checkerboard.h"

namespace bs::cli {
namespace {

// Each 3D segment sampled at 1/48 steps, projected through the lens; runs of >= 6 points inside FOV and sensor.
std::vector<vision::PickedLine> room_lines_in_image(const vision::Lens& lens,
                                                    const std::vector<vision::Segment3d>& segs) {
  std::vector<vision::PickedLine> out;
  const cv::Point2d c = lens.centre();
  for (const auto& seg : segs) {
    vision::PickedLine run;
    for (int i = 1; i <= 48; ++i) {
      const cv::Vec3d v = seg.a * (1 - i / 49.0) + seg.b * (i / 49.0);
      const cv::Vec3d u = v / cv::norm(v);
      const auto r = lens.radius(std::acos(std::clamp(u[0], -1.0, 1.0)));
      const double len = std::hypot(u[1], u[2]);
      const cv::Point2d p =
          r && len > 0 ? cv::Point2d(c.x + *r * u[1] / len, c.y - *r * u[2] / len) : cv::Point2d(-1, -1);
      if (p.x >= 0 && p.y >= 0 && p.x <= lens.width - 1 && p.y <= lens.height - 1) {
        run.push_back(p);
        continue;
      }
      if (run.size() >= 6) out.push_back(run);
      run.clear();
    }
    if (run.size() >= 6) out.push_back(run);
  }
  return out;
}

int run_synth(const std::vector<std::string>& raw_args, std::ostream& out) {
  std::set<std::string> valued = {"--lens", "--size", "--pattern", "--bits", "--out", "--scene", "--vignetting"};
  valued.insert(kCheckerboardSceneOptions.begin(), kCheckerboardSceneOptions.end());
  const ParsedArgs args = parse_args(raw_args, {}, valued);
  const auto prefix = args.value("--out");
  if (!prefix) throw UsageError("--out PREFIX is required");
  vision::Lens lens = vision::Lens::paper();
  vision::View view;
  const std::string lens_arg = args.value("--lens").value_or("paper");
  if (lens_arg != "paper") {
    std::ifstream f(lens_arg);
    if (!f) throw std::runtime_error(lens_arg + ": cannot open lens file");
    try {
      std::tie(lens, view) = vision::lens_from_json(nlohmann::json::parse(f));
    } catch (const std::exception& e) {
      throw std::runtime_error(lens_arg + ": " + e.what());
    }
  }
  if (const auto size = args.value("--size")) {
    int w = 0, h = 0;
    if (std::sscanf(size->c_str(), "%dx%d", &w, &h) != 2 || w < 8 || h < 8 || w > 16384 || h > 16384)
      throw UsageError("--size expects WxH between 8x8 and 16384x16384, e.g. 1280x1024");
    lens.r_pp *= static_cast<double>(lens.width) / w;  // keep the lens's field of view across the new width
    lens.width = w;
    lens.height = h;
  }
  const int bits = static_cast<int>(args.number("--bits", 8));
  if (bits != 8 && bits != 10 && bits != 12 && bits != 16) throw UsageError("--bits must be 8, 10, 12 or 16");
  const std::string scene = args.value("--scene").value_or("chart");
  if (scene == "checkerboard") {
    if (args.value("--pattern")) throw UsageError("--pattern is for the Bayer chart; the checkerboard views are grey");
    return synth_checkerboard(args, lens, view, *prefix, bits, out);
  }
  if (scene != "chart" && scene != "room") throw UsageError("--scene must be chart, room or checkerboard");
  // --noise and --seed shape the room scene too; the rest are the checkerboard's alone.
  for (const auto& o : kCheckerboardSceneOptions)
    if (args.value(o) && o != "--noise" && o != "--seed") throw UsageError(o + " belongs to --scene checkerboard");
  if (scene == "chart" && (args.value("--noise") || args.value("--seed") || args.value("--vignetting")))
    throw UsageError("--noise, --seed and --vignetting are for --scene room or checkerboard");
  vision::BayerPattern pattern;
  try {
    pattern = vision::bayer_pattern_from_string(args.value("--pattern").value_or("BGGR"));
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  vision::RoomOptions room;
  room.bits = bits;
  room.vignetting = args.number("--vignetting", 0);
  room.noise = args.number("--noise", 0);
  room.seed = static_cast<std::uint64_t>(args.number("--seed", 1));
  if (room.vignetting < 0 || room.vignetting >= 1) throw UsageError("--vignetting must be in [0, 1)");
  if (room.noise < 0 || room.noise > 0.5) throw UsageError("--noise must be in [0, 0.5] (a fraction of full scale)");
  if (scene == "chart" && (args.value("--vignetting") || args.value("--noise") || args.value("--seed")))
    throw UsageError("--vignetting, --noise and --seed apply to --scene room");
  const cv::Mat truth = scene == "room" ? vision::render_room_fisheye(lens, room) : vision::render_fisheye(lens, bits);
  const cv::Mat raw = vision::mosaic(truth, pattern);
  const std::filesystem::path parent = std::filesystem::path(*prefix).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  const std::string raw_path = *prefix + ".raw", json_path = *prefix + ".json", png_path = *prefix + "-truth.png";
  {
    std::ofstream f(raw_path, std::ios::binary);
    // Row-major samples, 1 byte (8-bit) or 2 bytes little-endian (more bits, values in the low bits).
    f.write(reinterpret_cast<const char*>(raw.data), static_cast<std::streamsize>(raw.total() * raw.elemSize()));
    if (!f) throw std::runtime_error(raw_path + ": write failed");
  }
  RawSidecar sidecar;
  sidecar.width = raw.cols;
  sidecar.height = raw.rows;
  sidecar.pattern = std::string(vision::to_string(pattern));
  sidecar.bit_depth = bits;
  sidecar.big_endian = std::endian::native == std::endian::big;  // the samples were written in this host's order
  sidecar.synthetic = true;
  sidecar.truth = png_path;
  sidecar.lens_json = vision::lens_to_json(lens, view).dump();
  std::ofstream(json_path) << raw_sidecar_to_json(sidecar).dump(2) << '\n';
  if (!bs::image_files::write(png_path, truth)) throw std::runtime_error(png_path + ": cannot write PNG");
  if (scene == "room") {
    // The room's grid lines as a user would pick them (true positions, every 1/48 of a wall), for refine-lines.
    const auto lines = room_lines_in_image(lens, vision::room_grid_lines(vision::room_yaw(room.seed)));
    vision::save_lines_json(lines, lens.width, lens.height, *prefix + "-lines.json");
    out << "wrote " << *prefix << "-lines.json (" << lines.size() << " grid lines straight in 3D, source pixels)\n";
  }
  out << "wrote " << raw_path << " (" << raw.cols << "x" << raw.rows << " " << vision::to_string(pattern) << ", "
      << bits << "-bit), " << json_path << ", " << png_path << '\n';
  return 0;
}

const CommandRegistrar registrar({
    "synth-frame",
    "render a synthetic Bayer capture of a test chart through a lens, with ground truth",
    "usage: benchscope-cli synth-frame --out PREFIX [--lens paper|LENS.json] [--size WxH] [--pattern "
    "BGGR|RGGB|GRBG|GBRG]\n"
    "         [--bits 8|10|12|16] [--scene chart|room] [--vignetting V] [--noise SIGMA] [--seed N]\n"
    "       benchscope-cli synth-frame --scene checkerboard --out PREFIX [--lens paper|LENS.json] [--size WxH]\n"
    "         [--board COLSxROWS] [--square MM] (--pose RX,RY,RZ,TX,TY,TZ[;...] | --poses FILE) [--bits 8|10|12|16]\n"
    "         [--noise SIGMA] [--blur PX] [--supersample N] [--seed S]\n"
    "  Writes PREFIX.raw (row-major samples; 16-bit little-endian above 8 bits), PREFIX.json (sidecar: size, pattern,\n"
    "  bit depth, endianness, lens, synthetic: true) and PREFIX-truth.png (the ground-truth colour image).\n"
    "  --scene chart (default): a flat test chart in front of the camera. --scene room: the inside of a room whose\n"
    "  walls carry a grid of dark lines (straight in 3D) and dark objects, lit all round, so the whole image circle\n"
    "  is lit and dark lines reach its rim; --vignetting V (fraction of brightness lost at the rim, 0..1), --noise\n"
    "  SIGMA (Gaussian, fraction of full scale) and --seed N (camera yaw in the room and noise) shape it; the\n"
    "  truth PNG then holds the capture with vignetting and noise, and PREFIX-lines.json the grid lines' true\n"
    "  image points (for lens refine-lines).\n"
    "  --scene checkerboard: a board of COLSxROWS squares (default 10x7) of MM millimetres (default 30) at each pose\n"
    "  (rotation in degrees, R = Rz Ry Rx; the board centre's position in mm; camera frame x forward, y right, z up;\n"
    "  a poses file has one pose per line), ray-traced through the lens with NxN samples per pixel (default 4):\n"
    "  PREFIX-01.png... (grey), PREFIX.json (ground truth). --noise here: Gaussian noise in grey levels; --blur:\n"
    "  sigma, px.",
    out_only<run_synth>,
});

}  // namespace
}  // namespace bs::cli
