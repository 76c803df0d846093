// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote/ssh.h"

#include <stdexcept>

namespace bs::remote {
namespace {

bool contains(std::string_view text, std::string_view what) { return text.find(what) != std::string_view::npos; }

}  // namespace

void check_destination(std::string_view d) {
  if (d.empty()) throw std::invalid_argument("no robot given (user@host or a Host of ~/.ssh/config)");
  if (d.front() == '-') throw std::invalid_argument("'" + std::string(d) + "' is not a host (it starts with '-')");
  for (const char c : d)
    if (static_cast<unsigned char>(c) <= ' ' || c == 0x7f)
      throw std::invalid_argument("'" + std::string(d) + "' is not a host (it contains a space or control character)");
}

std::string shell_quote(std::string_view word) {
  const bool plain = !word.empty() && word.find_first_not_of(
                                          "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                          "0123456789_-+=./:,@%") == std::string_view::npos;
  // A leading '~' or '=' would be expanded by some shells; quoting keeps every word literal.
  if (plain && word.front() != '=') return std::string(word);
  std::string q = "'";
  for (const char c : word) {
    if (c == '\'')
      q += "'\\''";
    else
      q += c;
  }
  return q + "'";
}

std::string shell_command(const std::vector<std::string>& words) {
  std::string line;
  for (const std::string& w : words) line += (line.empty() ? "" : " ") + shell_quote(w);
  return line;
}

std::vector<std::string> ssh_argv(const SshTarget& t, const std::string& remote_command) {
  check_destination(t.destination);
  std::vector<std::string> argv = {"ssh"};
  if (!t.config_file.empty()) argv.insert(argv.end(), {"-F", t.config_file});
  // Options given here win over the config file's (ssh keeps the first value it obtains).
  argv.insert(argv.end(), {"-T", "-o", "BatchMode=yes", "-o", "ConnectTimeout=20", "-o", "ServerAliveInterval=15", "-o",
                           "ServerAliveCountMax=4", "--", t.destination, remote_command});
  return argv;
}

std::string last_ssh_line(std::string_view err) {
  std::string last;
  std::size_t start = 0;
  while (start < err.size()) {
    std::size_t nl = err.find('\n', start);
    if (nl == std::string_view::npos) nl = err.size();
    std::string line(err.substr(start, nl - start));
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    // The robot's own messages (its CLI's) share the stream; they are not what ssh said.
    if (!line.empty() && !line.starts_with("Warning: Permanently added") && !line.starts_with("benchscope-cli"))
      last = line;
    start = nl + 1;
  }
  return last;
}

std::string describe_ssh_failure(std::string_view host, std::string_view err) {
  const std::string h(host);
  std::string said = last_ssh_line(err);
  while (!said.empty() && said.back() == '.') said.pop_back();  // the sentence around it has its own full stop
  // ssh starts some of its own messages with "ssh: " already.
  const std::string quote = said.empty()                ? std::string("ssh said nothing")
                            : said.starts_with("ssh: ") ? said
                                                        : "ssh: " + said;
  if (contains(err, "REMOTE HOST IDENTIFICATION HAS CHANGED") || contains(err, "Host key for") ||
      contains(err, "host key has changed"))
    return h + ": the robot's host key has CHANGED since it was last accepted (" + quote +
           "). This is what a reinstalled robot or an attacker looks like: check it with the robot's owner, then "
           "remove the old key (ssh-keygen -R HOST) and connect once with `ssh " +
           h + "` in a terminal.";
  if (contains(err, "Host key verification failed") || contains(err, "host key is known") ||
      contains(err, "No matching host key"))
    return h + ": the robot's host key is not known here (" + quote +
           "). BenchScope never accepts a host key on its own: connect once with `ssh " + h +
           "` in a terminal, check the fingerprint and accept it, then try again.";
  if (contains(err, "Permission denied") || contains(err, "Too many authentication failures"))
    return h + ": the robot refused the login (" + quote +
           "). BenchScope logs in with your SSH keys and agent only, never with a password: install your public "
           "key there (ssh-copy-id " +
           h + ") and check that `ssh " + h +
           " true` works in a terminal without a "
           "prompt.";
  if (contains(err, "Could not resolve hostname") || contains(err, "Name or service not known"))
    return h + ": no such host (" + quote + "). Check the name, or add a Host entry for it to ~/.ssh/config.";
  if (contains(err, "Connection refused") || contains(err, "No route to host") ||
      contains(err, "Network is unreachable") || contains(err, "Connection timed out") ||
      contains(err, "Operation timed out") || contains(err, "connect to host"))
    return h + ": the robot cannot be reached (" + quote +
           "). Is it switched on, on this network, and running an SSH server?";
  if (contains(err, "closed by remote host") || contains(err, "Broken pipe") || contains(err, "Connection reset") ||
      contains(err, "not responding") || contains(err, "Connection closed") || contains(err, "Connection to"))
    return h + ": the connection to the robot was lost (" + quote + ").";
  return h + ": ssh failed (" + quote + ").";
}

}  // namespace bs::remote
