// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/text_lines.h"
#include "util/text.h"

#include <cctype>

namespace bs::headroom_import {

bool LineCursor::next(TextLine* line) {
  if (pos_ >= text_.size()) return false;
  if ((++number_ & 0xFFF) == 0) cancel_.throw_if_cancelled();
  const std::size_t end = text_.find('\n', pos_);
  const bool has_end = end != std::string_view::npos;
  std::string_view body = text_.substr(pos_, (has_end ? end : text_.size()) - pos_);
  if (!body.empty() && body.back() == '\r') body.remove_suffix(1);
  line->number = number_;
  line->text = body;
  line->has_line_end = has_end;
  pos_ = has_end ? end + 1 : text_.size();
  return true;
}

namespace {

// Length of a CSI sequence's body after its introducer: parameter and intermediate bytes up to and including the
// final byte (0x40..0x7E); npos when the sequence is not closed on this line.
std::size_t csi_length(std::string_view s) {
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c >= 0x40 && c <= 0x7E) return i + 1;
    if (c < 0x20 || c > 0x3F) return std::string_view::npos;  // neither parameter nor intermediate byte
  }
  return std::string_view::npos;
}

}  // namespace

std::string strip_terminal_codes(std::string_view line) {
  // What a carriage return overwrote is gone from the screen: keep what followed the last one.
  if (const auto cr = line.rfind('\r'); cr != std::string_view::npos) line.remove_prefix(cr + 1);
  std::string out;
  out.reserve(line.size());
  for (std::size_t i = 0; i < line.size();) {
    const bool esc = line[i] == '\x1b';
    const bool caret = !esc && line.substr(i).starts_with("^[");  // `cat -v` writes ESC as ^[
    if (!esc && !caret) {
      out.push_back(line[i++]);
      continue;
    }
    const std::size_t intro = esc ? 1 : 2;
    const std::string_view rest = line.substr(i + intro);
    if (rest.starts_with("[")) {
      const std::size_t body = csi_length(rest.substr(1));
      if (body == std::string_view::npos) break;  // an unterminated sequence ends what the line shows
      i += intro + 1 + body;
    } else if (rest.starts_with("]")) {
      // OSC: up to BEL or ESC backslash.
      const std::size_t bel = rest.find('\a');
      const std::size_t st = rest.find("\x1b\\");
      if (bel == std::string_view::npos && st == std::string_view::npos) break;
      i += intro + (bel < st ? bel + 1 : st + 2);
    } else if (!rest.empty()) {
      i += intro + 1;  // ESC 7, ESC 8, ESC M, ...
    } else {
      break;
    }
  }
  return out;
}

std::vector<std::string_view> words_of(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
    const std::size_t start = i;
    while (i < s.size() && s[i] != ' ' && s[i] != '\t') ++i;
    if (i > start) out.push_back(s.substr(start, i - start));
  }
  return out;
}

std::string where(const std::string& file, std::size_t line) { return file + ":" + std::to_string(line) + ": "; }

}  // namespace bs::headroom_import
