// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote/robot_check.h"

#include <cctype>
#include <sstream>

#include "analysis/stats/units.h"

namespace bs::remote {
namespace {

constexpr const char* kMarker = "benchscope-probe-v1";

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

std::string str(const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_string() ? it->get<std::string>() : std::string();
}

}  // namespace

int compare_versions(const std::string& a, const std::string& b) {
  std::size_t i = 0, j = 0;
  while (i < a.size() || j < b.size()) {
    long long x = 0, y = 0;
    while (i < a.size() && std::isdigit(static_cast<unsigned char>(a[i]))) x = x * 10 + (a[i++] - '0');
    while (j < b.size() && std::isdigit(static_cast<unsigned char>(b[j]))) y = y * 10 + (b[j++] - '0');
    if (x != y) return x < y ? -1 : 1;
    // Skip one separator (or anything that is not a digit) on each side.
    if (i < a.size()) ++i;
    if (j < b.size()) ++j;
  }
  return 0;
}

std::string debian_architecture(const std::string& m) {
  if (m == "x86_64" || m == "amd64") return "amd64";
  if (m == "aarch64" || m == "arm64") return "arm64";
  if (m.starts_with("armv7") || m.starts_with("armv8l") || m == "armhf") return "armhf";
  if (m == "i686" || m == "i386") return "i386";
  if (m == "riscv64") return "riscv64";
  return m;
}

std::string install_command(const std::string& destination, const std::string& machine, const std::string& version) {
  const std::string deb = "benchscope-cli_" + version + "_" + debian_architecture(machine) + ".deb";
  return "scp " + deb + " " + destination + ": && ssh -t " + destination + " sudo apt install ./" + deb;
}

std::string RobotInfo::devices_text() const {
  std::string text = arch.empty() ? std::string("unknown architecture") : arch;
  if (!os.empty()) text += ", " + os;
  for (const RobotBackend& b : backends) {
    text += "; " + b.label + ": " + b.device;
    if (b.theoretical_peak_flops > 0) text += " (peak " + format_si(b.theoretical_peak_flops, "FLOPS") + ")";
  }
  std::string power;
  for (const RobotSensor& s : sensors)
    if (s.readable) power += (power.empty() ? "" : ", ") + s.id;
  text += "; power sensors: " + (power.empty() ? std::string("none readable") : power);
  return text;
}

std::string probe_command(const std::string& cli, const std::string& sysfs_root) {
  const std::string q = shell_quote(cli);
  const std::string root = sysfs_root.empty() ? std::string() : " --sysfs-root " + shell_quote(sysfs_root);
  const std::string script = std::string("echo ") + kMarker + "; uname -m; uname -n; if command -v " + q +
                             " >/dev/null 2>&1; then " + q + " --version; echo \"benchscope-probe-status $?\"; " + q +
                             " job probe" + root + " 2>/dev/null; else echo benchscope-probe-missing; fi";
  return "sh -c " + shell_quote(script);
}

void read_robot_event(const nlohmann::json& j, RobotInfo& info) {
  if (!j.is_object()) throw EventError("robot event: not an object");
  if (const std::string h = str(j, "host"); !h.empty()) info.hostname = h;
  if (const std::string a = str(j, "arch"); !a.empty()) info.arch = a;
  info.os = str(j, "os");
  info.cpu = str(j, "cpu");
  info.sensor_note = str(j, "sensor_note");
  info.jobs_dir = str(j, "jobs_dir");
  info.backends.clear();
  info.sensors.clear();
  if (const auto b = j.find("backends"); b != j.end() && b->is_array())
    for (const auto& x : *b) {
      if (!x.is_object()) continue;
      RobotBackend r{str(x, "id"), str(x, "label"), str(x, "device"), str(x, "kind"), 0};
      if (const auto p = x.find("theoretical_peak_flops"); p != x.end() && p->is_number())
        r.theoretical_peak_flops = p->get<double>();
      if (!r.id.empty()) info.backends.push_back(std::move(r));
    }
  if (const auto s = j.find("sensors"); s != j.end() && s->is_array())
    for (const auto& x : *s) {
      if (!x.is_object()) continue;
      RobotSensor r{
          str(x, "id"),    str(x, "label"), str(x, "kind"), x.value("readable", false), x.value("board_total", false),
          str(x, "reason")};
      if (!r.id.empty()) info.sensors.push_back(std::move(r));
    }
}

RobotCheck read_probe(const std::string& destination, const std::string& desk_version, const RemoteOutput& output,
                      const std::string& remote_cli) {
  RobotCheck c;
  c.info.destination = destination;
  if (output.status == 255) {
    c.problem = describe_ssh_failure(destination, output.err);
    return c;
  }
  const std::vector<std::string> lines = split_lines(output.out);
  std::size_t i = 0;
  while (i < lines.size() && lines[i] != kMarker) c.info.login_noise.push_back(lines[i++]);
  if (i == lines.size()) {
    c.problem = destination + ": the robot did not run the check (status " + std::to_string(output.status) +
                (last_ssh_line(output.err).empty() ? std::string() : ": " + last_ssh_line(output.err)) +
                "); its login shell must be able to run `sh -c`.";
    c.info.login_noise.clear();
    return c;
  }
  ++i;
  if (i < lines.size()) c.info.arch = lines[i++];
  if (i < lines.size()) c.info.hostname = lines[i++];
  const std::string fix_text = install_command(destination, c.info.arch, desk_version);
  if (i < lines.size() && lines[i] == "benchscope-probe-missing") {
    c.problem = destination + " (" + c.info.hostname + ", " + c.info.arch + "): BenchScope's CLI is not installed " +
                "there ('" + remote_cli + "' is not found there" +
                (remote_cli.find('/') == std::string::npos ? std::string(" on the login shell's PATH") : "") + ").";
    c.fix = fix_text;
    return c;
  }
  std::string version_line = i < lines.size() ? lines[i++] : std::string();
  std::string status_line = i < lines.size() ? lines[i++] : std::string();
  const std::string prefix = "benchscope-cli ";
  if (!version_line.starts_with(prefix) || status_line != "benchscope-probe-status 0") {
    c.problem = destination + ": '" + remote_cli + "' there is not BenchScope's CLI, or does not work (it answered '" +
                version_line.substr(0, 100) + "' to --version).";
    c.fix = fix_text;
    return c;
  }
  c.info.cli_version = version_line.substr(prefix.size());
  if (compare_versions(c.info.cli_version, desk_version) < 0) {
    c.problem = destination + ": its BenchScope CLI is " + c.info.cli_version + ", older than this desk's " +
                desk_version + "; install the matching package.";
    c.fix = fix_text;
    return c;
  }
  bool probed = false;
  for (; i < lines.size(); ++i) {
    try {
      const Event e = parse_event(lines[i]);
      if (e.type == "robot") {
        read_robot_event(e.body, c.info);
        probed = true;
      }
    } catch (const EventError&) {  // anything else it printed is not ours to judge here
    }
  }
  if (!probed) {
    c.problem = destination + ": its BenchScope CLI " + c.info.cli_version + " did not describe the robot (" +
                "`job probe` failed: " + last_ssh_line(output.err) + ").";
    return c;
  }
  c.ok = true;
  return c;
}

RobotCheck check_robot(const SshTarget& target, const JobControl& control, const std::string& sysfs_root) {
  check_destination(target.destination);
  const RemoteOutput out = run_remote_command(target, probe_command(target.remote_cli, sysfs_root), control);
  return read_probe(target.destination, BENCHSCOPE_VERSION, out, target.remote_cli);
}

}  // namespace bs::remote
