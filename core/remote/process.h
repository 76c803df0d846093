// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A child process with its stdin, stdout and stderr on pipes (POSIX, no Qt): the desk runs `ssh` this way, and the
// robot's job agent runs the measurement. The child gets a process group of its own, so a Ctrl+C typed at the
// desk's terminal reaches BenchScope (which then asks the robot to stop) and not ssh, and so the agent can stop a
// measurement with everything it started (record-power's command) in one kill.
#include <sys/types.h>

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bs::remote {

class ChildProcess {
 public:
  // Runs argv[0] (looked up on PATH when it has no slash). Throws std::runtime_error naming the program when it
  // cannot be found or started.
  explicit ChildProcess(const std::vector<std::string>& argv);
  // Forks and runs `body` in the child (no exec), its return value the exit status. For a caller that is single-
  // threaded at this point (the job agent): the child starts as a copy of it, and runs under qemu-user too, where
  // starting a foreign binary would need binfmt support.
  explicit ChildProcess(const std::function<int()>& body);
  ~ChildProcess();  // a child still running is killed (its whole group) and reaped
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  pid_t pid() const { return pid_; }
  // Writes all of `bytes` to the child's stdin; false when the child no longer reads it (never SIGPIPE).
  bool write_stdin(std::string_view bytes);
  void close_stdin();
  // Waits up to `timeout_ms` for output and hands what arrived to the callbacks. False once stdout and stderr are
  // both closed (the child and everything it started have let go of them).
  // `watch_fd` (when >= 0) is polled too, and `on_watch` called when it is readable or closed: the job agent
  // watches its own stdin (the desk's "cancel", or its end when the connection drops) this way.
  bool pump(int timeout_ms, const std::function<void(std::string_view)>& on_stdout,
            const std::function<void(std::string_view)>& on_stderr, int watch_fd = -1,
            const std::function<void()>& on_watch = {});
  // Sends `signal` to the child's process group.
  void kill_group(int signal);
  // The exit status once the child has ended (code, or 128 + signal): wait() blocks, try_wait() does not.
  int wait();
  std::optional<int> try_wait();

 private:
  void start(const std::function<void()>& in_child);
  pid_t pid_ = -1;
  int in_ = -1, out_ = -1, err_ = -1;
  std::optional<int> status_;
};

// Splits a byte stream into lines ('\n'; a '\r' before it is kept for the reader to judge). A line longer than
// `max_line` is handed over as it is at that length with `overlong` set, and the rest of it is dropped.
class LineSplitter {
 public:
  explicit LineSplitter(std::size_t max_line) : max_(max_line) {}
  void feed(std::string_view bytes, const std::function<void(std::string_view line, bool overlong)>& on_line);
  // What is left without a line end (the stream ended mid-line).
  const std::string& rest() const { return buffer_; }

 private:
  std::size_t max_;
  std::string buffer_;
  bool skipping_ = false;
};

// The exit status of a wait status: the code, or 128 + the signal that ended it.
int exit_status(int wait_status);

}  // namespace bs::remote
