// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote/remote_commands.h"

namespace bs::cli {

const std::vector<RemoteCommand>& remote_commands() {
  static const std::vector<RemoteCommand> list = {
      {"run flops", 2, true, true},  {"record-power", 1, true, true},   {"run bandwidth", 2, false, true},
      {"bench dnn", 2, false, true}, {"bench vision", 2, false, false}, {"bench kernels", 2, false, false},
      {"devices", 1, false, false},  {"sensors", 1, false, false},      {"headroom", 1, false, true},
      {"pipeline", 1, false, true},
  };
  return list;
}

std::optional<RemoteCommand> find_remote_command(const std::vector<std::string>& args) {
  for (const RemoteCommand& c : remote_commands()) {
    const std::string first = args.empty() ? std::string() : args[0];
    const std::string two = args.size() >= 2 ? args[0] + " " + args[1] : std::string();
    if ((c.words == 1 && first == c.name) || (c.words == 2 && two == c.name)) return c;
  }
  return std::nullopt;
}

std::string remote_command_names() {
  std::string names;
  for (const RemoteCommand& c : remote_commands()) names += (names.empty() ? "" : ", ") + c.name;
  return names;
}

}  // namespace bs::cli
