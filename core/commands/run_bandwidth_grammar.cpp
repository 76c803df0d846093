// SPDX-License-Identifier: GPL-3.0-or-later
#include "commands/run_bandwidth_grammar.h"

namespace bs::commands {

std::vector<std::string> to_words(const RunBandwidthSettings& s) {
  std::vector<std::string> a = {"run",       "bandwidth",
                                "--backend", s.backend,
                                "--mib",     std::to_string(s.mib_per_array),
                                "--repeats", std::to_string(s.repeats)};
  write_option(a, "--device", s.device);
  write_option(a, "--workspace", s.workspace);
  if (s.json) a.push_back("--json");
  if (s.quiet) a.push_back("--quiet");
  return a;
}

RunBandwidthSettings run_bandwidth_from_words(const std::vector<std::string>& words) {
  const Words args =
      read_words(words, {"--json", "--quiet"}, {"--backend", "--device", "--mib", "--repeats", "--workspace"});
  if (!args.positional.empty())
    throw UsageError("run bandwidth takes no positional argument ('" + args.positional[0] + "')");
  RunBandwidthSettings s;
  const double mib = args.number("--mib", 128), repeats = args.number("--repeats", 10);
  if (mib < 1 || mib > 16384 || mib != static_cast<double>(static_cast<long>(mib)))
    throw UsageError("--mib must be a whole number of MiB per array, 1 to 16384");
  if (repeats < 1 || repeats > 1000 || repeats != static_cast<double>(static_cast<long>(repeats)))
    throw UsageError("--repeats must be between 1 and 1000");
  s.mib_per_array = static_cast<std::size_t>(mib);
  s.repeats = static_cast<int>(repeats);
  s.backend = args.value("--backend").value_or("cpu");
  s.device = args.value("--device");
  s.workspace = args.value("--workspace");
  s.json = args.has("--json");
  s.quiet = args.has("--quiet");
  return s;
}

}  // namespace bs::commands
