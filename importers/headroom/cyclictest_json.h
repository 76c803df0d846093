// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// cyclictest --json (rt-tests 2.x, src/lib/rt-utils.c rt_write_json and cyclictest's write_stats), with the keys as
// rt-tests really writes them, trailing colons included:
//
//   { "file_version": 1, "cmdline:": "cyclictest ...", "rt_test_version:": "2.80", "start_time": "Mon, 31 Aug 2026
//     00:23:41 -0500", "end_time": ..., "return_code": 0, "sysinfo": { "sysname", "nodename", "release", "version",
//     "machine", "realtime": 1 }, "num_threads": 6, "resolution_in_ns": 0,
//     "thread": { "0": { "histogram": { "2": 215519, ... }, "cycles": 300000, "min": 2, "max": 20, "avg": 2.56,
//                        "cpu": 6, "node": 0 }, ... } }
//
// The histogram lists only non-empty buckets and no overflow count: overflows are cycles minus the histogram's sum.
// Its size is the command line's -h/-H (else the highest bucket + 1, said in a note); resolution_in_ns 1 (-N) makes
// buckets and values nanoseconds. A thread without "histogram" (no -h) is summary only. sysinfo gives the kernel
// facts (release, version, PREEMPT_RT).
//
// What rt-tests gets wrong is read with a warning naming the line: the command line is written unescaped (a '"' or
// '\' in an argument breaks the JSON: that one string is re-escaped), and a thread that ran no cycle has "avg": -nan
// (read as no average). A JSON of another rt-tests program (oslat, ptsematest, ...) is refused by name.
#include "common/format_importer.h"

namespace bs {

extern const FileFormat kCyclictestJsonFileFormat;  // id "cyclictest-json"

}  // namespace bs
