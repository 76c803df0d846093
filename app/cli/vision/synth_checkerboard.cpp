// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/synth_checkerboard.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "image_files/image_files.h"
#include "vision/frames/synthetic_checkerboard.h"

namespace bs::cli {

int synth_checkerboard(const ParsedArgs& args, const vision::Lens& lens, const vision::View& view,
                       const std::string& prefix, int bits, std::ostream& out) {
  vision::CheckerboardRender how;
  how.bits = bits;
  try {
    how.board = vision::parse_board(args.value("--board").value_or("10x7"), args.number("--square", 30));
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--board/--square: ") + e.what());
  }
  std::vector<vision::BoardPose> poses;
  if (const auto file = args.value("--poses")) poses = vision::load_poses(*file);
  if (const auto list = args.value("--pose")) {
    // Several poses separated by ';' (an option given twice keeps only its last value).
    std::istringstream in(*list);
    for (std::string one; std::getline(in, one, ';');) {
      try {
        poses.push_back(vision::parse_pose(one));
      } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--pose: ") + e.what());
      }
    }
  }
  if (poses.empty()) throw UsageError("--scene checkerboard needs --pose rx,ry,rz,tx,ty,tz[;...] or --poses FILE");
  how.noise_sigma = args.number("--noise", 0);
  how.blur_sigma_px = args.number("--blur", 0);
  how.supersample = static_cast<int>(args.number("--supersample", 4));
  how.seed = static_cast<unsigned>(args.number("--seed", 1));
  if (how.noise_sigma < 0 || how.blur_sigma_px < 0) throw UsageError("--noise and --blur must be >= 0");
  if (how.supersample < 1 || how.supersample > 16) throw UsageError("--supersample must be 1 to 16");

  const std::filesystem::path parent = std::filesystem::path(prefix).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  nlohmann::json truth = {
      {"format", "benchscope-synthetic-checkerboard"},
      {"board", {{"cols", how.board.cols}, {"rows", how.board.rows}, {"square_mm", how.board.square_mm}}},
      {"pose_convention",
       "rx,ry,rz degrees (R = Rz Ry Rx), tx,ty,tz mm of the board centre; "
       "camera frame x forward, y right, z up"},
      {"noise", how.noise_sigma},
      {"blur_px", how.blur_sigma_px},
      {"bits", bits},
      {"lens", vision::lens_to_json(lens, view)},
      {"images", nlohmann::json::array()}};
  for (std::size_t i = 0; i < poses.size(); ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "-%02zu.png", i + 1);
    const std::string path = prefix + name;
    how.seed = static_cast<unsigned>(args.number("--seed", 1)) + static_cast<unsigned>(i);
    const cv::Mat image = vision::render_checkerboard(lens, poses[i], how);
    if (!bs::image_files::write(path, image)) throw std::runtime_error(path + ": cannot write PNG");
    const auto& p = poses[i];
    truth["images"].push_back({{"file", std::filesystem::path(path).filename().string()},
                               {"pose", {p.rx_deg, p.ry_deg, p.rz_deg, p.tx_mm, p.ty_mm, p.tz_mm}}});
    out << "wrote " << path << " (" << image.cols << "x" << image.rows << ", " << bits << "-bit grey)\n";
  }
  const std::string json_path = prefix + ".json";
  std::ofstream(json_path) << truth.dump(2) << '\n';
  out << "wrote " << json_path << " (ground truth: lens, board, poses)\n";
  return 0;
}

}  // namespace bs::cli
