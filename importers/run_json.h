// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// BenchScope run JSON v1: the project's own format for FLOPS sweeps (docs/run-json-v1.md,
// resources/schema/benchscope-run-v1.schema.json). What `benchscope-cli run` writes and every view imports.
#include <span>
#include <string>

#include "importer.h"

namespace bs {

inline constexpr int kRunJsonVersion = 1;

class RunJsonImporter final : public Importer {
 public:
  std::string_view id() const override { return "benchscope-run-v1"; }
  std::string_view description() const override { return "BenchScope run JSON v1"; }
  int sniff(std::string_view head, std::string_view path) const override;
  ImportBatch parse(const std::string& path, const ImportLimits& limits, const CancelToken& cancel) const override;
};

// Parses run JSON text; `file` names the source in errors. Throws ImportError.
ImportBatch parse_run_json(std::string_view text, const std::string& file, const ImportLimits& limits = {});

// Serialises runs as run JSON v1 (stable key order, doubles round-trip exact, "flops_mean" per sample for readers).
std::string write_run_json(std::span<const FlopsRun> runs);
// Writes atomically: a temporary file beside `path`, then rename. Throws std::runtime_error naming the path.
void save_run_json(const std::string& path, std::span<const FlopsRun> runs);

}  // namespace bs
