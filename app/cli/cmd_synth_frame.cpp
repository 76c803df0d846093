// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli synth-frame: a synthetic capture with ground truth, to check a lens setup or feed the tests.
#include <bit>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "args.h"
#include "command.h"
#include "model/raw_sidecar.h"
#include "synth_checkerboard.h"
#include "vision/synthetic.h"

namespace bs::cli {
namespace {

int run_synth(const std::vector<std::string>& raw_args, std::ostream& out) {
  std::set<std::string> valued = {"--lens", "--size", "--pattern", "--bits", "--out", "--scene"};
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
  if (scene != "chart") throw UsageError("--scene must be chart or checkerboard");
  for (const auto& o : kCheckerboardSceneOptions)
    if (args.value(o)) throw UsageError(o + " belongs to --scene checkerboard");
  vision::BayerPattern pattern;
  try {
    pattern = vision::bayer_pattern_from_string(args.value("--pattern").value_or("BGGR"));
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  const cv::Mat truth = vision::render_fisheye(lens, bits);
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
  if (!cv::imwrite(png_path, truth)) throw std::runtime_error(png_path + ": cannot write PNG");
  out << "wrote " << raw_path << " (" << raw.cols << "x" << raw.rows << " " << vision::to_string(pattern) << ", "
      << bits << "-bit), " << json_path << ", " << png_path << '\n';
  return 0;
}

const CommandRegistrar registrar({
    "synth-frame",
    "render a synthetic Bayer capture of a test chart through a lens, with ground truth",
    "usage: benchscope-cli synth-frame --out PREFIX [--lens paper|LENS.json] [--size WxH] [--pattern BGGR|RGGB|GRBG|GBRG]\n"
    "         [--bits 8|10|12|16]\n"
    "       benchscope-cli synth-frame --scene checkerboard --out PREFIX [--lens paper|LENS.json] [--size WxH]\n"
    "         [--board COLSxROWS] [--square MM] (--pose RX,RY,RZ,TX,TY,TZ[;...] | --poses FILE) [--bits 8|10|12|16]\n"
    "         [--noise SIGMA] [--blur PX] [--supersample N] [--seed S]\n"
    "  Writes PREFIX.raw (row-major samples; 16-bit little-endian above 8 bits), PREFIX.json (sidecar: size, pattern,\n"
    "  bit depth, endianness, lens, synthetic: true) and PREFIX-truth.png (the ground-truth colour image).\n"
    "  --scene checkerboard: a board of COLSxROWS squares (default 10x7) of MM millimetres (default 30) at each pose\n"
    "  (rotation in degrees, R = Rz Ry Rx; the board centre's position in mm; camera frame x forward, y right, z up;\n"
    "  a poses file has one pose per line), ray-traced through the lens with NxN samples per pixel (default 4):\n"
    "  PREFIX-01.png... (grey), PREFIX.json (ground truth). --noise: Gaussian noise in grey levels; --blur: sigma, px.",
    [](const std::vector<std::string>& args, std::ostream& out, std::ostream& /*err*/) {
      return run_synth(args, out);
    },
});

}  // namespace
}  // namespace bs::cli
