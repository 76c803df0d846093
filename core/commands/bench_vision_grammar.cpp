// SPDX-License-Identifier: GPL-3.0-or-later
#include "commands/bench_vision_grammar.h"

namespace bs::commands {

std::vector<std::string> to_words(const BenchVisionSettings& s) {
  std::vector<std::string> a = {"bench", "vision", "--frames", std::to_string(s.frames)};
  if (s.threads) a.insert(a.end(), {"--threads", std::to_string(*s.threads)});
  write_power(s.power, a);
  return a;
}

BenchVisionSettings bench_vision_from_words(const std::vector<std::string>& words) {
  std::set<std::string> valued = {"--frames", "--threads"};
  valued.insert(kPowerWordOptions.begin(), kPowerWordOptions.end());
  const Words args = read_words(words, {}, valued);
  if (!args.positional.empty())
    throw UsageError("bench vision takes no positional argument ('" + args.positional[0] + "')");
  BenchVisionSettings s;
  const double frames = args.number("--frames", 200);
  if (!(frames >= 1 && frames <= 100000) || frames != static_cast<double>(static_cast<long>(frames)))
    throw UsageError("--frames must be between 1 and 100000");
  s.frames = static_cast<int>(frames);
  if (args.value("--threads")) {
    const double threads = args.number("--threads", 0);
    if (!(threads >= 1 && threads <= 1024) || threads != static_cast<double>(static_cast<long>(threads)))
      throw UsageError("--threads must be between 1 and 1024");
    s.threads = static_cast<int>(threads);
  }
  s.power = read_power(args);
  return s;
}

}  // namespace bs::commands
