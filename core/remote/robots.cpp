// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote/robots.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "util/host_clock.h"
#include "util/text.h"

namespace fs = std::filesystem;

namespace bs::remote {
namespace {

std::string home() {
  const char* h = std::getenv("HOME");
  return h ? h : "";
}

// Words of a config line: "Host a b" -> {"Host", "a", "b"}; "Host=a" -> {"Host", "a"}; quotes kept together.
std::vector<std::string> words(const std::string& line) {
  std::vector<std::string> w;
  std::string cur;
  bool quoted = false, first_eq = true;
  for (const char c : line) {
    if (c == '"') {
      quoted = !quoted;
      continue;
    }
    if (!quoted && (c == ' ' || c == '\t' || (c == '=' && first_eq && w.empty()))) {
      if (c == '=') first_eq = false;
      if (!cur.empty()) w.push_back(cur), cur.clear();
      continue;
    }
    cur += c;
  }
  if (!cur.empty()) w.push_back(cur);
  return w;
}

void read_hosts(const fs::path& file, std::vector<std::string>& hosts, int depth) {
  if (depth > 8) return;  // an Include loop
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    const auto w = words(line);
    if (w.size() < 2) continue;
    const std::string key = lower(w[0]);
    if (key == "host") {
      for (std::size_t i = 1; i < w.size(); ++i)
        if (w[i].find_first_of("*?!") == std::string::npos &&
            std::find(hosts.begin(), hosts.end(), w[i]) == hosts.end())
          hosts.push_back(w[i]);
    } else if (key == "include") {
      for (std::size_t i = 1; i < w.size(); ++i) {
        std::string pattern = w[i];
        if (pattern.starts_with("~/")) pattern = home() + pattern.substr(1);
        fs::path p(pattern);
        if (p.is_relative()) p = file.parent_path() / p;  // ssh: relative to ~/.ssh for the user's config
        // Only plain names and a '*' in the last part (Include config.d/*), as most configs use.
        if (p.filename().string().find('*') != std::string::npos) {
          std::vector<fs::path> found;
          std::error_code ec;
          const std::string pat = p.filename().string();
          const std::string pre = pat.substr(0, pat.find('*')), post = pat.substr(pat.find('*') + 1);
          for (const auto& e : fs::directory_iterator(p.parent_path(), ec)) {
            const std::string n = e.path().filename().string();
            if (n.size() >= pre.size() + post.size() && n.starts_with(pre) && n.ends_with(post)) found.push_back(e);
          }
          std::sort(found.begin(), found.end());
          for (const fs::path& f : found) read_hosts(f, hosts, depth + 1);
        } else {
          read_hosts(p, hosts, depth + 1);
        }
      }
    }
  }
}

nlohmann::json to_json(const Robot& r) {
  nlohmann::json runs = nlohmann::json::array();
  for (const RobotRun& x : r.runs)
    runs.push_back({{"date", x.date}, {"job_id", x.job_id}, {"command", x.command}, {"outcome", x.outcome}});
  return {{"name", r.name},
          {"added", r.added},
          {"config_file", r.config_file},
          {"remote_cli", r.remote_cli},
          {"platform", r.platform},
          {"last_contact", r.last_contact},
          {"last_ok", r.last_ok},
          {"last_problem", r.last_problem},
          {"hostname", r.hostname},
          {"arch", r.arch},
          {"cli_version", r.cli_version},
          {"devices", r.devices},
          {"runs", runs}};
}

Robot from_json(const nlohmann::json& j) {
  Robot r;
  const auto s = [&](const char* key) {
    const auto it = j.find(key);
    return it != j.end() && it->is_string() ? it->get<std::string>() : std::string();
  };
  r.name = s("name");
  r.added = j.value("added", false);
  r.config_file = s("config_file");
  r.remote_cli = s("remote_cli");
  r.platform = s("platform");
  r.last_contact = s("last_contact");
  r.last_ok = j.value("last_ok", false);
  r.last_problem = s("last_problem");
  r.hostname = s("hostname");
  r.arch = s("arch");
  r.cli_version = s("cli_version");
  r.devices = s("devices");
  if (const auto runs = j.find("runs"); runs != j.end() && runs->is_array())
    for (const auto& x : *runs)
      if (x.is_object())
        r.runs.push_back({x.value("date", ""), x.value("job_id", ""), x.value("command", ""), x.value("outcome", "")});
  return r;
}

}  // namespace

SshTarget Robot::target() const {
  SshTarget t;
  t.destination = name;
  t.config_file = config_file;
  if (!remote_cli.empty()) t.remote_cli = remote_cli;
  return t;
}

