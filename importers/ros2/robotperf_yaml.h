// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// RobotPerf's benchmark.yaml (github.com/robotperf/benchmarks, benchmarks/<category>/<id>_<name>/benchmark.yaml):
// a benchmark's id, name and description, and `results:`, a list of `- result:` entries with hardware (free text),
// metric (latency, throughput, power), metric_unit, value, category, datasource, note and "timestampt" (sic). What
// the value is: for latency the MAXIMUM of the run (the note's max_benchmark equals it), for throughput the MEAN
// (the note's mean_benchmark), for power the figure as reported (its statistic is not stated). Read with the strict
// YAML subset reader (ros2/yaml_subset.h): a duplicate key is refused with both lines. Flagged as warnings naming the
// line: impossible values (power <= 0 W, a non-positive latency or rate), free-text hardware names BenchScope cannot
// tie to one computer, and dates written day-or-month first (08-07-2023: August 7 or July 8?) beside ISO dates.
// One ResultSet per hardware name, in file order; every value's metric says what it is.
#include "common/format_importer.h"

namespace bs {

extern const FileFormat kRobotperfYamlFileFormat;

}  // namespace bs
