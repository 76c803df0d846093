// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Something that runs beside the control loop during one phase of a headroom measurement: BenchScope's vision
// pipeline at a camera rate, the detector, the FLOPS kernels, an external command. The runner starts it, lets it
// settle, measures the loop, and stops it; the load reports what it really achieved in that time, so a result
// reads "pipeline at 30 fps (29.6 fps achieved)" and a load that fell short or died is seen, not assumed.
#include <optional>
#include <string>
#include <vector>

#include "headroom/headroom_measurement.h"

namespace bs::headroom {

struct LoadReport {
  std::optional<double> achieved_rate;  // in Load::rate_unit(); empty when the load cannot say (an opaque command)
  std::vector<std::string> notes;       // "exited early (status 1) after 2.3 s", "fell short of 30 fps"
};

class Load {
 public:
  virtual ~Load() = default;
  virtual std::string name() const = 0;  // the phase's name: "pipeline@30fps", "flops W=4", "stress-ng --cpu 2"
  virtual LoadKind kind() const = 0;
  virtual std::string detail() const = 0;  // what exactly ran: frames and lens, network, command line
  virtual std::optional<double> target_rate() const { return std::nullopt; }
  virtual std::string rate_unit() const { return {}; }
  // Starts the load on threads or processes of its own and returns at once. Throws std::runtime_error saying why
  // it cannot run (a missing program, a frame that cannot be read).
  virtual void start() = 0;
  // Stops it (promptly: within about a second), waits for it and reports. Called once after start().
  virtual LoadReport stop() = 0;
  // The work completed since start(), in rate_unit() x seconds (GFLOP, frames, inferences), read from any thread
  // while the load runs: a sustained run (#53) takes its differences per interval to see the rate change over
  // minutes. Empty for a load that cannot count its work (an opaque command).
  virtual std::optional<double> work_done() const { return std::nullopt; }
};

}  // namespace bs::headroom
