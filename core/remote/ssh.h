// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// How BenchScope reaches a robot: the system's OpenSSH client, so the user's keys, agent, ~/.ssh/config (Host
// aliases, User, Port, ProxyJump) work exactly as in a terminal. Always in batch mode: ssh never asks for a
// password or a passphrase and never accepts an unknown host key on its own; BenchScope stores no secret.
#include <string>
#include <string_view>
#include <vector>

namespace bs::remote {

struct SshTarget {
  std::string destination;                    // "user@host", "host", or a Host of the SSH config
  std::string config_file;                    // ssh -F FILE; empty: ssh's own (~/.ssh/config, /etc/ssh/ssh_config)
  std::string remote_cli = "benchscope-cli";  // the CLI on the robot: a name on its PATH or an absolute path
};

// Throws std::invalid_argument when `destination` cannot be an SSH destination (empty, starts with '-', has
// spaces or control characters): it is passed to ssh, never to a shell, but an option in disguise is refused.
void check_destination(std::string_view destination);

// `word` quoted for a POSIX shell ('...' with each ' written '\''), unless it is plain enough to need none.
std::string shell_quote(std::string_view word);
// The words joined as one command line for the robot's login shell (ssh sends a single string).
std::string shell_command(const std::vector<std::string>& words);

// ssh's argument list: batch mode, no terminal, keep-alives so a dropped link is noticed within a minute,
// `-F` when the target names a config file, then the destination and the remote command.
std::vector<std::string> ssh_argv(const SshTarget& target, const std::string& remote_command);

// What went wrong, for an ssh that exited with 255 (its own failure, not the remote command's), naming the host
// and quoting ssh: the host cannot be reached, refused the login, has an unknown or changed host key, or the
// connection was lost. Ends with what to do about it.
std::string describe_ssh_failure(std::string_view destination, std::string_view ssh_stderr);
// ssh's last meaningful stderr line (what to quote): the last non-empty line, warnings about added keys and the
// robot's own CLI messages ("benchscope-cli: ...") skipped.
std::string last_ssh_line(std::string_view ssh_stderr);

}  // namespace bs::remote
