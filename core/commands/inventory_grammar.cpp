// SPDX-License-Identifier: GPL-3.0-or-later
#include "commands/inventory_grammar.h"

namespace bs::commands {
namespace {

void no_positional(const Words& args, const char* command) {
  if (!args.positional.empty())
    throw UsageError(std::string(command) + " takes no positional argument ('" + args.positional[0] + "')");
}

}  // namespace

std::vector<std::string> to_words(const DevicesSettings& s) {
  std::vector<std::string> a = {"devices"};
  if (s.table) a.push_back("--table");
  if (s.measure_ceilings) a.push_back("--measure-ceilings");
  write_option(a, "--isa", s.isa);
  write_option(a, "--workspace", s.workspace);
  write_option(a, "--proc-root", s.proc_root);
  write_option(a, "--sysfs-root", s.sysfs_root);
  if (s.json) a.push_back("--json");
  return a;
}

std::vector<std::string> to_words(const SensorsSettings& s) {
  std::vector<std::string> a = {"sensors"};
  write_option(a, "--sysfs-root", s.sysfs_root);
  if (s.json) a.push_back("--json");
  return a;
}

DevicesSettings devices_from_words(const std::vector<std::string>& words) {
  const Words args = read_words(words, {"--json", "--table", "--measure-ceilings"},
                                {"--isa", "--workspace", "--proc-root", "--sysfs-root"});
  no_positional(args, "devices");
  DevicesSettings s;
  s.json = args.has("--json");
  s.table = args.has("--table");
  s.measure_ceilings = args.has("--measure-ceilings");
  s.isa = args.value("--isa");
  s.workspace = args.value("--workspace");
  s.proc_root = args.value("--proc-root");
  s.sysfs_root = args.value("--sysfs-root");
  return s;
}

SensorsSettings sensors_from_words(const std::vector<std::string>& words) {
  const Words args = read_words(words, {"--json"}, {"--sysfs-root"});
  no_positional(args, "sensors");
  SensorsSettings s;
  s.json = args.has("--json");
  s.sysfs_root = args.value("--sysfs-root");
  return s;
}

}  // namespace bs::commands
