// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// NVIDIA ros2_benchmark's result JSON (github.com/NVIDIA-ISAAC-ROS/ros2_benchmark, results/*.json): a ROS 2 graph
// (one node, e.g. image_proc::RectifyNode) fed recorded messages, first at the peak rate its search found (the
// top level), then at fixed rates ("10.0fps", "30.0fps", "60.0fps"), each concluded over test_iterations runs with
// the best and the worst dropped (basic_performance_calculator.py). What each value is, as that code computes it:
//   MEAN_FRAME_RATE                   received frames / received duration, mean of the kept iterations
//   FIRST/LAST_SENT_RECEIVED_LATENCY  the latency of the FIRST (LAST) message only, mean of the iterations: not a
//                                     latency distribution and not a mean latency
//   MAX_JITTER / MIN_JITTER           the largest / smallest frame-to-frame jitter of the kept iterations
//   MEAN_JITTER                       the LARGEST of the iterations' mean jitters: a maximum, despite its name
//   STD_DEV_JITTER                    mean of the iterations' standard deviations
//   CPUProfilingMetrics.*_CPU_UTIL    CPU use in % of all cores, sampled every cpu_profiling_interval_sec
// One ResultSet per file: one measurement per value and run, its metric naming what it is; the node, input size,
// release (the CONFIG's default_config_version) and device come from the file's metadata.
#include "common/format_importer.h"

namespace bs {

extern const FileFormat kRos2BenchmarkJsonFileFormat;

}  // namespace bs
