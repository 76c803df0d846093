// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote/job_client.h"

#include <signal.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>

#include "remote/base64.h"
#include "remote/process.h"
#include "store/workspace.h"

namespace fs = std::filesystem;

namespace bs::remote {
namespace {

constexpr int kPollMs = 100;
constexpr std::uint64_t kMaxFileBytes = std::uint64_t{64} << 30;  // a result file larger than 64 GiB is refused
constexpr std::size_t kKeptStderr = 64 * 1024;

// The text of a line for a message: at most 100 characters, control characters shown as '?'.
std::string excerpt(std::string_view line) {
  std::string s;
  for (const char c : line.substr(0, 100)) s += static_cast<unsigned char>(c) < ' ' ? '?' : c;
  return line.size() > 100 ? s + "..." : s;
}

bool safe_file_name(const std::string& name) {
  return !name.empty() && name.size() <= 128 && name.front() != '.' &&
         name.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789._-") ==
             std::string::npos;
}

// One ssh session carrying an event stream, from start to the end of ssh.
// Starts `ssh` to run `command_line` on the robot; a missing or unstartable ssh is a RemoteError saying what to
// install.
void start_ssh(std::optional<ChildProcess>& ssh, const SshTarget& t, const std::string& command_line) {
  try {
    ssh.emplace(ssh_argv(t, command_line));
  } catch (const std::exception& e) {
    throw RemoteError(t.destination + ": cannot start ssh: " + e.what() +
                      " (BenchScope uses the system's OpenSSH client: apt install openssh-client)");
  }
}

class Session {
 public:
  Session(const SshTarget& t, const std::vector<std::string>& words, const std::string& staging,
          const JobHandlers& handlers, const JobControl& control)
      : target_(t), staging_(staging), handlers_(handlers), control_(control), lines_(kMaxEventLineBytes) {
    command_line_ = shell_command(words);
    start_ssh(ssh_, t, command_line_);
  }

  RemoteJob run(bool expect_job_end) {
    while (ssh_->pump(
        kPollMs, [&](std::string_view bytes) { on_stdout(bytes); },
        [&](std::string_view bytes) { on_stderr(bytes); })) {
      if (!problem_.empty()) stop_ssh();
      if (control_.aborted() && !aborted_) {
        aborted_ = true;
        stop_ssh();
      } else if (control_.cancelled() && !cancel_sent_) {
        cancel_sent_ = true;
        ssh_->write_stdin("cancel\n");
      }
    }
    if (!lines_.rest().empty() && problem_.empty()) on_line(lines_.rest(), false);
    flush_stderr_line();
    const int status = ssh_->wait();
    files_.clear();
    const std::string host = target_.destination;
    const std::string fetch_hint = job_.id.empty() ? std::string()
                                                   : " What the robot finished is kept there as job " + job_.id +
                                                         ": `benchscope-cli remote " + host + " fetch " + job_.id +
                                                         "` brings it home.";
    if (!problem_.empty()) throw RemoteError(problem_ + " Nothing was imported." + fetch_hint);
    if (aborted_) throw RemoteError(host + ": stopped here; nothing was imported." + fetch_hint);
    if (expect_job_end && ended_) {
      job_.remote_command_line = command_line_;
      return job_;
    }
    if (!expect_job_end && status == 0) return job_;
    if (status == 255) {
      std::string what = describe_ssh_failure(host, stderr_);
      // Once the robot has answered, an ssh failure is the link going down (ssh may say no more than its status).
      if (saw_event_ && what.find("connection to the robot was lost") == std::string::npos)
        what = host + ": the connection to the robot was lost during the job (" +
               (last_ssh_line(stderr_).empty() ? std::string("ssh exited with status 255")
                                               : "ssh: " + last_ssh_line(stderr_)) +
               ").";
      throw RemoteError(what + " Nothing was imported." + fetch_hint);
    }
    if (status == 127 || (!saw_event_ && (stderr_.find("not found") != std::string::npos ||
                                          stderr_.find("No such file") != std::string::npos)))
      throw RemoteError(host + ": BenchScope's CLI is not there ('" + target_.remote_cli +
                        "': " + excerpt(last_ssh_line(stderr_)) + "). `benchscope-cli remote " + host +
                        " check` says how to install it.");
    if (!saw_event_ && status != 0)
      throw RemoteError(host + ": '" + target_.remote_cli + "' did not answer as BenchScope's CLI does (status " +
                        std::to_string(status) + ": " + excerpt(last_ssh_line(stderr_)) +
                        "); is it older than this BenchScope? `benchscope-cli remote " + host + " check` tells.");
    std::string why = !job_.error.empty() ? job_.error : excerpt(last_ssh_line(stderr_));
    throw RemoteError(host + ": the robot's side ended (status " + std::to_string(status) + ") before the job was " +
                      "complete" + (why.empty() ? std::string(".") : ": " + why + ".") + " Nothing was imported." +
                      fetch_hint);
  }

  const std::vector<Event>& events() const { return kept_; }
  void keep_events(bool keep) { keep_ = keep; }

