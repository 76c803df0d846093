// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `benchscope-cli run bandwidth`'s words (the STREAM triad, the memory ceiling of the roofline), read and written side
// by side like every command a robot runs for the desk (commands/remote_commands.h). Whether the backend exists and
// has a triad kernel is the running computer's to say (the CLI).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "commands/words.h"

namespace bs::commands {

struct RunBandwidthSettings {
  std::string backend = "cpu";           // --backend cpu|opencl
  std::optional<std::string> device;     // --device N (the backend's device index)
  std::size_t mib_per_array = 128;       // --mib, 1 to 16384 MiB per array
  int repeats = 10;                      // --repeats, 1 to 1000
  std::optional<std::string> workspace;  // --workspace WS
  bool json = false;                     // --json
  bool quiet = false;                    // --quiet
  bool operator==(const RunBandwidthSettings&) const = default;
};

// ["run", "bandwidth", "--backend", "cpu", "--mib", "128", "--repeats", "10", ...]: sizes spelled out (the robot's
// defaults may differ).
std::vector<std::string> to_words(const RunBandwidthSettings& settings);
// The words after "run bandwidth". Throws UsageError naming the option and the accepted range.
RunBandwidthSettings run_bandwidth_from_words(const std::vector<std::string>& words);

}  // namespace bs::commands
