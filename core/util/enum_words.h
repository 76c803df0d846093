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

// Whether `words` has a line for every value of an enumeration numbered 0, 1, ... up to `last` (the default numbering):
// `static_assert(names_every_value(kWords, Enum::Last))` beside a table stands in for the -Wswitch a switch had, so a
// value added to the enumeration before `last` without its line fails the build. (One added after `last` needs the
// assertion's `last` moved too: keep the assertion naming the enumeration's last value.)
template <class Enum, std::size_t N>
constexpr bool names_every_value(const EnumWord<Enum> (&words)[N], Enum last) {
  for (long long v = 0; v <= static_cast<long long>(last); ++v) {
    bool named = false;
    for (const EnumWord<Enum>& w : words) named = named || static_cast<long long>(w.value) == v;
    if (!named) return false;
  }
  return true;
}

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
