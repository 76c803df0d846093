// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/headroom_command.h"

#include <cstdio>

namespace bs::headroom {
namespace {

// Shortest text that reads back as the same number ("1000", "0.5", "12.25").
std::string number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.15g", v);
  return buf;
}

}  // namespace

std::vector<std::string> headroom_cli_args(const RunConfig& config, const std::string& loads,
                                           const std::string& load_command, bool record_power) {
  const ProbeConfig& p = config.probe;
  std::vector<std::string> a = {"headroom",
                                "--rate",
                                number(p.rate_hz),
                                "--seconds",
                                number(config.phase_s),
                                "--settle",
                                number(config.settle_s),
                                "--threads",
                                std::to_string(p.threads),
                                "--computation-us",
                                number(static_cast<double>(p.computation_ns) / 1000),
                                "--limit-us",
                                std::to_string(p.limit_ns / 1000)};
  if (p.deadline_ns) a.insert(a.end(), {"--deadline-us", number(static_cast<double>(*p.deadline_ns) / 1000)});
  if (!p.cpus.empty()) {
    std::string list;
    for (int c : p.cpus) list += (list.empty() ? "" : ",") + std::to_string(c);
    a.insert(a.end(), {"--cpu", list});
  }
  if (p.realtime)
    a.insert(a.end(), {"--priority", std::to_string(p.priority)});
  else
    a.push_back("--no-rt");
  if (!config.idle_phase) a.push_back("--no-idle");
  if (!loads.empty()) a.insert(a.end(), {"--load", loads});
  if (!load_command.empty()) a.insert(a.end(), {"--load-command", load_command});
  if (!config.platform.empty()) a.insert(a.end(), {"--platform", config.platform});
  if (record_power) a.insert(a.end(), {"--power", "auto"});
  return a;
}

}  // namespace bs::headroom
