// SPDX-License-Identifier: GPL-3.0-or-later
#include "util/text.h"

#include <algorithm>
#include <charconv>
#include <cstdio>

namespace bs {
namespace {
constexpr bool white(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }
}  // namespace

std::string_view trim(std::string_view s) {
  while (!s.empty() && white(s.front())) s.remove_prefix(1);
  while (!s.empty() && white(s.back())) s.remove_suffix(1);
  return s;
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return out;
}

bool ends_with_ci(std::string_view text, std::string_view suffix) {
  return suffix.size() <= text.size() && lower(text.substr(text.size() - suffix.size())) == lower(suffix);
}

bool ends_with_any_ci(std::string_view text, std::string_view endings) {
  while (!endings.empty()) {
    const std::size_t space = endings.find(' ');
    const std::string_view ending = endings.substr(0, space);
    if (!ending.empty() && ends_with_ci(text, ending)) return true;
    endings = space == std::string_view::npos ? std::string_view() : endings.substr(space + 1);
  }
  return false;
}

std::string join(const std::vector<std::string>& parts, std::string_view separator) {
  std::string out;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (i > 0) out += separator;
    out += parts[i];
  }
  return out;
}

std::vector<std::string> comma_terms(std::string_view text) {
  std::vector<std::string> terms;
  std::string cur;
  for (const char c : text) {
    if (c == ',') {
      if (!cur.empty()) terms.push_back(cur);
      cur.clear();
    } else if (c != ' ') {
      cur += c;
    }
  }
  if (!cur.empty()) terms.push_back(cur);
  return terms;
}

std::string format_number(const char* printf_format, double v) {
  char buf[64];
  const int n = std::snprintf(buf, sizeof buf, printf_format, v);
  if (n < 0) return {};
  if (static_cast<std::size_t>(n) < sizeof buf) return std::string(buf, static_cast<std::size_t>(n));
  std::string out(static_cast<std::size_t>(n) + 1, '\0');  // a huge value in fixed notation
  std::snprintf(out.data(), out.size(), printf_format, v);
  out.resize(static_cast<std::size_t>(n));
  return out;
}

std::string fixed(double v, int digits) {
  char buf[400];  // any finite double in fixed notation with up to 17 decimals fits
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, std::clamp(digits, 0, 17));
  if (r.ec != std::errc()) return format_number("%f", v);  // inf, nan
  return std::string(buf, r.ptr);
}

}  // namespace bs
