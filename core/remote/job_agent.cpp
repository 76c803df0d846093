// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote/job_agent.h"

#include <pwd.h>
#include <signal.h>
#include <sys/utsname.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <random>
#include <stdexcept>

#include "remote/base64.h"
#include "remote/events.h"
#include "remote/process.h"
#include "store/workspace.h"
#include "util/host_clock.h"

namespace fs = std::filesystem;

namespace bs::remote {
namespace {

constexpr std::size_t kChunkBytes = 48 * 1024;  // 64 KiB of base64 per "file" event
constexpr int kPollMs = 100;
constexpr int kPollsBeforeKill = 50;  // after SIGTERM, SIGKILL follows once the group had ~5 s to stop

std::atomic<int> g_signal{0};
extern "C" void on_agent_signal(int s) { g_signal.store(s); }

std::string machine_architecture() {
  utsname u{};
  return uname(&u) == 0 ? std::string(u.machine) : std::string("unknown");
}

nlohmann::json read_record(const fs::path& file) {
  std::ifstream in(file);
  if (!in) return nullptr;
  nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  return j.is_object() ? j : nlohmann::json(nullptr);
}

// job.json through a temporary file and a rename: a reader sees the old record or the new one, never half.
void save_record(const fs::path& dir, const nlohmann::json& record) {
  const fs::path tmp = dir / (std::string(kJobRecordFile) + ".tmp");
  {
    std::ofstream f(tmp, std::ios::trunc);
    f << record.dump(2) << '\n';
    f.flush();
    if (!f) throw std::runtime_error("cannot write " + tmp.string() + ": " + std::strerror(errno));
  }
  fs::rename(tmp, dir / kJobRecordFile);
}

nlohmann::json job_event_fields(const nlohmann::json& record, const fs::path& dir) {
  nlohmann::json j = record;
  j.erase("format");
  j.erase("version");
  j["dir"] = dir.string();
  return j;
}

// The job's result files: every regular file but the record and the event log (the workspace and, after a crash,
// its write-ahead log with committed data), by name.
std::vector<std::string> result_files(const fs::path& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (!entry.is_regular_file() || name == kJobRecordFile || name == "events.jsonl" || name.ends_with(".tmp") ||
        name.ends_with("-shm") || name.ends_with("-journal"))
      continue;
    names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

nlohmann::json file_list(const fs::path& dir) {
  nlohmann::json files = nlohmann::json::array();
  for (const std::string& name : result_files(dir)) {
    std::error_code ec;
    const auto size = fs::file_size(dir / name, ec);
    if (ec) continue;
    files.push_back({{"name", name}, {"size", size}, {"hash", file_content_hash((dir / name).string())}});
  }
  return files;
}

// The files as "file" events, chunk by chunk. False when a file cannot be read (an "error" event says which).
bool stream_files(EventWriter& ev, const fs::path& dir, const nlohmann::json& files) {
  for (const auto& f : files) {
    const std::string name = f["name"].get<std::string>();
    std::ifstream in(dir / name, std::ios::binary);
    if (!in) {
      ev.error("cannot read " + (dir / name).string() + ": " + std::strerror(errno));
      return false;
    }
    const auto size = f["size"].get<std::uint64_t>();
    std::uint64_t offset = 0;
    std::string chunk(kChunkBytes, '\0');
    do {
      in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
      const auto got = static_cast<std::size_t>(in.gcount());
      ev.write("file", {{"name", name},
                        {"size", size},
                        {"offset", offset},
                        {"data", base64_encode(std::string_view(chunk.data(), got))}});
      offset += got;
    } while (in && offset < size);
  }
  return true;
}

std::string now_iso() { return utc_timestamp(); }

}  // namespace

std::string default_jobs_dir() {
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && x[0] == '/') return std::string(x) + "/benchscope/remote";
  const char* home = std::getenv("HOME");
  std::string h = home && home[0] ? home : "";
  if (h.empty())
    if (const passwd* pw = getpwuid(getuid())) h = pw->pw_dir;
  return h + "/.cache/benchscope/remote";
}

void check_job_id(const std::string& id) {
  const bool ok = !id.empty() && id.size() <= 64 && id.front() != '.' && std::all_of(id.begin(), id.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' ||
           c == '.';
  });
  if (!ok) throw std::invalid_argument("'" + id + "' is not a job id (1 to 64 letters, digits, '-', '_' or '.')");
}

std::string new_job_id() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  localtime_r(&t, &tm);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &tm);
  std::random_device rd;
  char tail[16];
  std::snprintf(tail, sizeof tail, "%06x", static_cast<unsigned>(rd() & 0xffffff));
  return std::string(stamp) + "-" + tail;
}

