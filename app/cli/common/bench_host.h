// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the `bench` commands read of the machine around a timing: this process's CPU time (how many cores a method
// kept busy) and the load average (a busy neighbour on a shared machine explains a slow run). One copy for every
// bench command, so that they all say it alike.
#include <string>

namespace bs::cli {

// CPU seconds of every thread of this process so far (CLOCK_PROCESS_CPUTIME_ID).
double process_cpu_seconds();
// "0.52 (1 min), 0.40 (5 min)", or "unknown" when /proc/loadavg cannot be read.
std::string load_average_text();
// The 1-minute load average, or -1 when /proc/loadavg cannot be read.
double one_minute_load();

}  // namespace bs::cli