 private:
  void stop_ssh() {
    ssh_->close_stdin();  // the agent sees the end of its stdin and stops the measurement
    ssh_->kill_group(SIGTERM);
  }

  void on_stderr(std::string_view bytes) {
    if (stderr_.size() < kKeptStderr) stderr_.append(bytes.substr(0, kKeptStderr - stderr_.size()));
    for (const char c : bytes) {
      if (c == '\n') {
        flush_stderr_line();
      } else if (c != '\r' && err_line_.size() < 4096) {
        err_line_ += c;
      }
    }
  }
  void flush_stderr_line() {
    if (!err_line_.empty() && handlers_.on_remote_stderr) handlers_.on_remote_stderr(err_line_);
    err_line_.clear();
  }

  void on_stdout(std::string_view bytes) {
    if (!problem_.empty()) return;
    lines_.feed(bytes, [&](std::string_view line, bool overlong) { on_line(line, overlong); });
  }

  void on_line(std::string_view line, bool overlong) {
    if (!problem_.empty()) return;
    ++line_no_;
    const std::string host = target_.destination;
    Event e;
    try {
      if (overlong) throw EventError("a line longer than " + std::to_string(kMaxEventLineBytes) + " bytes");
      e = parse_event(line);
    } catch (const EventError& why) {
      problem_ = host + ": the robot wrote something that is not a BenchScope event on its output (line " +
                 std::to_string(line_no_) + ": \"" + excerpt(line) + "\": " + why.what() + ").";
      if (!saw_event_)
        problem_ += " A login script that prints on non-interactive shells (~/.bashrc), or a '" + target_.remote_cli +
                    "' that is not BenchScope's CLI, does this.";
      return;
    }
    saw_event_ = true;
    try {
      handle(e);
    } catch (const EventError& why) {
      problem_ = host + ": the robot sent a broken event (line " + std::to_string(line_no_) + "): " + why.what() + ".";
    } catch (const RemoteError& why) {
      problem_ = why.what();
    }
  }

  void handle(const Event& e) {
    if (e.type == "file") {
      receive_chunk(e);
      return;
    }
    if (keep_) kept_.push_back(e);
    if (e.type == "job") {
      job_.record = e.body;
      job_.id = string_field(e, "id");
    } else if (e.type == "error") {
      if (const auto m = e.body.find("message"); m != e.body.end() && m->is_string())
        job_.error = m->get<std::string>();
    } else if (e.type == "job_end") {
      finish(e);
    }
    if (handlers_.on_event) handlers_.on_event(e);
  }

  void receive_chunk(const Event& e) {
    const std::string name = string_field(e, "name");
    if (!safe_file_name(name)) throw EventError("file event: '" + excerpt(name) + "' is not a plain file name");
    const auto size = static_cast<std::uint64_t>(integer_field(e, "size", 0, static_cast<std::int64_t>(kMaxFileBytes)));
    const auto offset = static_cast<std::uint64_t>(integer_field(e, "offset", 0, static_cast<std::int64_t>(size)));
    const auto bytes = base64_decode(string_field(e, "data"));
    if (!bytes) throw EventError("file event: 'data' is not base64");
    Staged& f = staged_[name];
    if (!f.out) {
      std::error_code ec;
      fs::create_directories(staging_, ec);
      f.path = (fs::path(staging_) / name).string();
      f.out = std::make_unique<std::ofstream>(f.path, std::ios::binary | std::ios::trunc);
      if (!*f.out)
        throw RemoteError(target_.destination + ": cannot write the robot's results to " + f.path +
                          " here: " + std::strerror(errno) + ".");
    }
    if (offset != f.written || f.written + bytes->size() > size)
      throw EventError("file event: " + name + " arrives out of order or beyond its size");
    f.out->write(bytes->data(), static_cast<std::streamsize>(bytes->size()));
    f.out->flush();
    if (!*f.out)
      throw RemoteError(target_.destination + ": cannot write the robot's results to " + f.path + " here (" +
                        std::strerror(errno) + ": a full disk?).");
    f.written += bytes->size();
  }

  void finish(const Event& e) {
    job_.status = string_field(e, "status");
    job_.exit_status = static_cast<int>(integer_field(e, "exit_status", -1000, 1000));
    const auto files = e.body.find("files");
    if (files == e.body.end() || !files->is_array()) throw EventError("job_end event: no 'files' list");
    for (const auto& f : *files) {
      if (!f.is_object() || !f.contains("name") || !f["name"].is_string() || !f.contains("hash") ||
          !f["hash"].is_string() || !f.contains("size") || !f["size"].is_number_unsigned())
        throw EventError("job_end event: a file without name, size and hash");
      const std::string name = f["name"].get<std::string>();
      auto it = staged_.find(name);
      if (it == staged_.end() && f["size"].get<std::uint64_t>() == 0) {  // an empty file sends no chunk
        Event empty{"file", {{"name", name}, {"size", 0}, {"offset", 0}, {"data", ""}}};
        receive_chunk(empty);
        it = staged_.find(name);
      }
      if (it == staged_.end()) throw EventError("job_end event: " + name + " was listed but never sent");
      it->second.out->close();
      if (it->second.written != f["size"].get<std::uint64_t>() ||
          file_content_hash(it->second.path) != f["hash"].get<std::string>())
        throw RemoteError(target_.destination + ": " + name + " arrived damaged (size or hash differs from the " +
                          "robot's).");
      job_.files.push_back(it->second.path);
    }
    ended_ = true;
  }

