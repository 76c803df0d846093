// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a file cannot say about itself: one set of options for every importer. Each format reads the fields it
// knows and ignores the rest. import_file() uses the defaults below (and what the file's own comments and
// context say); callers that know more (the CLI's --supply-volts, a GUI dialog, the importer API) pass them to
// Importer::parse(), import_power_log() or a parse_X() function.
#include <optional>
#include <string>

namespace bs {

struct ParseOptions {
  // Power logs (power CSV, tegrastats, jtop, nvidia-smi, perf stat, PTDaemon).
  // Supply voltage of a current-only log, used to turn current into power. Overrides a "# supply_voltage_V:"
  // comment. Left empty, such a trace keeps supply_voltage_v empty (power unknown until a platform gives it).
  std::optional<double> supply_voltage_v;
  // Seconds between tegrastats lines that carry no timestamp (tegrastats --interval, default 1000 ms).
  double interval_s = 1.0;
  // Platform name when the file does not name one ("# platform: NUC"). Left empty, the log has none: a board family
  // is not a platform (a TX2's and an Orin's tegrastats both say "Jetson"), so the import asks or guesses
  // (common/log_platform.h), never "Jetson" for every board (issue #43.3).
  std::string platform;

  // Google Benchmark JSON: which argument of the benchmark name is the worker count of a FLOPS sweep. Left
  // empty, the context key "benchscope_workers_argument" (Google Benchmark >= 1.6:
  // --benchmark_context=benchscope_workers_argument=0) decides, else the name's threads:N segment (1 when absent).
  // Recorded as the "workers from" setting of the set's provenance (analysis/foreign_sweeps.h reads it).
  std::optional<int> workers_argument;
};

}  // namespace bs
