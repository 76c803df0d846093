// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The terminal form of a headroom measurement: the kernel's real-time facts, the policy the probe obtained (a
// non-real-time run says so first), the table per phase and thread, and the flags and notes.
#include <iosfwd>
#include <string>

#include "headroom/headroom_measurement.h"

namespace bs::cli {

void print_headroom(std::ostream& out, const headroom::HeadroomMeasurement& m, const std::string& source);
// "kernel 6.1.0-18-amd64 (PREEMPT_DYNAMIC, not PREEMPT_RT), governor performance, isolcpus none, nohz_full none"
std::string kernel_line(const headroom::KernelFacts& k);

}  // namespace bs::cli
