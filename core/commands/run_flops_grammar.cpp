// SPDX-License-Identifier: GPL-3.0-or-later
#include "commands/run_flops_grammar.h"

#include <stdexcept>

#include "commands/events_words.h"
#include "kernels/worker_spec.h"

namespace bs::commands {

std::vector<std::string> to_words(const RunFlopsSettings& s) {
  std::vector<std::string> a = {"run",          "flops",
                                "--backend",    s.backend,
                                "--variant",    s.variant,
                                "--workers",    s.workers,
                                "--points",     s.points,
                                "--iterations", std::to_string(s.iterations),
                                "--repeats",    std::to_string(s.repeats)};
  if (!s.warmup) a.push_back("--no-warmup");
  write_option(a, "--device", s.device);
  write_option(a, "--isa", s.isa);
  write_option(a, "--out", s.out);
  write_option(a, "--workspace", s.workspace);
  write_option(a, "--events", s.events);
  if (s.json) a.push_back("--json");
  if (s.quiet) a.push_back("--quiet");
  write_power(s.power, a);
  return a;
}

RunFlopsSettings run_flops_from_words(const std::vector<std::string>& words) {
  std::set<std::string> valued = {"--backend",   "--points",  "--iterations", "--workers", "--repeats", "--out",
                                  "--workspace", "--variant", "--device",     "--isa",     "--events"};
  valued.insert(kPowerWordOptions.begin(), kPowerWordOptions.end());
  const Words args = read_words(words, {"--json", "--no-warmup", "--quiet"}, valued);
  if (!args.positional.empty()) throw UsageError("expected 'run flops'");
  RunFlopsSettings s;
  s.workers = args.value("--workers").value_or(s.workers);
  s.points = args.value("--points").value_or(s.points);
  try {
    kernels::parse_worker_spec(s.workers);
    kernels::parse_dims_list(s.points);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--workers/--points: ") + e.what());
  }
  const double n = args.number("--iterations", 40000);
  const double repeats = args.number("--repeats", 3);
  if (n < 1 || n > 1e12 || n != static_cast<double>(static_cast<std::int64_t>(n)))
    throw UsageError("--iterations must be a whole number >= 1");
  if (repeats < 1 || repeats > 1000) throw UsageError("--repeats must be between 1 and 1000");
  s.iterations = static_cast<std::int64_t>(n);
  s.repeats = static_cast<int>(repeats);
  s.warmup = !args.has("--no-warmup");
  s.variant = args.value("--variant").value_or(s.variant);
  // The throughput variant's per-backend labels (float16x4, float4x4) are accepted as its names too.
  if (s.variant != "paper" && s.variant != "throughput" && s.variant != "float16x4" && s.variant != "float4x4")
    throw UsageError("--variant must be paper or throughput");
  s.backend = args.value("--backend").value_or(s.backend);
  s.device = args.value("--device");
  s.isa = args.value("--isa");
  s.out = args.value("--out");
  s.workspace = args.value("--workspace");
  s.events = read_events(args);
  s.json = args.has("--json");
  s.quiet = args.has("--quiet");
  s.power = read_power(args);
  return s;
}

}  // namespace bs::commands
