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