void check_input_name(const std::string& name) {
  // "3/capture.raw": a numbered folder keeps the desk file's own name (a frame and its sidecar side by side, a model
  // under the name it is stored by).
  const auto slash = name.find('/');
  const std::string folder = slash == std::string::npos ? std::string() : name.substr(0, slash);
  const std::string file = slash == std::string::npos ? name : name.substr(slash + 1);
  const bool folder_ok = slash == std::string::npos ||
                         (!folder.empty() && folder.size() <= 9 &&
                          std::all_of(folder.begin(), folder.end(), [](char c) { return c >= '0' && c <= '9'; }));
  const bool ok = folder_ok && !file.empty() && file.size() <= 128 && file.front() != '.' &&
                  std::all_of(file.begin(), file.end(), [](char c) {
                    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' ||
                           c == '_' || c == '.';
                  });
  if (!ok)
    throw std::invalid_argument("'" + name +
                                "' is not an input file name (1 to 128 letters, digits, '-', '_' or '.', after an "
                                "optional numbered folder: 3/capture.raw)");
}

int put_job_input(const std::string& jobs_dir, const std::string& id, const std::string& name, std::uint64_t size,
                  int fd, std::ostream& err) {
  try {
    check_job_id(id);
    check_input_name(name);
  } catch (const std::invalid_argument& e) {
    err << "benchscope-cli: error: " << e.what() << '\n';
    return 1;
  }
  if (size > kJobInputLimit) {
    err << "benchscope-cli: error: " << name << ": " << size << " bytes is more than a job input may be ("
        << (kJobInputLimit >> 30) << " GiB)\n";
    return 1;
  }
  const fs::path dir = fs::path(jobs_dir) / id;
  std::error_code ec;
  if (fs::exists(dir / kJobRecordFile, ec)) {
    err << "benchscope-cli: error: job " << id << " has run already: its inputs cannot change\n";
    return 1;
  }
  const fs::path target = dir / kJobInputsFolder / name, tmp = target.string() + ".tmp";
  fs::create_directories(target.parent_path(), ec);
  if (ec) {
    err << "benchscope-cli: error: cannot make " << target.parent_path().string() << ": " << ec.message() << '\n';
    return 1;
  }
  std::uint64_t got = 0;
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    std::string chunk(64 * 1024, '\0');
    while (f && got < size) {
      const ssize_t n =
          read(fd, chunk.data(), static_cast<std::size_t>(std::min<std::uint64_t>(chunk.size(), size - got)));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      f.write(chunk.data(), n);
      got += static_cast<std::uint64_t>(n);
    }
    f.flush();
    if (!f) {
      err << "benchscope-cli: error: cannot write " << target.string() << ": " << std::strerror(errno) << '\n';
      fs::remove(tmp, ec);
      return 1;
    }
  }
  if (got < size) {
    err << "benchscope-cli: error: " << name << ": the desk sent " << got << " of " << size
        << " bytes (the connection ended early); nothing kept\n";
    fs::remove(tmp, ec);
    return 1;
  }
  fs::rename(tmp, target, ec);
  if (ec) {
    err << "benchscope-cli: error: cannot keep " << target.string() << ": " << ec.message() << '\n';
    fs::remove(tmp, ec);
    return 1;
  }
  return 0;
}

