// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Whether a list of messages (an import's warnings, what a sampler could not read) says something: tests look for
// the part that matters, not for a whole message whose other words may be reworded.
#include <algorithm>
#include <string>
#include <vector>

namespace bs::test {

inline bool any_line_contains(const std::vector<std::string>& lines, const std::string& text) {
  return std::any_of(lines.begin(), lines.end(),
                     [&](const std::string& l) { return l.find(text) != std::string::npos; });
}

}  // namespace bs::test
