// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Google Benchmark's JSON output (--benchmark_format=json or --benchmark_out): a "context" object describing the
// machine and a "benchmarks" array of iteration rows (one per repetition) and aggregate rows (mean, median, stddev,
// cv). Imported as one ResultSet: per run_name, real_time and cpu_time in seconds and every user counter
// (bytes_per_second in B/s, items_per_second in 1/s, FLOP counters in FLOP/s), one value per repetition, with the
// aggregate rows kept as reported_aggregates. Rows with error_occurred or skipped become warnings.
#include <string>

#include "common/format_importer.h"

namespace bs {

extern const FileFormat kGoogleBenchmarkJsonFileFormat;

// Also reads the bare NaN / Infinity that Google Benchmark prints for non-finite values (not JSON): such a time
// drops its row and such a counter is left out (missing data, never 0), each with a warning. Refused with the
// file:line and field: duplicate keys with different values, iterations that are not an integer >= 0 (negative,
// fractional, Infinity, beyond int64), threads that is not an integer >= 1 or disagrees with the name's threads:N,
// one benchmark with two different `threads`, and the same repetition (or aggregate) of a benchmark twice with
// different data; an identical repeated row is skipped with a warning. A context whose library_build_type is
// "debug" gives Google Benchmark's own warning. Context fields (host_name, num_cpus, mhz_per_cpu, caches,
// library_version, library_build_type, custom context keys) become provenance settings. items_per_second is in
// FLOP/s when the context says benchscope_item = "flop", else in 1/s. Reads ParseOptions::workers_argument (what
// the file may not say: which argument of the benchmark name is the worker count of a FLOPS sweep).
ImportBatch parse_google_benchmark_json(const std::string& text, const std::string& file,
                                        const ParseOptions& options = {}, const ImportLimits& limits = {},
                                        const CancelToken& cancel = CancelToken{});

}  // namespace bs
