// SPDX-License-Identifier: GPL-3.0-or-later
#include "commands/bench_kernels_grammar.h"

#include <cmath>

namespace bs::commands {

std::vector<std::string> to_words(const BenchKernelsSettings& s) {
  std::vector<std::string> a = {"bench", "kernels", "--runs", std::to_string(s.runs)};
  if (s.workers) a.insert(a.end(), {"--workers", std::to_string(*s.workers)});
  write_option(a, "--isa", s.isa);
  if (s.no_ceilings) a.push_back("--no-ceilings");
  if (s.ceilings_only) a.push_back("--ceilings-only");
  write_power(s.power, a);
  return a;
}

BenchKernelsSettings bench_kernels_from_words(const std::vector<std::string>& words) {
  std::set<std::string> valued = {"--runs", "--workers", "--isa"};
  valued.insert(kPowerWordOptions.begin(), kPowerWordOptions.end());
  const Words args = read_words(words, {"--no-ceilings", "--ceilings-only"}, valued);
  if (!args.positional.empty())
    throw UsageError("bench kernels takes no positional argument ('" + args.positional[0] + "')");
  BenchKernelsSettings s;
  const double runs = args.number("--runs", 7);
  if (!(runs >= 1 && runs <= 1000) || runs != std::floor(runs)) throw UsageError("--runs must be between 1 and 1000");
  s.runs = static_cast<int>(runs);
  s.no_ceilings = args.has("--no-ceilings");
  s.ceilings_only = args.has("--ceilings-only");
  if (s.no_ceilings && s.ceilings_only) throw UsageError("--no-ceilings and --ceilings-only exclude each other");
  if (args.value("--workers")) {
    const double workers = args.number("--workers", 0);
    if (!(workers >= 1 && workers <= 1e6) || workers != std::floor(workers))
      throw UsageError("--workers must be between 1 and 1e6");
    s.workers = static_cast<std::int64_t>(workers);
  }
  s.isa = args.value("--isa");
  s.power = read_power(args);
  return s;
}

}  // namespace bs::commands
