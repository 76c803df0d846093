// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/args.h"

#include <charconv>
#include <cmath>

namespace bs::cli {

std::optional<std::string> ParsedArgs::value(const std::string& option) const {
  const auto it = options.find(option);
  if (it == options.end()) return std::nullopt;
  return it->second;
}

double ParsedArgs::number(const std::string& option, double fallback) const {
  const auto v = value(option);
  if (!v) return fallback;
  double d = 0;
  const auto [ptr, ec] = std::from_chars(v->data(), v->data() + v->size(), d);
  if (ec != std::errc() || ptr != v->data() + v->size() || !std::isfinite(d))
    throw UsageError(option + " expects a number, got '" + *v + "'");
  return d;
}

ParsedArgs parse_args(const std::vector<std::string>& args, const std::set<std::string>& flags,
                      const std::set<std::string>& valued) {
  ParsedArgs out;
  bool only_positional = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
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
        if (i + 1 >= args.size()) throw UsageError(name + " needs a value");
        out.options[name] = args[++i];
      }
    } else {
      throw UsageError("unknown option '" + name + "'");
    }
  }
  return out;
}

}  // namespace bs::cli
