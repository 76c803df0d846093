// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The end of a load that works on a thread of its own (the pipeline, the detector, the FLOPS kernels), the same for
// each: wait for the thread, and let a failure speak for itself.
#include <optional>
#include <string>
#include <string_view>
#include <thread>

#include "headroom/load.h"

namespace bs::headroom {

// Waits for the load's `worker` thread, told to stop already. When its work threw (`error`: what it caught), the
// report is that alone ("detector failed: ..."), since what it counted until then is no achieved rate; else nullopt,
// and the load reports what it did.
inline std::optional<LoadReport> join_worker(std::thread& worker, const std::string& error, std::string_view what) {
  if (worker.joinable()) worker.join();
  if (error.empty()) return std::nullopt;
  LoadReport r;
  r.notes.push_back(std::string(what) + " failed: " + error);
  return r;
}

}  // namespace bs::headroom