int run_job_agent(const AgentJob& job, std::ostream& out, std::ostream& err) {
  EventWriter ev(out);
  // The desk may vanish at any time: a write to its closed pipe must be an error, not the end of the agent
  // (which still has to stop the measurement).
  signal(SIGPIPE, SIG_IGN);
  try {
    check_job_id(job.id);
  } catch (const std::invalid_argument& e) {
    ev.error(e.what());
    ev.write("job_end", {{"id", job.id}, {"status", "failed"}, {"exit_status", 2}, {"files", nlohmann::json::array()}});
    return 1;
  }
  const fs::path dir = fs::path(job.jobs_dir) / job.id;
  std::error_code ec;
  fs::create_directories(job.jobs_dir, ec);
  // A job whose inputs came first (`job put`) has its folder already, with no record in it.
  if (!ec) fs::create_directory(dir, ec);
  std::error_code exists_ec;
  if (ec || fs::exists(dir / kJobRecordFile, exists_ec)) {
    ev.error("cannot make the job folder " + dir.string() + ": " +
             (ec ? ec.message() : std::string("it exists already (a job id is used once)")));
    ev.write("job_end", {{"id", job.id}, {"status", "failed"}, {"exit_status", 1}, {"files", nlohmann::json::array()}});
    return 1;
  }
  nlohmann::json record = {{"format", "benchscope-remote-job"},
                           {"version", 1},
                           {"id", job.id},
                           {"command", job.command},
                           {"cli_version", BENCHSCOPE_VERSION},
                           {"host", host_name()},
                           {"arch", machine_architecture()},
                           {"started", now_iso()},
                           {"status", "running"},
                           {"agent_pid", static_cast<long long>(getpid())}};
  try {
    save_record(dir, record);
  } catch (const std::exception& e) {
    ev.error(e.what());
    ev.write("job_end", {{"id", job.id}, {"status", "failed"}, {"exit_status", 1}, {"files", nlohmann::json::array()}});
    return 1;
  }
  ev.write("job", job_event_fields(record, dir));

  g_signal.store(0);
  struct sigaction sa {};
  sa.sa_handler = on_agent_signal;
  sigemptyset(&sa.sa_mask);
  for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaction(s, &sa, nullptr);

  std::ofstream log(dir / "events.jsonl", std::ios::app);
  std::ofstream output(dir / kJobOutputFile, std::ios::binary | std::ios::trunc);
  std::size_t output_bytes = 0;
  // The robot's disk is the robot's: a command that prints without end is kept up to the limit only.
  const auto keep_output = [&](std::string_view bytes) {
    if (output_bytes >= kJobOutputLimit) return;
    const std::size_t room = kJobOutputLimit - output_bytes;
    output.write(bytes.data(), static_cast<std::streamsize>(std::min(room, bytes.size())));
    output_bytes += std::min(room, bytes.size());
    if (output_bytes >= kJobOutputLimit)
      output << "\n[the rest of the output was not kept: " << (kJobOutputLimit >> 20) << " MiB kept]\n";
    output.flush();
  };
  out.flush();  // nothing of ours left in the stream's buffer for the forked child to write again
  ChildProcess child([&] { return job.body(dir.string()); });
  record["child_pid"] = static_cast<long long>(child.pid());
  try {
    save_record(dir, record);
  } catch (const std::exception&) {  // the record is for `jobs` and fetch; the run goes on without the pid in it
  }

  LineSplitter out_lines(kMaxEventLineBytes), err_lines(64 * 1024), in_lines(4096);
  bool saw_end = false, cancel_sent = false, hangup = false, stdin_open = job.stdin_fd >= 0;
  int child_status_in_event = 0, kill_countdown = -1;
  std::string last_error;
  const auto forward = [&](std::string_view line, bool overlong) {
    std::string text(line);
    try {
      if (overlong) throw EventError("an overlong line");
      const Event e = parse_event(text);
      if (e.type == "end") {
        saw_end = true;
        if (const auto s = e.body.find("status"); s != e.body.end() && s->is_number_integer())
          child_status_in_event = s->get<int>();
      }
      if (e.type == "error")
        if (const auto m = e.body.find("message"); m != e.body.end() && m->is_string())
          last_error = m->get<std::string>();
    } catch (const EventError&) {
      // Something in the measurement printed plain text on stdout (a driver, a library): passed on as a message, so
      // the desk's stream stays events only.
      ev.message("info", text);
      log << text << '\n';
      return;
    }
    out << text << '\n' << std::flush;
    log << text << '\n';
  };
  const auto stop_group = [&](int signal) {
    child.kill_group(signal);
    if (kill_countdown < 0) kill_countdown = kPollsBeforeKill;
  };
  const auto on_stdin = [&] {
    char buf[512];
    const ssize_t n = read(job.stdin_fd, buf, sizeof buf);
    if (n < 0 && errno == EINTR) return;
    if (n <= 0) {  // the desk is gone (or closed its end on purpose): stop everything
      stdin_open = false;
      hangup = true;
      stop_group(SIGTERM);
      return;
    }
    in_lines.feed(std::string_view(buf, static_cast<std::size_t>(n)), [&](std::string_view line, bool) {
      while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.remove_suffix(1);
      if (line == "cancel" && !cancel_sent) {
        cancel_sent = true;
        child.kill_group(SIGINT);  // as Ctrl+C: the command stops within a chunk and keeps what it completed
      }
    });
  };
  while (child.pump(
      kPollMs, [&](std::string_view bytes) { out_lines.feed(bytes, forward); },
      [&](std::string_view bytes) {
        err << bytes << std::flush;
        keep_output(bytes);
        err_lines.feed(bytes, [&](std::string_view line, bool) {
          if (!line.empty()) last_error = std::string(line);
        });
      },
      stdin_open ? job.stdin_fd : -1, on_stdin)) {
    if (g_signal.load() != 0 && !hangup) {
      hangup = true;
      stop_group(SIGTERM);
    }
    if (kill_countdown > 0 && --kill_countdown == 0) child.kill_group(SIGKILL);
  }
  if (!out_lines.rest().empty()) forward(out_lines.rest(), false);
  // Whatever of the group closed its output but still runs goes now, while the child (a zombie until waited for)
  // still holds the group's id.
  child.kill_group(SIGKILL);
  const int status = child.wait();
  const bool cancelled = cancel_sent && !hangup;
  const std::string outcome = hangup ? "interrupted" : cancel_sent ? "cancelled" : status == 0 ? "done" : "failed";
  if (!saw_end) {
    ev.error(last_error.empty() ? "the command ended with status " + std::to_string(status) + " without a word"
                                : last_error);
    ev.end(status, cancelled);
  }
  (void)child_status_in_event;
  output.close();
  std::error_code output_ec;
  if (output_bytes == 0) fs::remove(dir / kJobOutputFile, output_ec);  // nothing printed, nothing to send
  const nlohmann::json files = file_list(dir);
  record["status"] = outcome;
  record["exit_status"] = status;
  record["ended"] = now_iso();
  record["files"] = files;
  if (!last_error.empty() && status != 0) record["message"] = last_error;
  try {
    save_record(dir, record);
  } catch (const std::exception& e) {
    err << "benchscope-cli: " << e.what() << '\n';
  }
  if (hangup) return 0;  // nobody to send the files to: `remote HOST fetch` gets them
  stream_files(ev, dir, files);
  ev.write("job_end", {{"id", job.id}, {"status", outcome}, {"exit_status", status}, {"files", files}});
  return 0;
}

