// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/command_load.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <cstring>
#include <sstream>
#include <stdexcept>

extern char** environ;

namespace bs::headroom {
namespace {

constexpr std::size_t kKeptOutput = 64 * 1024;

double monotonic_s() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

void sleep_ms(int ms) {
  const timespec ts{0, ms * 1'000'000L};
  nanosleep(&ts, nullptr);
}

std::string status_text(int status) {
  if (WIFEXITED(status)) return "status " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return std::string("signal ") + strsignal(WTERMSIG(status));
  return "status " + std::to_string(status);
}

std::string quoted(const std::string& word) {
  if (!word.empty() && word.find_first_of(" \t'\"\\") == std::string::npos) return word;
  std::string out = "'";
  for (char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

CommandLoad::CommandLoad(std::vector<std::string> argv) : argv_(std::move(argv)) {
  if (argv_.empty() || argv_.front().empty()) throw std::invalid_argument("an external load needs a command");
}

CommandLoad::~CommandLoad() {
  if (pid_ > 0) (void)stop();
}

std::string CommandLoad::name() const {
  std::string n;
  for (std::size_t i = 0; i < argv_.size() && n.size() < 60; ++i) n += (i ? " " : "") + quoted(argv_[i]);
  return n;
}

std::string CommandLoad::detail() const {
  std::string d;
  for (const std::string& w : argv_) d += (d.empty() ? "" : " ") + quoted(w);
  return d;
}

void CommandLoad::start() {
  if (pid_ > 0) throw std::logic_error("command load started twice");
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("cannot create a pipe: ") + strerror(errno));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, fds[1], 1);
  posix_spawn_file_actions_adddup2(&actions, fds[1], 2);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  // A process group of its own, so stopping reaches every process it forks (stress-ng's workers); default signal
  // handling, whatever this process ignores.
  posix_spawnattr_setpgroup(&attr, 0);
  sigset_t none, all;
  sigemptyset(&none);
  sigfillset(&all);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setsigdefault(&attr, &all);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  std::vector<char*> args;
  for (std::string& a : argv_) args.push_back(a.data());
  args.push_back(nullptr);
  pid_t pid = -1;
  const int e = posix_spawnp(&pid, argv_.front().c_str(), &actions, &attr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attr);
  close(fds[1]);
  if (e != 0) {
    close(fds[0]);
    throw std::runtime_error(argv_.front() + ": cannot start (" + strerror(e) + ")");
  }
  pid_ = pid;
  out_fd_ = fds[0];
  started_s_ = monotonic_s();
  stop_reading_ = false;
  reader_ = std::thread([this] {
    char buffer[4096];
    pollfd p{out_fd_, POLLIN, 0};
    while (!stop_reading_) {
      if (poll(&p, 1, 50) <= 0) continue;
      const ssize_t n = read(out_fd_, buffer, sizeof buffer);
      if (n <= 0) break;
      output_.append(buffer, static_cast<std::size_t>(n));
      if (output_.size() > 2 * kKeptOutput) output_.erase(0, output_.size() - kKeptOutput);
    }
  });
}

bool CommandLoad::has_exited() {
  if (exit_status_) return true;
  if (pid_ <= 0) return false;
  int status = 0;
  if (waitpid(pid_, &status, WNOHANG) != pid_) return false;
  exit_status_ = status;
  return true;
}

LoadReport CommandLoad::stop() {
  LoadReport report;
  if (pid_ <= 0) return report;
  int status = 0;
  if (has_exited()) {
    status = *exit_status_;
    report.notes.push_back(argv_.front() + " exited (" + status_text(status) + ") before the phase ended, after " +
                           std::to_string(static_cast<int>(monotonic_s() - started_s_)) + " s");
    kill(-pid_, SIGKILL);  // what it left running in its group
  } else {
    // SIGINT first (stress-ng prints its metrics on it), then SIGTERM, then SIGKILL, 2 s apart.
    bool done = false;
    for (int sig : {SIGINT, SIGTERM, SIGKILL}) {
      kill(-pid_, sig);
      for (int i = 0; i < 200 && !done; ++i) {
        if (waitpid(pid_, &status, WNOHANG) == pid_)
          done = true;
        else
          sleep_ms(10);
      }
      if (done) break;
      if (sig != SIGKILL) report.notes.push_back(argv_.front() + " ignored " + (sig == SIGINT ? "SIGINT" : "SIGTERM"));
    }
    if (!done) waitpid(pid_, &status, 0);
    kill(-pid_, SIGKILL);  // any process of its group still alive
  }
  pid_ = -1;
  exit_status_.reset();
  // The reader ends at end of file; a process that left the group and keeps the pipe open must not hold us.
  for (int i = 0; i < 100 && out_fd_ >= 0; ++i) {
    pollfd p{out_fd_, POLLIN | POLLHUP, 0};
    if (poll(&p, 1, 0) > 0 && (p.revents & POLLHUP) && !(p.revents & POLLIN)) break;
    sleep_ms(10);
  }
  stop_reading_ = true;
  if (reader_.joinable()) reader_.join();
  close(out_fd_);
  out_fd_ = -1;
  if (output_.size() > kKeptOutput) output_.erase(0, output_.size() - kKeptOutput);
  const StressNgMetrics metrics = parse_stress_ng_metrics(output_);
  report.achieved_rate = metrics.bogo_ops_per_s;
  for (const std::string& s : metrics.per_stressor) report.notes.push_back(s);
  return report;
}

StressNgMetrics parse_stress_ng_metrics(const std::string& output) {
  // stress-ng: metrc: [32006] stressor       bogo ops real time  usr time  sys time   bogo ops/s     bogo ops/s
  // stress-ng: metrc: [32006]                           (secs)    (secs)    (secs)   (real time) (usr+sys time)
  // stress-ng: metrc: [32006] cpu                2611      2.00      1.54      0.00      1302.85        1693.64
  // (older versions tag the lines "info:" instead of "metrc:"; later columns may follow)
  StressNgMetrics m;
  std::istringstream lines(output);
  std::string line;
  bool in_table = false;
  std::vector<double> rates;
  while (std::getline(lines, line)) {
    if (line.find("bogo ops/s") != std::string::npos && line.find("stressor") != std::string::npos) {
      in_table = true;
      continue;
    }
    if (!in_table) continue;
    const auto bracket = line.find("] ");
    if (line.rfind("stress-ng:", 0) != 0 || bracket == std::string::npos) {
      in_table = false;
      continue;
    }
    std::istringstream words(line.substr(bracket + 2));
    std::string stressor;
    double ops = 0, real = 0, usr = 0, sys = 0, rate = 0;
    if (!(words >> stressor >> ops >> real >> usr >> sys >> rate)) continue;  // the "(secs)" line, a summary
    char text[160];
    std::snprintf(text, sizeof text, "%s: %.2f bogo ops/s", stressor.c_str(), rate);
    m.per_stressor.push_back(text);
    rates.push_back(rate);
  }
  if (rates.size() == 1) m.bogo_ops_per_s = rates.front();
  return m;
}

std::vector<std::string> split_command(const std::string& line) {
  std::vector<std::string> words;
  std::string word;
  bool in_word = false;
  char quote = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quote) {
      if (c == quote)
        quote = 0;
      else if (c == '\\' && quote == '"' && i + 1 < line.size())
        word += line[++i];
      else
        word += c;
    } else if (c == '\'' || c == '"') {
      quote = c;
      in_word = true;
    } else if (c == '\\' && i + 1 < line.size()) {
      word += line[++i];
      in_word = true;
    } else if (c == ' ' || c == '\t') {
      if (in_word) words.push_back(word);
      word.clear();
      in_word = false;
    } else {
      word += c;
      in_word = true;
    }
  }
  if (quote) throw std::invalid_argument("unclosed " + std::string(1, quote) + " in command '" + line + "'");
  if (in_word) words.push_back(word);
  if (words.empty()) throw std::invalid_argument("empty command");
  return words;
}

}  // namespace bs::headroom
