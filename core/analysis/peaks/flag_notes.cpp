// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/peaks/flag_notes.h"

#include <algorithm>

namespace bs {

std::string FlagNotes::marker(const std::vector<PlausibilityFlag>& flags) {
  std::string text;
  for (const PlausibilityFlag& f : flags) {
    auto it = std::find(notes_.begin(), notes_.end(), f);
    if (it == notes_.end()) it = notes_.insert(notes_.end(), f);
    text += (text.empty() ? "[" : ",") + std::to_string(it - notes_.begin() + 1);
  }
  return text.empty() ? text : text + "]";
}

std::string FlagNotes::mark(const std::string& text, const std::vector<PlausibilityFlag>& flags) {
  const std::string m = marker(flags);
  return m.empty() ? text : text + " " + m;
}

std::vector<std::string> FlagNotes::lines() const {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < notes_.size(); ++i)
    out.push_back("[" + std::to_string(i + 1) + "] " + notes_[i].code + ": " + notes_[i].reason);
  return out;
}

void FlagNotes::add_to(ExportTable& table) const {
  for (std::string& l : lines()) table.notes.push_back(std::move(l));
}

std::string short_flag_line(const std::string& line) {
  std::string s = line;
  const auto bracket = s.find("] ");
  const auto code = s.find(": ");
  if (bracket != std::string::npos && code != std::string::npos && code > bracket) s.erase(bracket + 2, code - bracket);
  const auto paren = s.find(" (");
  const auto stop = s.find(". ");
  if (paren != std::string::npos && (stop == std::string::npos || paren < stop))
    s.resize(paren);
  else if (stop != std::string::npos)
    s.resize(stop);
  if (s.empty() || s.back() != '.') s += '.';
  return s;
}

}  // namespace bs
