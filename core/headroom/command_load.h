// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// An external command as a load (stress-ng, a ROS 2 launch, the lab's own workload): started in a process group of
// its own, its output kept (bounded), stopped with SIGINT (stress-ng then prints its metrics), SIGTERM after 2 s
// and SIGKILL after 2 s more. stress-ng's metrics ("bogo ops/s (real time)") give the achieved rate when it prints
// them (--metrics or --metrics-brief); otherwise the rate is unknown and said to be.
#include <sys/types.h>

#include <atomic>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "headroom/load.h"

namespace bs::headroom {

class CommandLoad : public Load {
 public:
  // `argv`: the program and its arguments (no shell); the program is looked up on PATH.
  explicit CommandLoad(std::vector<std::string> argv);
  ~CommandLoad() override;
  std::string name() const override;
  LoadKind kind() const override { return LoadKind::Command; }
  std::string detail() const override;
  std::string rate_unit() const override { return "bogo ops/s"; }
  void start() override;
  LoadReport stop() override;
  // What it printed (stdout and stderr, last 64 KiB); read it after stop().
  const std::string& output() const { return output_; }
  // True once the process has ended by itself (its status is kept for stop()'s note).
  bool has_exited();

 private:
  std::vector<std::string> argv_;
  pid_t pid_ = -1;
  int out_fd_ = -1;
  std::thread reader_;
  std::atomic<bool> stop_reading_{false};
  std::string output_;
  double started_s_ = 0;
  std::optional<int> exit_status_;  // reaped before stop()
};

// stress-ng's metrics table in `output`: "bogo ops/s (real time)" per stressor ("cpu: 1302.85 bogo ops/s"), and as
// the rate the one stressor's value when there is only one (different stressors' bogo ops do not add up); empty
// rate when no metrics line is there.
struct StressNgMetrics {
  std::optional<double> bogo_ops_per_s;
  std::vector<std::string> per_stressor;
};
StressNgMetrics parse_stress_ng_metrics(const std::string& output);

// Splits a command line into words: blanks separate, '...' and "..." quote, \ escapes (no expansion, no shell).
// Throws std::invalid_argument for an unclosed quote or an empty command.
std::vector<std::string> split_command(const std::string& line);

}  // namespace bs::headroom
