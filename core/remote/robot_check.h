// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The first contact with a robot: can we log in, what is it (architecture, host name), is BenchScope's CLI there
// and as new as the desk's, what can it measure (its backends and devices) and with which power sensors. One ssh
// connection; a missing or older CLI gives the one command that installs the matching package.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "remote/job_client.h"
#include "remote/ssh.h"

namespace bs::remote {

struct RobotBackend {
  std::string id;      // "cpu-simd", "opencl:0", "cuda:0": what `run flops --backend` takes
  std::string label;   // "CPU SIMD (AVX2)"
  std::string device;  // "Intel(R) Core(TM) i7-7567U CPU @ 3.50GHz"
  std::string kind;    // "cpu", "gpu"
  double theoretical_peak_flops = 0;
};

struct RobotSensor {
  std::string id, label, kind;
  bool readable = false, board_total = false;
  std::string reason;  // why not readable
};

struct RobotInfo {
  std::string destination;  // as the user named it
  std::string hostname;     // the robot's own name (uname -n)
  std::string arch;         // uname -m: x86_64, aarch64
  std::string cli_version;  // "0.1.0"; empty when the CLI is missing
  std::string os, cpu;
  std::vector<RobotBackend> backends;
  std::vector<RobotSensor> sensors;
  std::string sensor_note;               // what `auto` would record
  std::string jobs_dir;                  // where the robot keeps its jobs
  std::vector<std::string> login_noise;  // lines a login script printed before ours (they break event streams)
  // "x86_64; CPU SIMD (AVX2): Intel ...; OpenCL: ...; power: rapl:package-0 (auto)", for provenance and lists.
  std::string devices_text() const;
};

struct RobotCheck {
  bool ok = false;  // reachable, CLI there and not older than the desk's: measurements can run
  RobotInfo info;
  std::string problem;  // when not ok: what is wrong, naming the host
  std::string fix;      // the one command that puts it right (install the package), when there is one
};

// Compares dotted versions numerically ("0.10.0" > "0.9.2"); -1, 0, 1.
int compare_versions(const std::string& a, const std::string& b);
// Debian's name for `uname -m`'s architecture: amd64, arm64, armhf, ... (the machine name itself when unknown).
std::string debian_architecture(const std::string& uname_machine);
// The one line, typed at the desk, that installs BenchScope's CLI package of `version` on the robot.
std::string install_command(const std::string& destination, const std::string& uname_machine,
                            const std::string& version);

// What the probe runs on the robot (through `sh -c`, whatever the login shell). `sysfs_root`: where the robot's
// sensors are looked for (the measurement's --sysfs-root), empty for /.
std::string probe_command(const std::string& remote_cli, const std::string& sysfs_root = {});
// Reads the probe's output; `desk_version` is this BenchScope's. Never throws for the robot's output.
RobotCheck read_probe(const std::string& destination, const std::string& desk_version, const RemoteOutput& output,
                      const std::string& remote_cli);
// Connects and checks. Throws RemoteError only when ssh cannot be started; an unreachable robot is a RobotCheck
// with its problem.
RobotCheck check_robot(const SshTarget& target, const JobControl& control = {}, const std::string& sysfs_root = {});

// The `robot` event `benchscope-cli job probe` prints, read into `info`. Throws EventError.
void read_robot_event(const nlohmann::json& body, RobotInfo& info);

}  // namespace bs::remote