  struct Staged {
    std::string path;
    std::unique_ptr<std::ofstream> out;
    std::uint64_t written = 0;
  };

  const SshTarget& target_;
  std::string staging_;
  const JobHandlers& handlers_;
  const JobControl& control_;
  std::optional<ChildProcess> ssh_;
  std::string command_line_;
  LineSplitter lines_;
  std::string stderr_, err_line_, problem_;
  std::map<std::string, Staged> staged_;
  std::vector<std::string> files_;
  RemoteJob job_;
  std::vector<Event> kept_;
  bool keep_ = false, saw_event_ = false, ended_ = false, cancel_sent_ = false, aborted_ = false;
  int line_no_ = 0;
};

}  // namespace

std::string staged_file(const RemoteJob& job, const std::string& name) {
  for (const std::string& f : job.files)
    if (std::filesystem::path(f).filename() == name) return f;
  return {};
}

std::vector<std::string> job_run_words(const SshTarget& t, const std::string& id,
                                       const std::vector<std::string>& command) {
  std::vector<std::string> words = {t.remote_cli, "job", "run", "--id", id, "--"};
  words.insert(words.end(), command.begin(), command.end());
  return words;
}

RemoteJob run_remote_job(const SshTarget& t, const std::string& id, const std::vector<std::string>& command,
                         const std::string& staging_dir, const JobHandlers& handlers, const JobControl& control) {
  Session s(t, job_run_words(t, id, command), staging_dir, handlers, control);
  return s.run(true);
}

RemoteJob fetch_remote_job(const SshTarget& t, const std::string& id, const std::string& staging_dir,
                           const JobHandlers& handlers, const JobControl& control) {
  std::vector<std::string> words = {t.remote_cli, "job", "fetch"};
  if (!id.empty()) words.insert(words.end(), {"--id", id});
  Session s(t, words, staging_dir, handlers, control);
  return s.run(true);
}

std::vector<nlohmann::json> list_remote_jobs(const SshTarget& t, const JobControl& control) {
  const JobHandlers none;
  Session s(t, {t.remote_cli, "job", "list"}, {}, none, control);
  s.keep_events(true);
  s.run(false);
  std::vector<nlohmann::json> jobs;
  for (const Event& e : s.events())
    if (e.type == "job") jobs.push_back(e.body);
  return jobs;
}

void send_job_input(const SshTarget& t, const std::string& id, const std::string& name, const std::string& local_path,
                    const JobControl& control) {
  std::ifstream in(local_path, std::ios::binary);
  std::error_code ec;
  const auto size = std::filesystem::file_size(local_path, ec);
  if (!in || ec) throw RemoteError(local_path + ": cannot read it to send to " + t.destination);
  const std::string line = shell_command({t.remote_cli, "job", "put", "--id", id, "--name", name, "--size",
                                          std::to_string(static_cast<unsigned long long>(size))});
  std::optional<ChildProcess> ssh;
  start_ssh(ssh, t, line);
  std::string err;
  const auto keep_err = [&](std::string_view b) {
    if (err.size() < kKeptStderr) err.append(b);
  };
  std::string chunk(64 * 1024, '\0');
  bool sent = true;
  while (in && sent) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    if (in.gcount() > 0) sent = ssh->write_stdin(std::string_view(chunk.data(), static_cast<std::size_t>(in.gcount())));
    ssh->pump(
        0, [](std::string_view) {}, keep_err);  // ssh's own words (a refused login) while the bytes go
    if (control.aborted() || control.cancelled()) {
      ssh->kill_group(SIGTERM);
      sent = false;
    }
  }
  ssh->close_stdin();
  while (ssh->pump(
      kPollMs, [](std::string_view) {}, keep_err)) {
  }
  const int status = ssh->wait();
  if (status == 0 && sent) return;
  if (control.aborted() || control.cancelled())
    throw RemoteError(t.destination + ": stopped while sending " + local_path + "; nothing ran");
  if (status == 255) throw RemoteError(describe_ssh_failure(t.destination, err));
  throw RemoteError(t.destination + ": could not take " + local_path + " (" + last_ssh_line(err) + ")");
}

RemoteOutput run_remote_command(const SshTarget& t, const std::string& command_line, const JobControl& control) {
  std::optional<ChildProcess> ssh;
  start_ssh(ssh, t, command_line);
  RemoteOutput r;
  ssh->close_stdin();
  while (ssh->pump(
      kPollMs,
      [&](std::string_view b) {
        if (r.out.size() < kMaxEventLineBytes * 4) r.out.append(b);
      },
      [&](std::string_view b) {
        if (r.err.size() < kKeptStderr) r.err.append(b);
      })) {
    if (control.aborted() || control.cancelled()) ssh->kill_group(SIGTERM);
  }
  r.status = ssh->wait();
  return r;
}

}  // namespace bs::remote
