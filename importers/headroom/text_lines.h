// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Line-by-line reading shared by the headroom text formats (cyclictest's histogram and terminal output, rttest logs,
// performance_test's CSV log): 1-based line numbers for errors, CRLF folded, whether the last line had its line end
// (a file cut mid-line must be said), and terminal control codes removed from what a person captured with `script`
// or pasted from a terminal (cyclictest redraws its status lines with cursor-up codes).
#include <charconv>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "util/cancel.h"
#include "util/text.h"

namespace bs::headroom_import {

struct TextLine {
  std::size_t number = 0;  // 1-based
  std::string_view text;   // without the line end (and without a trailing '\r')
  bool has_line_end = true;
};

// Iterates over `text` line by line; polls `cancel` every 4096 lines.
class LineCursor {
 public:
  LineCursor(std::string_view text, const CancelToken& cancel) : text_(text), cancel_(cancel) {}
  bool next(TextLine* line);

 private:
  std::string_view text_;
  const CancelToken& cancel_;
  std::size_t pos_ = 0;
  std::size_t number_ = 0;
};

// Feeds every line of `text` to parser.line(line) and returns parser.finish(): the whole parse of the formats read
// by a line-at-a-time parser object (cyclictest text, rttest statistics).
template <class Parser>
auto parse_lines(Parser& parser, std::string_view text, const CancelToken& cancel) {
  LineCursor cursor(text, cancel);
  TextLine line;
  while (cursor.next(&line)) parser.line(line);
  return parser.finish();
}

// `line` without terminal control sequences: ESC [ ... final byte (cursor moves, colours, erase), ESC ] ... BEL
// (window titles), other two-byte ESC sequences, the same written in caret notation by `cat -v` ("^[[4A"), and
// what a carriage return inside the line overwrote (only the text after the last '\r' was left on screen).
std::string strip_terminal_codes(std::string_view line);

using bs::trim;  // util/text.h

// The words of `s`, split on spaces and tabs.
std::vector<std::string_view> words_of(std::string_view s);

// `word` read whole as a number of type T (no sign for unsigned, no trailing text); false otherwise.
template <class T>
bool whole_number(std::string_view word, T* value) {
  if (word.empty()) return false;
  const auto [ptr, ec] = std::from_chars(word.data(), word.data() + word.size(), *value);
  return ec == std::errc() && ptr == word.data() + word.size();
}

// "file:line: " for warnings.
std::string where(const std::string& file, std::size_t line);

}  // namespace bs::headroom_import
