// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// cyclictest's text output (rt-tests), as people keep it: system wake-up latency of periodic real-time threads.
//
// - the histogram of -h/-H (stdout or --histfile): "# Histogram", rows "000004 013847\t003773" (bucket, one count per
//   thread, tab-separated), then "# Min Latencies:", "# Avg Latencies:", "# Max Latencies:", "# Histogram Overflows:"
//   and "# Histogram Overflow at cycle number:" with a "# Thread N:" line each. Before rt-tests 2.7 every row of the
//   histogram is printed and "# Total:" (the binned count per thread) follows the rows; from 2.7 on rows whose every
//   count is 0 are left out and there is no total. -H adds a sum column to the rows (and, with more than one thread,
//   to the Max and Overflows lines). Counts are one bucket per microsecond, or per nanosecond with -N.
// - the footer alone, when someone stripped the rows: summary statistics only.
// - a terminal capture: the "T: 0 ( 1234) P:99 I:1000 C: 349868 Min: 4 Act: 6 Avg: 5 Max: 35" status lines, redrawn
//   with cursor-up codes (kept by `script`, or shown as ^[[2A by `cat -v`), the "policy: fifo: loadavg: ..." line,
//   and a shell prompt naming the command, with or without a histogram after them.
//
// One HeadroomMeasurement, kind system wake-up latency, one thread per histogram column (or T: line). Cycles are the
// binned counts plus the overflows, the true maximum is the footer's. What the command line says (a prompt line, or
// the JSON paired with a --histfile) gives the period, the histogram's size, policy, priority and -N; without it the
// unit is cyclictest's default (us) and the histogram's size is what its rows show.
//
// Errors name the line: a histogram without its footer (cut), rows out of order or with the wrong number of
// columns, a "# Total:" or sum column that disagrees with the rows, a footer whose columns disagree. A last line
// without its line end is a warning.
#include "common/format_importer.h"

namespace bs {

extern const FileFormat kCyclictestTextFileFormat;  // id "cyclictest-text"

}  // namespace bs
