// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote/process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdio_ext.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <stdexcept>
#include <string_view>

namespace bs::remote {
namespace {

// An executable file for `program`: itself when it names a path, else the first match on PATH.
std::string find_program(const std::string& program) {
  if (program.find('/') != std::string::npos) return program;
  const char* path = std::getenv("PATH");
  std::string_view dirs = path ? path : "/usr/local/bin:/usr/bin:/bin";
  while (true) {
    const std::size_t colon = dirs.find(':');
    const std::string_view dir = dirs.substr(0, colon);
    std::string candidate(dir.empty() ? std::string_view(".") : dir);
    candidate.push_back('/');
    candidate.append(program);
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
    if (colon == std::string_view::npos) break;
    dirs.remove_prefix(colon + 1);
  }
  throw std::runtime_error("'" + program + "' is not installed here (not found on PATH)");
}

// Closes every descriptor from 3 up (async-signal-safe: a forked child of a threaded parent may call it). The
// close_range system call where the kernel has it (5.9+), else one close() per possible descriptor.
void close_from_3(long open_max) {
#if defined(SYS_close_range)
  if (syscall(SYS_close_range, 3U, ~0U, 0U) == 0) return;
#endif
  const long top = open_max > 0 && open_max < 65536 ? open_max : 65536;
  for (long fd = 3; fd < top; ++fd) close(static_cast<int>(fd));
}

void make_pipe(int fds[2]) {
  if (pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("cannot make a pipe: ") + std::strerror(errno));
}

void close_fd(int& fd) {
  if (fd >= 0) close(fd);
  fd = -1;
}

}  // namespace

int exit_status(int ws) { return WIFEXITED(ws) ? WEXITSTATUS(ws) : WIFSIGNALED(ws) ? 128 + WTERMSIG(ws) : 1; }

ChildProcess::ChildProcess(const std::vector<std::string>& argv) {
  if (argv.empty()) throw std::runtime_error("no program to run");
  const std::string path = find_program(argv[0]);
  // Everything the child needs is prepared before fork: a multi-threaded parent (the GUI) may only make
  // async-signal-safe calls in the child until exec.
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  start([&] {
    execv(path.c_str(), args.data());
    const char msg[] = "cannot start the program\n";
    (void)!write(2, msg, sizeof msg - 1);
    _exit(127);
  });
}

ChildProcess::ChildProcess(const std::function<int()>& body) {
  start([&] {
    // What the parent had buffered for its own stdout is not the child's to write.
    __fpurge(stdout);
    const int code = body();
    _exit(code);
  });
}

void ChildProcess::start(const std::function<void()>& in_child) {
  int in[2], out[2], err[2];
  make_pipe(in);
  make_pipe(out);
  make_pipe(err);
  // Signals stay blocked across fork until the child has its own handling: a signal sent to the new group at once
  // (a cancel) must meet the default action, not a copy of the parent's handler.
  const long open_max = sysconf(_SC_OPEN_MAX);
  sigset_t all, old;
  sigfillset(&all);
  pthread_sigmask(SIG_SETMASK, &all, &old);
  pid_ = fork();
  if (pid_ < 0) {
    const int e = errno;
    pthread_sigmask(SIG_SETMASK, &old, nullptr);
    for (int fd : {in[0], in[1], out[0], out[1], err[0], err[1]}) close(fd);
    throw std::runtime_error(std::string("cannot start a process: ") + std::strerror(e));
  }
  if (pid_ == 0) {
    setpgid(0, 0);
    // Default signal handling for the child, whatever the parent set (SIGPIPE ignored, Ctrl+C handlers).
    for (int sig : {SIGPIPE, SIGINT, SIGTERM, SIGHUP, SIGQUIT}) signal(sig, SIG_DFL);
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, nullptr);
    dup2(in[0], 0);
    dup2(out[1], 1);
    dup2(err[1], 2);
    // Nothing else of the parent's: a pipe it holds (the agent's stdin from sshd, a test's) must close when the
    // parent closes it, not live on in the child.
    close_from_3(open_max);
    in_child();
    _exit(127);
  }
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
  setpgid(pid_, pid_);  // also here, so the group exists before the parent signals it
  close(in[0]);
  close(out[1]);
  close(err[1]);
  in_ = in[1];
  out_ = out[0];
  err_ = err[0];
}