std::vector<std::string> ssh_config_hosts(const std::string& config_path) {
  std::vector<std::string> hosts;
  read_hosts(config_path, hosts, 0);
  return hosts;
}

std::string default_ssh_config() { return home() + "/.ssh/config"; }

std::string default_robots_file() {
  if (const char* x = std::getenv("XDG_CONFIG_HOME"); x && x[0] == '/')
    return std::string(x) + "/benchscope/robots.json";
  return home() + "/.config/benchscope/robots.json";
}

RobotList::RobotList(std::string file) : file_(std::move(file)) {
  std::ifstream in(file_);
  if (!in) return;
  nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object() || j.value("format", "") != "benchscope-robots" || !j.contains("robots") ||
      !j["robots"].is_array())
    throw std::runtime_error(file_ + ": not a BenchScope robots list (format benchscope-robots); move it away");
  for (const auto& r : j["robots"])
    if (r.is_object() && r.contains("name") && r["name"].is_string()) robots_.push_back(from_json(r));
}

std::vector<Robot> RobotList::all(const std::string& ssh_config) const {
  std::vector<Robot> list = robots_;
  const std::vector<std::string> hosts = ssh_config_hosts(ssh_config);
  for (Robot& r : list) r.from_ssh_config = std::find(hosts.begin(), hosts.end(), r.name) != hosts.end();
  for (const std::string& h : hosts)
    if (!find(h)) {
      Robot r;
      r.name = h;
      r.from_ssh_config = true;
      list.push_back(std::move(r));
    }
  return list;
}

const Robot* RobotList::find(const std::string& name) const {
  const auto it = std::find_if(robots_.begin(), robots_.end(), [&](const Robot& r) { return r.name == name; });
  return it == robots_.end() ? nullptr : &*it;
}

Robot& RobotList::entry(const std::string& name) {
  auto it = std::find_if(robots_.begin(), robots_.end(), [&](const Robot& r) { return r.name == name; });
  if (it != robots_.end()) return *it;
  Robot r;
  r.name = name;
  robots_.push_back(std::move(r));
  return robots_.back();
}

void RobotList::put(const Robot& robot) {
  entry(robot.name) = robot;
  save();
}

bool RobotList::remove(const std::string& name) {
  const auto n = robots_.size();
  std::erase_if(robots_, [&](const Robot& r) { return r.name == name; });
  if (n == robots_.size()) return false;
  save();
  return true;
}

void RobotList::record_check(const std::string& name, const RobotCheck& check, const SshTarget& target) {
  Robot& r = entry(name);
  r.last_contact = utc_timestamp();
  r.last_ok = check.ok;
  r.last_problem = check.problem;
  // What a failed login could not see stays as last seen; a robot reached says what it has (no CLI: none).
  if (!check.info.hostname.empty()) {
    r.hostname = check.info.hostname;
    r.cli_version = check.info.cli_version;
  }
  if (!check.info.arch.empty()) r.arch = check.info.arch;
  if (check.ok) r.devices = check.info.devices_text();
  r.config_file = target.config_file;
  r.remote_cli = target.remote_cli == "benchscope-cli" ? std::string() : target.remote_cli;
  save();
}

void RobotList::record_run(const std::string& name, const RobotRun& run) {
  Robot& r = entry(name);
  r.runs.push_back(run);
  if (r.runs.size() > kMaxRobotRuns) r.runs.erase(r.runs.begin(), r.runs.end() - kMaxRobotRuns);
  save();
}

void RobotList::save() const {
  nlohmann::json list = nlohmann::json::array();
  for (const Robot& r : robots_) list.push_back(to_json(r));
  const nlohmann::json doc = {{"format", "benchscope-robots"}, {"version", 1}, {"robots", list}};
  const fs::path path(file_);
  std::error_code ec;
  fs::create_directories(path.parent_path(), ec);
  const std::string tmp = file_ + ".tmp" + std::to_string(getpid());
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << doc.dump(2) << '\n';
    out.flush();
    if (!out) {
      const int e = errno;
      fs::remove(tmp, ec);
      throw std::runtime_error("cannot save the robots list " + file_ + ": " + std::strerror(e));
    }
  }
  fs::rename(tmp, path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw std::runtime_error("cannot save the robots list " + file_ + ": " + ec.message());
  }
}

RobotRun robot_run_started(const std::string& job_id, const std::vector<std::string>& command) {
  return {utc_timestamp(), job_id, join(command, " "), {}};
}

std::string robot_run_outcome(const std::string& job_status, const std::string& what) {
  const bool partial = job_status == "cancelled" || job_status == "interrupted";
  return partial ? job_status + ", " + what : what;
}

}  // namespace bs::remote
