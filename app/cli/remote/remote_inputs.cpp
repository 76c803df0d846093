// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote/remote_inputs.h"

#include <algorithm>
#include <filesystem>
#include <map>

#include "commands/bench_dnn_grammar.h"
#include "commands/pipeline_grammar.h"
#include "model/raw_sidecar.h"

namespace fs = std::filesystem;

namespace bs::cli {
namespace {

bool desk_file(const std::string& path) {
  std::error_code ec;
  return !path.empty() && fs::is_regular_file(path, ec);
}

// A name the robot's `job put` takes (letters, digits, '-', '_', '.'), from the desk file's own name.
std::string plain_name(const std::string& path) {
  std::string name = fs::path(path).filename().string();
  for (char& c : name)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' ||
          c == '.'))
      c = '_';
  if (name.size() > 100) name = name.substr(name.size() - 100);
  return name;
}

class Carrier {
 public:
  explicit Carrier(std::string robot_dir) : robot_dir_(std::move(robot_dir)) {}

  // The robot's path for a desk file, sent once however often it is named.
  std::string carry(const std::string& path) {
    std::error_code ec;
    const std::string key = fs::weakly_canonical(path, ec).string();
    if (const auto it = names_.find(key); it != names_.end()) return robot_dir_ + "/" + it->second;
    const int number = ++count_;
    numbers_[key] = number;
    return send(path, key, number);
  }
  // A raw frame and its sidecar (capture.raw + capture.json) in one numbered folder, so that the robot finds the
  // sidecar by the frame's stem, as here. A sidecar sent already into another folder (as a --lens file) goes again.
  std::string carry_frame(const std::string& path) {
    const std::string there = carry(path);
    if (const auto side = find_raw_sidecar(path)) {
      std::error_code ec;
      const int number = numbers_.at(fs::weakly_canonical(path, ec).string());
      const std::string side_key = fs::weakly_canonical(*side, ec).string();
      if (const auto it = numbers_.find(side_key); it == numbers_.end()) {
        numbers_[side_key] = number;
        send(*side, side_key, number);
      } else if (it->second != number) {
        send(*side, side_key + "\n(again, as the sidecar of)\n" + path, number);
      }
    }
    return there;
  }
  std::vector<CarriedFile> files() const { return files_; }

 private:
  std::string send(const std::string& path, const std::string& key, int number) {
    const std::string name = std::to_string(number) + "/" + plain_name(path);
    names_[key] = name;
    files_.push_back({path, name});
    return robot_dir_ + "/" + name;
  }

  std::string robot_dir_;
  std::map<std::string, std::string> names_;
  std::map<std::string, int> numbers_;
  std::vector<CarriedFile> files_;
  int count_ = 0;
};

// --detector MODEL[,CONFIG]: each part that is a desk file carried.
std::string carry_model(Carrier& carrier, const std::string& value) {
  const auto comma = value.find(',');
  std::string model = value.substr(0, comma);
  if (desk_file(model)) model = carrier.carry(model);
  if (comma == std::string::npos) return model;
  std::string config = value.substr(comma + 1);
  if (desk_file(config)) config = carrier.carry(config);
  return model + "," + config;
}

}  // namespace

CarriedCommand carry_desk_files(const std::vector<std::string>& command, const std::string& robot_inputs_dir) {
  CarriedCommand out{command, {}};
  Carrier carrier(robot_inputs_dir);
  std::vector<std::string>& words = out.command;
  // bench dnn --model MODEL[,CONFIG]: the network's files, found and written again by the command's grammar.
  if (words.size() >= 2 && words[0] == "bench" && words[1] == "dnn") {
    commands::BenchDnnSettings settings = commands::bench_dnn_from_words({words.begin() + 2, words.end()});
    if (settings.model) settings.model = carry_model(carrier, *settings.model);
    out.command = commands::to_words(settings);
    out.files = carrier.files();
    return out;
  }
  if (command.empty() || command[0] != "pipeline") return out;
  // pipeline FRAME... --lens LENS --detector MODEL[,CONFIG]: found and written again by the command's grammar too.
  commands::PipelineSettings settings = commands::pipeline_from_words({words.begin() + 1, words.end()});
  for (std::string& frame : settings.frame_files)
    if (desk_file(frame)) frame = carrier.carry_frame(frame);
  if (settings.lens && *settings.lens != "paper" && desk_file(*settings.lens))
    settings.lens = carrier.carry(*settings.lens);
  settings.detector = carry_model(carrier, settings.detector);
  // Written again only when a file goes with it: the words the user typed stay the record of what ran.
  if (!carrier.files().empty()) out.command = commands::to_words(settings);
  out.files = carrier.files();
  return out;
}

}  // namespace bs::cli
