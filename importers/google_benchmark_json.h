// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Google Benchmark's JSON output (--benchmark_format=json or --benchmark_out): a "context" object describing the
// machine and a "benchmarks" array of iteration rows (one per repetition) and aggregate rows (mean, median, stddev,
// cv). Imported as one ResultSet of throughput measurements in SI units.
#include <string>

#include "importer.h"

namespace bs {

class GoogleBenchmarkJsonImporter final : public Importer {
 public:
  std::string_view id() const override { return "google-benchmark-json"; }
  std::string_view description() const override { return "Google Benchmark JSON"; }
  int sniff(std::string_view head, std::string_view path) const override;
  ImportBatch parse(const std::string& path, const ImportLimits& limits, const CancelToken& cancel) const override;
};

ImportBatch parse_google_benchmark_json(std::string_view text, const std::string& file,
                                        const ImportLimits& limits = {});

}  // namespace bs
