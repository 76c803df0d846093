// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// ROS 2 graph benchmark results (ros2_benchmark, RobotPerf) of the chosen library computers as one table: the
// Platforms tab's "ROS 2 graph benchmarks" table, its CSV, and `library compare --json`. Rows stay in their class
// (tool, node, input, release, measure: graph_benchmark_classes()), and every row says what its value IS, because the
// tools' names mislead: ros2_benchmark's "latency" is the first message's only, its "mean jitter" a maximum,
// RobotPerf's latency the run's maximum.
#include <span>

#include "analysis/library/library.h"
#include "util/table_export.h"

namespace bs {

// Columns: Measure, Computer, Value, What the value is, Rank, the rest of the class (Benchmark, Input, Release,
// Tool), Source (URL and cited lines). A result's plausibility flags are numbered footnotes, as in the candidates
// table. Rank 1 is the best of its class (highest rate, lowest latency, CPU use or power); a class of one row says
// "only result".
ExportTable graph_benchmarks_table(std::span<const GraphBenchmarkClass> classes, const Library& lib);

}  // namespace bs
