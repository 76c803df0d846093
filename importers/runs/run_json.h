// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// BenchScope run JSON v1: the project's own format for FLOPS sweeps (docs/run-json-v1.md,
// resources/schema/benchscope-run-v1.schema.json). What `benchscope-cli run` writes and every view imports.
#include <span>
#include <string>

#include "common/format_importer.h"

namespace bs {

inline constexpr int kRunJsonVersion = 1;

extern const FileFormat kRunJsonFileFormat;

// Parses run JSON text; `file` names the source in errors. Throws ImportError (or Cancelled). No options.
ImportBatch parse_run_json(const std::string& text, const std::string& file, const ParseOptions& options = {},
                           const ImportLimits& limits = {}, const CancelToken& cancel = CancelToken{});

// Serialises runs as run JSON v1: pretty, keys in a fixed order, doubles in the shortest form that reads back
// bit-identical, "flops_mean" per sample for human readers. With `file_default`, it is written as the file-level
// provenance and runs whose provenance equals it leave theirs out (they inherit it on reading).
// Throws std::invalid_argument naming the run and field when a run breaks a rule the reader enforces (no samples,
// non-ascending workers, a time <= 0 or not finite, ...), so the writer never produces a run it would refuse.
// An empty span gives a document with an empty "runs" array, which the reader refuses (a file needs a run).
std::string write_run_json(std::span<const FlopsRun> runs, const Provenance* file_default = nullptr);
// Writes atomically: a uniquely named temporary file beside `path`, flushed to disk, then renamed over `path`.
// Throws std::runtime_error naming the path (and leaves no temporary file behind).
void save_run_json(const std::string& path, std::span<const FlopsRun> runs, const Provenance* file_default = nullptr);

}  // namespace bs
