// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `benchscope-cli headroom`'s words, read and written side by side: the CLI reads its command line with
// headroom_from_words, the Headroom tab writes what a robot runs with to_words (issue #44), and the round trip is
// tested, so the robot runs what the desk shows. Every measurement setting is written out, defaults too: the
// robot's defaults may differ. Loads stay their --load text: the robot's CLI builds them, on the robot.
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "commands/power_words.h"
#include "commands/words.h"
#include "headroom/headroom_run.h"
#include "headroom/probe.h"

namespace bs::commands {

struct HeadroomSettings {
  headroom::RunConfig config;       // probe, phases and platform (its command and kernel_root are not words)
  std::string loads;                // --load "pipeline@30fps,dnn"; empty: none
  std::string load_command;         // --load-command "stress-ng --cpu 2", one word; empty: none
  std::string detector = "hog";     // --detector of the pipeline load
  std::vector<std::string> frames;  // FRAME files the pipeline load plays
  PowerWords power;
  std::optional<std::string> workspace;  // --workspace WS
  bool json = false;                     // --json
};

// ["headroom", "--rate", "1000", "--seconds", "20", ...]
std::vector<std::string> to_words(const HeadroomSettings& settings);
// The words after "headroom". Throws UsageError naming the option and the accepted range.
HeadroomSettings headroom_from_words(const std::vector<std::string>& words);

// The probe's options, shared with `bench headroom`: --rate, --threads, --computation-us, --deadline-us, --cpu,
// --priority, --limit-us and the flag --no-rt. read_probe checks the words, not this computer (headroom::validate
// says whether the --cpu CPUs exist here).
inline const std::set<std::string> kProbeOptions = {"--rate", "--threads",  "--computation-us", "--deadline-us",
                                                    "--cpu",  "--priority", "--limit-us"};
void write_probe(const headroom::ProbeConfig& probe, std::vector<std::string>& words);
headroom::ProbeConfig read_probe(const Words& words);

}  // namespace bs::commands
