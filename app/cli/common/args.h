// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Minimal, strict argument parsing shared by the subcommands: unknown options are usage errors (exit 2).
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace bs::cli {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct ParsedArgs {
  std::vector<std::string> positional;
  std::set<std::string> flags;                 // given boolean options, e.g. "--json"
  std::map<std::string, std::string> options;  // options with a value, e.g. "--out" -> "dir"
  bool has(const std::string& flag) const { return flags.count(flag) > 0; }
  std::optional<std::string> value(const std::string& option) const;
  double number(const std::string& option, double fallback) const;  // throws UsageError on junk
};

// `flags` take no value; `valued` take the next argument (or --opt=value).
ParsedArgs parse_args(const std::vector<std::string>& args, const std::set<std::string>& flags,
                      const std::set<std::string>& valued);

}  // namespace bs::cli
