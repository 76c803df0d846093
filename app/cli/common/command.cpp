// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/command.h"

#include <algorithm>

namespace bs::cli {
namespace {

std::vector<Command>& registry() {
  static std::vector<Command> list;  // function-local: safe from static initialisation order
  return list;
}

}  // namespace

void register_command(Command command) {
  auto& list = registry();
  list.push_back(std::move(command));
  std::sort(list.begin(), list.end(), [](const Command& a, const Command& b) { return a.name < b.name; });
}

const std::vector<Command>& commands() { return registry(); }

const Command* find_command(std::string_view name) {
  for (const Command& c : registry())
    if (c.name == name) return &c;
  return nullptr;
}

}  // namespace bs::cli