ChildProcess::~ChildProcess() {
  if (pid_ > 0 && !status_) {
    kill_group(SIGKILL);
    wait();
  }
  close_fd(in_);
  close_fd(out_);
  close_fd(err_);
}

bool ChildProcess::write_stdin(std::string_view bytes) {
  if (in_ < 0) return false;
  // SIGPIPE blocked on this thread for the write, and a pending one consumed, so a closed pipe is an error code
  // and never ends the process (the GUI's or the agent's).
  sigset_t pipe_set, old;
  sigemptyset(&pipe_set);
  sigaddset(&pipe_set, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipe_set, &old);
  bool ok = true;
  while (!bytes.empty()) {
    const ssize_t n = write(in_, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      ok = false;
      if (errno == EPIPE) {
        const timespec zero{0, 0};
        sigtimedwait(&pipe_set, nullptr, &zero);
      }
      break;
    }
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
  if (!ok) close_stdin();
  return ok;
}

void ChildProcess::close_stdin() { close_fd(in_); }

bool ChildProcess::pump(int timeout_ms, const std::function<void(std::string_view)>& on_stdout,
                        const std::function<void(std::string_view)>& on_stderr, int watch_fd,
                        const std::function<void()>& on_watch) {
  if (out_ < 0 && err_ < 0) return false;
  pollfd fds[3] = {{out_, POLLIN, 0}, {err_, POLLIN, 0}, {watch_fd, POLLIN, 0}};
  const int n = poll(fds, watch_fd >= 0 ? 3 : 2, timeout_ms);
  if (n < 0 && errno != EINTR) throw std::runtime_error(std::string("poll: ") + std::strerror(errno));
  if (n <= 0) return true;
  if (watch_fd >= 0 && (fds[2].revents & (POLLIN | POLLHUP | POLLERR | POLLNVAL)) && on_watch) on_watch();
  char buf[65536];
  for (int i = 0; i < 2; ++i) {
    if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
    const ssize_t got = read(fds[i].fd, buf, sizeof buf);
    if (got < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (got <= 0) {
      close_fd(i == 0 ? out_ : err_);
      continue;
    }
    const auto& sink = i == 0 ? on_stdout : on_stderr;
    if (sink) sink(std::string_view(buf, static_cast<std::size_t>(got)));
  }
  return out_ >= 0 || err_ >= 0;
}

void ChildProcess::kill_group(int signal) {
  if (pid_ > 0 && !status_) ::kill(-pid_, signal);
}

int ChildProcess::wait() {
  if (status_) return *status_;
  int ws = 0;
  while (waitpid(pid_, &ws, 0) < 0) {
    if (errno != EINTR) {
      status_ = 1;
      return *status_;
    }
  }
  status_ = exit_status(ws);
  return *status_;
}

std::optional<int> ChildProcess::try_wait() {
  if (status_) return status_;
  int ws = 0;
  const pid_t r = waitpid(pid_, &ws, WNOHANG);
  if (r == pid_) status_ = exit_status(ws);
  return status_;
}

void LineSplitter::feed(std::string_view bytes,
                        const std::function<void(std::string_view line, bool overlong)>& on_line) {
  while (!bytes.empty()) {
    const std::size_t nl = bytes.find('\n');
    const std::string_view piece = bytes.substr(0, nl);
    if (skipping_) {
      if (nl != std::string_view::npos) skipping_ = false;
    } else if (buffer_.size() + piece.size() > max_) {
      buffer_.append(piece.substr(0, max_ - buffer_.size()));
      on_line(buffer_, true);
      buffer_.clear();
      skipping_ = nl == std::string_view::npos;
    } else {
      buffer_.append(piece);
      if (nl != std::string_view::npos) {
        on_line(buffer_, false);
        buffer_.clear();
      }
    }
    if (nl == std::string_view::npos) break;
    bytes.remove_prefix(nl + 1);
  }
}

}  // namespace bs::remote