namespace {

struct JobFolder {
  fs::path dir;
  nlohmann::json record;
};

std::vector<JobFolder> job_folders(const std::string& jobs_dir) {
  std::vector<JobFolder> jobs;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(jobs_dir, ec)) {
    if (!entry.is_directory()) continue;
    nlohmann::json r = read_record(entry.path() / kJobRecordFile);
    if (r.is_object() && r.value("id", "") == entry.path().filename().string()) jobs.push_back({entry.path(), r});
  }
  std::sort(jobs.begin(), jobs.end(), [](const JobFolder& a, const JobFolder& b) {
    return std::pair(a.record.value("started", ""), a.dir.string()) <
           std::pair(b.record.value("started", ""), b.dir.string());
  });
  return jobs;
}

}  // namespace

int fetch_job_agent(const std::string& jobs_dir, const std::string& id, std::ostream& out) {
  EventWriter ev(out);
  signal(SIGPIPE, SIG_IGN);
  std::vector<JobFolder> jobs = job_folders(jobs_dir);
  const JobFolder* job = nullptr;
  if (id.empty()) {
    if (!jobs.empty()) job = &jobs.back();
  } else {
    for (const JobFolder& j : jobs)
      if (j.record.value("id", "") == id) job = &j;
  }
  if (!job) {
    ev.error(id.empty() ? "no job on this robot (" + jobs_dir + " holds none)"
                        : "no job '" + id + "' on this robot (in " + jobs_dir + ")");
    return 1;
  }
  std::string status = job->record.value("status", "");
  if (status == "running") {
    const long long pid = job->record.value("agent_pid", 0LL);
    if (pid > 0 && kill(static_cast<pid_t>(pid), 0) == 0) {
      ev.write("job", job_event_fields(job->record, job->dir));
      ev.error("job '" + job->record.value("id", "") + "' is still running on this robot");
      return 1;
    }
    status = "interrupted";  // its agent is gone without saying how it ended (killed, the robot rebooted)
  }
  ev.write("job", job_event_fields(job->record, job->dir));
  const nlohmann::json files = file_list(job->dir);
  if (!stream_files(ev, job->dir, files)) return 1;
  ev.write("job_end", {{"id", job->record.value("id", "")},
                       {"status", status},
                       {"exit_status", job->record.value("exit_status", 1)},
                       {"files", files}});
  return 0;
}

int list_jobs_agent(const std::string& jobs_dir, std::ostream& out) {
  EventWriter ev(out);
  for (const JobFolder& j : job_folders(jobs_dir)) ev.write("job", job_event_fields(j.record, j.dir));
  ev.end(0, false);
  return 0;
}

}  // namespace bs::remote
