// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Google Benchmark's JSON output (--benchmark_format=json or --benchmark_out): a "context" object describing the
// machine and a "benchmarks" array of iteration rows (one per repetition) and aggregate rows (mean, median, stddev,
// cv). Imported as one ResultSet: per run_name, real_time and cpu_time in seconds and every user counter
// (bytes_per_second in B/s, items_per_second in 1/s, FLOP counters in FLOP/s), one value per repetition, with the
// aggregate rows kept as reported_aggregates. Rows with error_occurred or skipped become warnings.
#include <string>

#include "importer.h"

namespace bs {

class GoogleBenchmarkJsonImporter final : public Importer {
 public:
  std::string_view id() const override { return "google-benchmark-json"; }
  std::string_view description() const override { return "Google Benchmark JSON"; }
  int sniff(std::string_view head, std::string_view path) const override;
  bool usual_extension(std::string_view path) const override;
  ImportBatch parse(const std::string& path, const ImportLimits& limits, const CancelToken& cancel) const override;
};

// Also reads the bare NaN / Infinity that Google Benchmark prints for non-finite values (not JSON): such a time
// drops its row and such a counter is left out, each with a warning.
ImportBatch parse_google_benchmark_json(std::string_view text, const std::string& file,
                                        const ImportLimits& limits = {}, const CancelToken* cancel = nullptr);

}  // namespace bs
