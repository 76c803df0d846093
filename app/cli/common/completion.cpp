// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/completion.h"

#include <regex>
#include <set>

namespace bs::cli {

std::vector<std::string> options_in_usage(const std::string& usage) {
  static const std::regex option(R"((^|[^A-Za-z0-9-])(--[a-z][a-z0-9-]*))");
  std::set<std::string> found;
  for (auto it = std::sregex_iterator(usage.begin(), usage.end(), option); it != std::sregex_iterator(); ++it)
    found.insert((*it)[2].str());
  return {found.begin(), found.end()};
}

std::string bash_completion(const std::vector<Command>& commands) {
  std::string names;
  for (const Command& c : commands) names += (names.empty() ? "" : " ") + c.name;
  std::string s =
      "# bash completion for benchscope-cli. Generated from the command registry by `benchscope-cli completion bash`;\n"
      "# regenerate it rather than editing it. Use: source this file, or install it as\n"
      "# /usr/share/bash-completion/completions/benchscope-cli.\n"
      "_benchscope_cli() {\n"
      "  local cur=\"${COMP_WORDS[COMP_CWORD]}\"\n"
      "  local commands=\"" +
      names +
      "\"\n"
      "  if [[ $COMP_CWORD -eq 1 ]]; then\n"
      "    COMPREPLY=($(compgen -W \"$commands --help --version\" -- \"$cur\"))\n"
      "    return\n"
      "  fi\n"
      "  local options=\"\"\n"
      "  case \"${COMP_WORDS[1]}\" in\n";
  for (const Command& c : commands) {
    std::string opts;
    for (const std::string& o : options_in_usage(c.usage)) opts += " " + o;
    if (c.name == "help") {
      s += "    help) COMPREPLY=($(compgen -W \"$commands\" -- \"$cur\")); return ;;\n";
      continue;
    }
    s += "    " + c.name + ") options=\"--help" + opts + "\" ;;\n";
  }
  s += "  esac\n"
       "  if [[ $cur == -* ]]; then\n"
       "    COMPREPLY=($(compgen -W \"$options\" -- \"$cur\"))\n"
       "  else\n"
       "    COMPREPLY=($(compgen -f -- \"$cur\"))\n"
       "  fi\n"
       "}\n"
       "complete -o filenames -F _benchscope_cli benchscope-cli\n";
  return s;
}

}  // namespace bs::cli
