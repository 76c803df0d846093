// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli frames WORKSPACE [--triptych N --out PREFIX ...]: the workspace's frames, and the paper's Figure 3
// panels of one of them (raw mosaic as grey, demosaiced, reprojected) as PNG, rendered by the same core function
// as the GUI's triptych.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "common/args.h"
#include "common/command.h"
#include "common/text_table.h"
#include "frames/frame_store.h"
#include "image_files/image_files.h"
#include "store/workspace.h"
#include "vision/frames/frame_image.h"
#include "vision/reproject/triptych.h"
#include "vision/workspace_lens.h"
#include "workspace/inputs.h"

namespace bs::cli {
namespace {

int run_frames(const std::vector<std::string>& raw_args, std::ostream& out) {
  const ParsedArgs args = parse_args(raw_args, {}, {"--triptych", "--out", "--method", "--lens", "--window"});
  if (args.positional.size() != 1) throw UsageError("frames needs exactly one workspace");
  const Workspace ws(args.positional[0], Workspace::OpenMode::ReadOnly);
  warn_damage(ws);
  const auto frames = ws.frames();
  if (!args.value("--triptych")) {
    if (frames.empty()) {
      out << "no frames in " << ws.path() << '\n';
      return 0;
    }
    TextTable t({"#", "label", "size (px)", "pattern", "bits", "origin", "storage", "file"});
    for (std::size_t i = 0; i < frames.size(); ++i) {
      const Frame& f = frames[i].frame;
      t.add({std::to_string(i + 1), f.label, std::to_string(f.width) + "x" + std::to_string(f.height),
             f.is_mosaic() ? f.pattern : (f.channels == 3 ? "colour" : "grey"), std::to_string(f.bit_depth),
             f.synthetic ? "synthetic" : "captured", f.storage == FrameStorage::Copy ? "copy" : "reference",
             frames[i].path});
    }
    t.print(out);
    return 0;
  }
  const auto prefix = args.value("--out");
  if (!prefix) throw UsageError("--triptych N needs --out PREFIX");
  const double index = args.number("--triptych", 0);
  if (index < 1 || index > static_cast<double>(frames.size()) || index != static_cast<int>(index))
    throw UsageError("--triptych takes a frame number from 1 to " + std::to_string(frames.size()) +
                     " (see benchscope-cli frames " + args.positional[0] + ")");
  vision::DemosaicMethod method = vision::DemosaicMethod::Bilinear;
  try {
    method = vision::demosaic_method_from_string(args.value("--method").value_or("bilinear"));
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--method: ") + e.what());
  }
  const StoredFrame& stored = frames[static_cast<std::size_t>(index) - 1];
  const Frame frame = load_frame(ws, stored);
  // The lens the GUI would use (saved for the frame or its camera, recorded, the paper's), or --lens FILE.
  vision::ResolvedLens fl = vision::resolve_frame_lens(&ws, stored);
  std::string lens_source = vision::describe_lens_source(fl);
  if (const auto lens_path = args.value("--lens")) {
    std::ifstream f(*lens_path);
    if (!f) throw std::runtime_error(*lens_path + ": cannot open lens file");
    try {
      std::tie(fl.lens, fl.view) = vision::lens_from_json(nlohmann::json::parse(f));
    } catch (const std::exception& e) {
      throw std::runtime_error(*lens_path + ": " + e.what());
    }
    lens_source = "from " + *lens_path;
  }
  double low = 0, high = vision::full_scale(frame);
  if (const auto w = args.value("--window")) {
    if (std::sscanf(w->c_str(), "%lf:%lf", &low, &high) != 2 || !(high > low))
      throw UsageError("--window expects LOW:HIGH in counts, e.g. 0:4095");
  }
  const vision::TriptychImages t = vision::render_triptych(frame, method, fl.lens, fl.view);
  const std::filesystem::path parent = std::filesystem::path(*prefix).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  const std::pair<const char*, const cv::Mat*> panels[] = {
      {"-a-mosaic.png", &t.mosaic}, {"-b-demosaiced.png", &t.demosaiced}, {"-c-reprojected.png", &t.reprojected}};
  for (const auto& [suffix, mat] : panels) {
    const std::string path = *prefix + suffix;
    if (!bs::image_files::write(path, vision::window_to_8bit(*mat, low, high)))
      throw std::runtime_error(path + ": cannot write PNG");
    out << "wrote " << path << " (" << mat->cols << "x" << mat->rows << " px)\n";
  }
  out << "frame " << frame.label << (frame.synthetic ? " (synthetic)" : "") << ", demosaic "
      << vision::to_string(method) << ", lens " << vision::to_string(fl.lens.type) << " " << fl.lens.fov_deg << " deg"
      << " (" << lens_source << ")"
      << ", view " << fl.view.fov_deg << " deg " << fl.view.width << "x" << fl.view.height << " px\n";
  return 0;
}

const CommandRegistrar registrar({
    "frames",
    "list a workspace's frames; write one frame's Figure 3 panels (mosaic, demosaiced, reprojected)",
    "usage: benchscope-cli frames WORKSPACE [--triptych N --out PREFIX [--method bilinear|mhc|opencv]\n"
    "         [--lens LENS.json] [--window LOW:HIGH]]\n"
    "  Without --triptych: one line per frame (size, Bayer pattern, bit depth, synthetic or captured, kept by\n"
    "  reference or copied). With --triptych N: frame N as the paper's Figure 3 panels, PREFIX-a-mosaic.png (raw\n"
    "  mosaic as grey), PREFIX-b-demosaiced.png and PREFIX-c-reprojected.png, through the lens recorded with the\n"
    "  frame (or LENS.json, as the reprojection tuner saves it; else the paper's 195 degree lens and 150 degree "
    "view),\n"
    "  8-bit through the display window (default: the frame's full range).",
    out_only<run_frames>,
});

}  // namespace
}  // namespace bs::cli
