// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Reading a command line built as words (what the GUI sends to a robot's CLI): the word after an option, and
// whether a word is there at all.
#include <algorithm>
#include <string>
#include <vector>

namespace bs::test {

// The word after `option`, or "(absent)" (a value no test expects).
inline std::string word_after(const std::vector<std::string>& words, const std::string& option) {
  const auto it = std::find(words.begin(), words.end(), option);
  return it == words.end() || it + 1 == words.end() ? std::string("(absent)") : *(it + 1);
}

inline bool has_word(const std::vector<std::string>& words, const std::string& word) {
  return std::find(words.begin(), words.end(), word) != words.end();
}

}  // namespace bs::test
