// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A command's grammar as its tests drive it (#52): the words it starts with ("bench", "dnn") and the reader the CLI
// parses the rest with. round_trip is settings -> words -> settings (the words must name the command first); refusal
// is what the reader refuses bad words with, word for word. One definition, so the grammar tests differ only in what
// they check.
#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include <QString>

#include "refusal.h"

namespace bs::test {

template <typename Settings>
struct Grammar {
  std::vector<std::string> command;
  Settings (*read)(const std::vector<std::string>&);

  // to_words is found next to Settings (bs::commands), as the CLI and the desk find it.
  Settings round_trip(const Settings& settings) const {
    const std::vector<std::string> words = to_words(settings);
    if (words.size() < command.size() || !std::equal(command.begin(), command.end(), words.begin()))
      throw std::logic_error("the words do not start with the command");
    return read({words.begin() + static_cast<std::ptrdiff_t>(command.size()), words.end()});
  }

  QString refusal(const std::vector<std::string>& words) const {
    return bs::test::refusal([&] { read(words); });
  }
};

}  // namespace bs::test
