// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote/remote_inputs.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include "commands/bench_dnn_grammar.h"
#include "model/raw_sidecar.h"

namespace fs = std::filesystem;

namespace bs::cli {
namespace {

// `pipeline`'s options that take a value (cmd_pipeline.cpp): a value is never a frame file.
const std::set<std::string>& pipeline_valued_options() {
  static const std::set<std::string> options = {
      "--lens",           "--demosaic",     "--backend", "--detector",          "--frames",
      "--policy",         "--out",          "--pattern", "--platform",          "--queue",
      "--detect-workers", "--detect-scale", "--power",   "--power-interval-ms", "--sysfs-root"};
  return options;
}

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

std::string carry_value(Carrier& carrier, const std::string& option, const std::string& value) {
  if (option == "--lens" && value != "paper" && desk_file(value)) return carrier.carry(value);
  if (option == "--detector") return carry_model(carrier, value);
  return value;
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
  for (std::size_t i = 1; i < words.size(); ++i) {
    std::string& w = words[i];
    if (w == "--") break;
    if (const auto eq = w.find('='); w.starts_with("--") && eq != std::string::npos) {
      w = w.substr(0, eq + 1) + carry_value(carrier, w.substr(0, eq), w.substr(eq + 1));
    } else if (pipeline_valued_options().count(w) && i + 1 < words.size()) {
      words[i + 1] = carry_value(carrier, w, words[i + 1]);
      ++i;
    } else if (!w.starts_with("--") && desk_file(w)) {
      w = carrier.carry_frame(w);
    }
  }
  out.files = carrier.files();
  return out;
}

}  // namespace bs::cli
