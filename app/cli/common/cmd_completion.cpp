// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli completion bash: prints the completion script built from the command registry
// (resources/completion/benchscope-cli.bash is this output, committed; tests/app/common/test_cli_conventions.cpp keeps
// the two equal).
#include <iostream>

#include "common/args.h"
#include "common/command.h"
#include "common/completion.h"

namespace bs::cli {
namespace {

const CommandRegistrar registrar({
    "completion",
    "print a shell completion script (bash)",
    "usage: benchscope-cli completion bash\n"
    "  Prints a bash completion script for every command and its options, generated from this build's commands.\n"
    "  Try it with `source <(benchscope-cli completion bash)`; install it as\n"
    "  /usr/share/bash-completion/completions/benchscope-cli.",
    [](const std::vector<std::string>& args, std::ostream& out, std::ostream& /*err*/) {
      const ParsedArgs parsed = parse_args(args, {}, {});
      if (parsed.positional.size() != 1 || parsed.positional[0] != "bash")
        throw UsageError("completion takes one shell, and bash is the one it writes");
      out << bash_completion(commands());
      return 0;
    },
});

}  // namespace
}  // namespace bs::cli
