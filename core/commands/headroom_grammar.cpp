// SPDX-License-Identifier: GPL-3.0-or-later
#include "commands/headroom_grammar.h"

#include <cmath>
#include <cstdlib>

namespace bs::commands {
namespace {

std::vector<int> read_cpu_list(const std::string& list) {
  std::vector<int> cpus;
  std::string cur;
  for (char ch : list + ",") {
    if (ch != ',') {
      cur += ch;
      continue;
    }
    if (cur.empty()) throw UsageError("--cpu takes CPU numbers separated by commas (got '" + list + "')");
    char* end = nullptr;
    const long v = std::strtol(cur.c_str(), &end, 10);
    if (*end != '\0' || v < 0 || v > 4095) throw UsageError("--cpu: '" + cur + "' is not a CPU number");
    cpus.push_back(static_cast<int>(v));
    cur.clear();
  }
  return cpus;
}

std::string microseconds(std::int64_t ns) { return number_word(static_cast<double>(ns) / 1000); }

}  // namespace

void write_probe(const headroom::ProbeConfig& p, std::vector<std::string>& a) {
  a.insert(a.end(), {"--rate", number_word(p.rate_hz), "--threads", std::to_string(p.threads), "--computation-us",
                     microseconds(p.computation_ns), "--limit-us", std::to_string(p.limit_ns / 1000)});
  if (p.deadline_ns) a.insert(a.end(), {"--deadline-us", microseconds(*p.deadline_ns)});
  if (!p.cpus.empty()) {
    std::string list;
    for (int c : p.cpus) list += (list.empty() ? "" : ",") + std::to_string(c);
    a.insert(a.end(), {"--cpu", list});
  }
  if (p.realtime)
    a.insert(a.end(), {"--priority", std::to_string(p.priority)});
  else
    a.push_back("--no-rt");
}

headroom::ProbeConfig read_probe(const Words& args) {
  headroom::ProbeConfig c;
  c.rate_hz = args.number("--rate", 1000);
  if (!(c.rate_hz >= headroom::kMinRateHz && c.rate_hz <= headroom::kMaxRateHz))
    throw UsageError("--rate must be from 50 to 10000 Hz");
  c.threads = static_cast<int>(whole_number(args, "--threads", 1, 1, 64));
  c.computation_ns = static_cast<std::int64_t>(std::llround(args.number("--computation-us", 0) * 1000));
  if (c.computation_ns < 0 || c.computation_ns >= c.period_ns())
    throw UsageError("--computation-us must be at least 0 and below the period (" +
                     std::to_string(c.period_ns() / 1000) + " us)");
  if (args.value("--deadline-us")) {
    const double d = args.number("--deadline-us", 0);
    if (!(d > 0 && d <= 1e7)) throw UsageError("--deadline-us must be above 0 and at most 10,000,000");
    c.deadline_ns = static_cast<std::int64_t>(std::llround(d * 1000));
  }
  c.priority = static_cast<int>(whole_number(args, "--priority", 80, 1, 99));
  c.limit_ns = whole_number(args, "--limit-us", 10000, 10, 4'000'000) * 1000;
  c.realtime = !args.has("--no-rt");
  // Whether these CPUs exist is the running computer's to say (headroom::validate, in the CLI): the desk reading
  // a robot's words has other CPUs.
  if (const auto cpus = args.value("--cpu")) c.cpus = read_cpu_list(*cpus);
  return c;
}

std::vector<std::string> to_words(const HeadroomSettings& s) {
  std::vector<std::string> a = {"headroom", "--seconds", number_word(s.config.phase_s), "--settle",
                                number_word(s.config.settle_s)};
  write_probe(s.config.probe, a);
  if (!s.config.idle_phase) a.push_back("--no-idle");
  if (!s.loads.empty()) a.insert(a.end(), {"--load", s.loads});
  if (!s.load_command.empty()) a.insert(a.end(), {"--load-command", s.load_command});
  a.insert(a.end(), {"--detector", s.detector});
  if (!s.config.platform.empty()) a.insert(a.end(), {"--platform", s.config.platform});
  write_power(s.power, a);
  if (s.workspace) a.insert(a.end(), {"--workspace", *s.workspace});
  if (s.json) a.push_back("--json");
  if (!s.frames.empty()) a.push_back("--");  // a frame named "-x.png" stays a frame
  a.insert(a.end(), s.frames.begin(), s.frames.end());
  return a;
}

HeadroomSettings headroom_from_words(const std::vector<std::string>& words) {
  std::set<std::string> valued = kProbeOptions;
  valued.insert({"--seconds", "--settle", "--load", "--load-command", "--detector", "--platform", "--workspace"});
  valued.insert(kPowerWordOptions.begin(), kPowerWordOptions.end());
  const Words args = read_words(words, {"--json", "--no-rt", "--no-idle"}, valued);
  HeadroomSettings s;
  s.config.probe = read_probe(args);
  s.config.phase_s = args.number("--seconds", 20);
  if (!(s.config.phase_s >= 0.1 && s.config.phase_s <= 86400)) throw UsageError("--seconds must be from 0.1 to 86400");
  s.config.settle_s = args.number("--settle", 1);
  if (!(s.config.settle_s >= 0 && s.config.settle_s <= 600)) throw UsageError("--settle must be from 0 to 600 seconds");
  s.config.idle_phase = !args.has("--no-idle");
  s.config.platform = args.value("--platform").value_or("");
  s.loads = args.value("--load").value_or("");
  s.load_command = args.value("--load-command").value_or("");
  if (!s.config.idle_phase && s.loads.empty() && s.load_command.empty())
    throw UsageError("--no-idle needs at least one --load or --load-command");
  s.detector = args.value("--detector").value_or("hog");
  s.frames = args.positional;
  s.power = read_power(args);
  s.workspace = args.value("--workspace");
  s.json = args.has("--json");
  return s;
}

}  // namespace bs::commands
