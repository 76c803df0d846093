// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// ROS 2 rttest's per-iteration results file (rttest -f FILE; pendulum_demo -f FILE writes it for its 1 kHz control
// loop): a header "iteration timestamp latency minor_pagefaults major_pagefaults" (older rttest: "minor_pagefaults
// minor_pagefaults"), then one line per loop iteration, "59999 59999000000 9277 0 0": the iteration, its intended
// start (iteration x update period, ns), the wake-up latency of the loop in ns (how late it started; negative when
// early), and the page faults in that iteration.
//
// An application loop's latency (kind "application loop"): every sample is kept in a 1 us histogram (up to 100 ms,
// the true maximum beyond), with exact mean and SD, and deadline misses (latency > the update period) counted
// iteration by iteration with the longest run. The period is the timestamps' step. The log does not record the
// scheduling policy, which is left unknown.
//
// Errors name the line: iterations out of order, a timestamp off the period's grid, a row without five integers.
// A last line without its line end is kept with a warning when whole, dropped with a warning when cut short.
#include "common/format_importer.h"

namespace bs {

extern const FileFormat kRttestLogFileFormat;  // id "rttest-log"

}  // namespace bs
