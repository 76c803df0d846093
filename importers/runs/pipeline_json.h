// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// BenchScope pipeline JSON v1 (docs/pipeline-json-v1.md): one vision pipeline run of one platform, per-stage
// timing statistics in seconds. What `benchscope-cli pipeline --json` writes and what sample_data/paper-2018 uses
// for the paper's reported stage timings.
#include <string>
#include <string_view>

#include "common/format_importer.h"

namespace bs {

inline constexpr std::string_view kPipelineJsonFormat = "benchscope-pipeline-v1";

extern const FileFormat kPipelineJsonFileFormat;

// Parses pipeline JSON text; `file` names the source in errors. Throws ImportError naming file, line:column and
// the JSON pointer of the bad field. No options.
ImportBatch parse_pipeline_json(const std::string& text, const std::string& file, const ParseOptions& options = {},
                                const ImportLimits& limits = {}, const CancelToken& cancel = CancelToken{});

// Serialises one run (keys in a fixed order, doubles that read back bit-identical). Throws std::invalid_argument
// when the run breaks a rule the reader enforces (no stages, n = 0, a negative or non-finite time, ...).
std::string write_pipeline_json(const PipelineRun& run);

// Whether `stage` is one of the format's stage names (pipeline_stage::kPreprocess, kDetect, kEndToEnd).
bool is_pipeline_stage(std::string_view stage);

}  // namespace bs
