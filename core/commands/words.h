// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The words of a command line, read strictly: the one reader behind every `benchscope-cli` command (app/cli's
// parse_args) and every robot-runnable command's grammar in this folder, so the desk and the robot split words
// the same way. Unknown options, a missing value and junk numbers are UsageErrors naming the option.
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace bs::commands {

// A wrong call of a command: what is wrong, naming the option (the CLI prints it with the usage line, exit 2).
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Words {
  std::vector<std::string> positional;
  std::set<std::string> flags;                 // given boolean options, e.g. "--json"
  std::map<std::string, std::string> options;  // options with a value, e.g. "--out" -> "dir"
  bool has(const std::string& flag) const { return flags.count(flag) > 0; }
  std::optional<std::string> value(const std::string& option) const;
  double number(const std::string& option, double fallback) const;  // throws UsageError on junk
};

// `flags` take no value; `valued` take the next word (or --opt=value). Everything after "--" is positional.
Words read_words(const std::vector<std::string>& words, const std::set<std::string>& flags,
                 const std::set<std::string>& valued);

// The shortest word that reads back as the same double ("1000", "0.5", "12.25"): what grammars write numbers as.
std::string number_word(double v);

// Appends `option` and its value when there is one: how grammars write an optional setting.
void write_option(std::vector<std::string>& words, const std::string& option, const std::optional<std::string>& value);

// `option`'s value as a whole number from `min` to `max` (`fallback` when absent), else a UsageError
// "<option> must be a whole number from <min> to <max>".
long long whole_number(const Words& words, const std::string& option, long long fallback, long long min, long long max);

}  // namespace bs::commands
