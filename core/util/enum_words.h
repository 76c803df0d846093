// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The words an enumeration is written as (in files, the workspace, the CLI, the views): one table of {value, word}
// pairs per enumeration serves both directions, so that the word written for a value and the value read back from
// that word come from the same line and cannot drift apart, as two hand-written switches could.
#include <cstddef>
#include <optional>
#include <string_view>

namespace bs {

template <class Enum>
struct EnumWord {
  Enum value;
  std::string_view word;
};

// The word of `value` in `words`; `fallback` for a value the table does not list.
template <class Enum, std::size_t N>
constexpr std::string_view word_of(const EnumWord<Enum> (&words)[N], Enum value, std::string_view fallback) {
  for (const EnumWord<Enum>& w : words)
    if (w.value == value) return w.word;
  return fallback;
}

// The value whose word is exactly `word` (the first such line), if any.
template <class Enum, std::size_t N>
constexpr std::optional<Enum> parse_word(const EnumWord<Enum> (&words)[N], std::string_view word) {
  for (const EnumWord<Enum>& w : words)
    if (w.word == word) return w.value;
  return std::nullopt;
}

}  // namespace bs
