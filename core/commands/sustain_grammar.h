// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `benchscope-cli sustain`'s words (#53), read and written side by side: the CLI reads its command line with
// sustain_from_words, the desk writes what a robot runs with to_words, `remote` checks the words through it before
// they go, and the round trip is tested. Every measurement setting is written out, defaults too: the robot's
// defaults may differ. The load stays its --load text: the robot's CLI builds it, on the robot.
#include <optional>
#include <string>
#include <vector>

#include "commands/power_words.h"
#include "commands/words.h"

namespace bs::commands {

struct SustainSettings {
  std::string load = "flops";             // --load: flops[:W], pipeline[@FPS], dnn[:NET][@RATE] (one load)
  double seconds = 600;                   // --seconds: how long the load runs (default: a RoboCup half)
  double interval_s = 1;                  // --interval
  std::string detector = "hog";           // --detector of the pipeline load
  std::string platform;                   // --platform; empty: this host's name
  double stable_percent = 97;             // --stable-percent (3DMark's stable pass)
  double throttle_threshold = 0.8;        // --throttle-threshold (nvbench)
  std::optional<std::string> sysfs_root;  // --sysfs-root: clocks, temperatures and power sensors are read under it
  PowerWords power;                       // --power, --power-interval-ms (its sysfs_root is the one above)
  std::optional<std::string> workspace;   // --workspace WS
  bool json = false;                      // --json
  std::optional<std::string> events;      // --events jsonl: the run as events of stream v1 on stdout (a robot's job)
  bool operator==(const SustainSettings&) const = default;
};

// ["sustain", "--load", "flops", "--seconds", "600", ...]
std::vector<std::string> to_words(const SustainSettings& settings);
// The words after "sustain". Throws UsageError naming the option and the accepted range.
SustainSettings sustain_from_words(const std::vector<std::string>& words);

}  // namespace bs::commands
