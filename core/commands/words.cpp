// SPDX-License-Identifier: GPL-3.0-or-later
#include "commands/words.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace bs::commands {

std::optional<std::string> Words::value(const std::string& option) const {
  const auto it = options.find(option);
  if (it == options.end()) return std::nullopt;
  return it->second;
}

double Words::number(const std::string& option, double fallback) const {
  const auto v = value(option);
  if (!v) return fallback;
  double d = 0;
  const auto [ptr, ec] = std::from_chars(v->data(), v->data() + v->size(), d);
  if (ec != std::errc() || ptr != v->data() + v->size() || !std::isfinite(d))
    throw UsageError(option + " expects a number, got '" + *v + "'");
  return d;
}

Words read_words(const std::vector<std::string>& words, const std::set<std::string>& flags,
                 const std::set<std::string>& valued) {
  Words out;
  bool only_positional = false;
  for (std::size_t i = 0; i < words.size(); ++i) {
    const std::string& a = words[i];
    // "-3" and "-" are values, not options.
    if (only_positional || a.size() < 2 || a[0] != '-' ||
        (a[1] != '-' && !std::isalpha(static_cast<unsigned char>(a[1])))) {
      out.positional.push_back(a);
      continue;
    }
    if (a == "--") {
      only_positional = true;
      continue;
    }
    const auto eq = a.find('=');
    const std::string name = a.substr(0, eq);
    if (flags.count(name)) {
      if (eq != std::string::npos) throw UsageError(name + " takes no value");
      out.flags.insert(name);
    } else if (valued.count(name)) {
      if (eq != std::string::npos) {
        out.options[name] = a.substr(eq + 1);
      } else {
        if (i + 1 >= words.size()) throw UsageError(name + " needs a value");
        out.options[name] = words[++i];
      }
    } else {
      throw UsageError("unknown option '" + name + "'");
    }
  }
  return out;
}

std::string number_word(double v) {
  // %.15g is what a person would type ("1000", "0.35") and reads back for almost every value; %.17g always does.
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.15g", v);
  double back = 0;
  std::from_chars(buf, buf + std::char_traits<char>::length(buf), back);
  if (back != v) std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

void write_option(std::vector<std::string>& words, const std::string& option, const std::optional<std::string>& value) {
  if (value) words.insert(words.end(), {option, *value});
}

long long whole_number(const Words& words, const std::string& option, long long fallback, long long min,
                       long long max) {
  const double v = words.number(option, static_cast<double>(fallback));
  if (!(v >= static_cast<double>(min) && v <= static_cast<double>(max)) || v != std::floor(v))
    throw UsageError(option + " must be a whole number from " + std::to_string(min) + " to " + std::to_string(max));
  return static_cast<long long>(v);
}

}  // namespace bs::commands
