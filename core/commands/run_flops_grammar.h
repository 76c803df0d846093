// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `benchscope-cli run flops`'s words, read and written side by side: the CLI reads its command line with
// run_flops_from_words, the Kernel Runner writes what a robot runs (`remote ROBOT run flops ...`) with to_words,
// and the round trip is tested. Worker and dimension lists stay as their text (a sweep spec "1,2,4:64:4" is what the
// user typed and what the run records) but are checked here. Which backends and instruction sets exist is the
// running computer's business (the CLI checks those).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "commands/power_words.h"
#include "commands/words.h"

namespace bs::commands {

struct RunFlopsSettings {
  std::string workers = "1,2,4,8,16,32,64,128,256";  // --workers: a worker sweep spec
  std::string points = "4";                          // --points: dimensions D, "1,2,4"
  std::int64_t iterations = 40000;                   // --iterations, 1 .. 1e12
  int repeats = 3;                                   // --repeats, 1 .. 1000
  bool warmup = true;                                // --no-warmup
  std::string variant = "throughput";                // --variant paper|throughput (or its labels)
  std::string backend = "cpu";                       // --backend
  std::optional<std::string> device;                 // --device N
  std::optional<std::string> isa;                    // --isa avx512|avx2|sse4|generic
  std::optional<std::string> out;                    // --out run.json
  std::optional<std::string> workspace;              // --workspace WS
  std::optional<std::string> events;                 // --events jsonl
  bool json = false;                                 // --json
  bool quiet = false;                                // --quiet
  PowerWords power;
  bool operator==(const RunFlopsSettings&) const = default;
};

// ["run", "flops", "--backend", "cpu", ...]: the sweep's settings always, the rest when given.
std::vector<std::string> to_words(const RunFlopsSettings& settings);
// The words after "run flops". Throws UsageError naming the option and what it takes.
RunFlopsSettings run_flops_from_words(const std::vector<std::string>& words);

}  // namespace bs::commands
