// SPDX-License-Identifier: GPL-3.0-or-later
#include "commands/sustain_grammar.h"

#include "commands/events_words.h"

namespace bs::commands {
namespace {

// One load, of a kind the robot's CLI builds (its own parser checks the rest of the token there).
void check_load(const std::string& load) {
  if (load.find(',') != std::string::npos) throw UsageError("--load takes one load (got '" + load + "')");
  const std::string kind = load.substr(0, load.find_first_of(":@"));
  if (kind != "flops" && kind != "pipeline" && kind != "dnn")
    throw UsageError("--load must be flops[:W], pipeline[@FPS] or dnn[:NET][@RATE] (got '" + load + "')");
}

double bounded(const Words& args, const std::string& option, double fallback, double lo, double hi,
               const std::string& range) {
  const double v = args.number(option, fallback);
  if (!(v >= lo && v <= hi)) throw UsageError(option + " must be " + range);
  return v;
}

}  // namespace

std::vector<std::string> to_words(const SustainSettings& s) {
  std::vector<std::string> a = {"sustain",
                                "--load",
                                s.load,
                                "--seconds",
                                number_word(s.seconds),
                                "--interval",
                                number_word(s.interval_s),
                                "--detector",
                                s.detector,
                                "--stable-percent",
                                number_word(s.stable_percent),
                                "--throttle-threshold",
                                number_word(s.throttle_threshold)};
  if (!s.platform.empty()) a.insert(a.end(), {"--platform", s.platform});
  write_option(a, "--sysfs-root", s.sysfs_root);
  PowerWords power = s.power;
  power.sysfs_root.reset();  // written once above: the sampler's root and the sensors' are one
  write_power(power, a);
  write_option(a, "--workspace", s.workspace);
  if (s.json) a.push_back("--json");
  write_option(a, "--events", s.events);
  return a;
}

SustainSettings sustain_from_words(const std::vector<std::string>& words) {
  std::set<std::string> valued = {"--load",     "--seconds",        "--interval",           "--detector",
                                  "--platform", "--stable-percent", "--throttle-threshold", "--workspace",
                                  "--events"};
  valued.insert(kPowerWordOptions.begin(), kPowerWordOptions.end());
  Words args = read_words(words, {"--json"}, valued);
  if (!args.positional.empty()) throw UsageError("sustain takes no positional argument ('" + args.positional[0] + "')");
  SustainSettings s;
  s.load = args.value("--load").value_or("flops");
  check_load(s.load);
  s.seconds = bounded(args, "--seconds", 600, 0.1, 7 * 86400, "from 0.1 to 604800 seconds");
  s.interval_s = bounded(args, "--interval", 1, 0.05, 3600, "from 0.05 to 3600 seconds");
  if (s.interval_s > s.seconds) throw UsageError("--interval must not be longer than --seconds");
  s.detector = args.value("--detector").value_or("hog");
  s.platform = args.value("--platform").value_or("");
  s.stable_percent = bounded(args, "--stable-percent", 97, 1, 100, "from 1 to 100 (%)");
  s.throttle_threshold =
      bounded(args, "--throttle-threshold", 0.8, 0.01, 1, "from 0.01 to 1 (a fraction of the clock's maximum)");
  // --sysfs-root is the sampler's as much as the power sensors': read here, so it needs no --power.
  s.sysfs_root = args.value("--sysfs-root");
  args.options.erase("--sysfs-root");
  s.power = read_power(args);
  s.power.sysfs_root = s.sysfs_root;
  s.workspace = args.value("--workspace");
  s.json = args.has("--json");
  s.events = read_events(args);
  return s;
}

}  // namespace bs::commands
