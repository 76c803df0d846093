// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// ROS 2 rttest's summary statistics, in the two forms people keep:
//
// - the "_statistics" file that rttest's analyze.py (and ros2_realtime_benchmarks) writes beside a results log:
//     Min latency: 7049 / Max latency: 129592 / Mean latency: 11074.759716666667 / # of samples overrun: 1
//   analyze.py takes the absolute value of each latency first. Its "# of samples overrun" is len() of the tuple
//   numpy.where returns, which is 1 whatever the data: it is not a count, and is ignored with a warning.
// - the block rttest prints when the loop ends (pendulum_demo's stdout):
//     rttest statistics[ for FILE]: / - Minor pagefaults: 0 / - Major pagefaults: 0 /
//     Latency (time after deadline was missed): / - Min: 2414 ns / - Max: 45949 ns / - Mean: 8712.12 ns /
//     - Standard deviation: 1438.74
//   (older rttest: no "ns" after the values; one version adds "Missed deadlines", "Early deadlines" and a Jitter
//   section, whose Min/Max are not latencies). When the output holds several blocks, the last is the run's end.
//
// Latencies are in ns. Summary only (kind "application loop"): neither form says how many iterations ran, so n is
// unknown, and there is no distribution.
#include "common/format_importer.h"

namespace bs {

extern const FileFormat kRttestStatisticsFileFormat;  // id "rttest-statistics"

}  // namespace bs
