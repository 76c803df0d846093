// SPDX-License-Identifier: GPL-3.0-or-later
#include "runs/pipeline_json.h"

#include <cmath>
#include <stdexcept>

#include "common/json_access.h"
#include "common/text_file.h"
#include "model/provenance_json.h"

namespace bs {
namespace {

using json_access::child;
using json_access::json;
using json_access::Reader;

// Format limits (docs/pipeline-json-v1.md).
constexpr std::int64_t kMaxFrames = std::int64_t{1} << 40;
constexpr std::int64_t kMaxSide = 1 << 16;
constexpr const char* kStages[] = {pipeline_stage::kPreprocess, pipeline_stage::kDetect, pipeline_stage::kEndToEnd};

Provenance read_provenance(const Reader& r, const json& value, const std::string& at) {
  r.require_object(value, at);
  Provenance p;
  const std::string origin = r.optional_string(value, at, "origin", "unknown");
  if (origin != "measured" && origin != "reconstructed" && origin != "published" && origin != "unknown")
    r.fail(ImportErrorCategory::InvalidValue, child(at, "origin"),
           "'" + origin + "' is not one of measured, reconstructed, published, unknown");
  p.origin = data_origin_from_string(origin);
  p.host = r.optional_string(value, at, "host");
  p.cpu_model = r.optional_string(value, at, "cpu_model");
  p.gpu_model = r.optional_string(value, at, "gpu_model");
  p.os = r.optional_string(value, at, "os");
  p.compiler = r.optional_string(value, at, "compiler");
  p.tool = r.optional_string(value, at, "tool");
  p.git_revision = r.optional_string(value, at, "git_revision");
  p.date = r.optional_string(value, at, "date");
  p.note = r.optional_string(value, at, "note");
  return p;
}

double seconds(const Reader& r, const json& stage, const std::string& at, const char* key) {
  const double v = r.require_number(stage, at, key);
  if (v < 0) r.fail(ImportErrorCategory::InvalidValue, child(at, key), "a time cannot be negative");
  return v;
}

std::optional<double> optional_seconds(const Reader& r, const json& stage, const std::string& at, const char* key) {
  const auto v = r.optional_number(stage, at, key);
  if (v && *v < 0) r.fail(ImportErrorCategory::InvalidValue, child(at, key), "a time cannot be negative");
  return v;
}

StageStats read_stage(const Reader& r, const json& value, const std::string& at, const std::string& name) {
  r.require_object(value, at);
  StageStats s;
  s.stage = name;
  s.n = static_cast<std::size_t>(r.require_integer(value, at, "n", 1, kMaxFrames));
  s.mean_s = seconds(r, value, at, "mean_s");
  s.sd_s = seconds(r, value, at, "sd_s");
  s.min_s = optional_seconds(r, value, at, "min_s");
  s.max_s = optional_seconds(r, value, at, "max_s");
  s.p50_s = optional_seconds(r, value, at, "p50_s");
  s.p95_s = optional_seconds(r, value, at, "p95_s");
  // Statistics that contradict each other mean a broken writer or a hand-edited file: refuse rather than show them.
  // (A relative slack of 1e-9 lets values that were rounded when written pass.)
  const auto le = [](double a, double b) { return a <= b + 1e-9 * std::max(std::abs(a), std::abs(b)); };
  if (s.min_s && !le(*s.min_s, s.mean_s))
    r.fail(ImportErrorCategory::InvalidValue, child(at, "min_s"), "is greater than mean_s");
  if (s.max_s && !le(s.mean_s, *s.max_s))
    r.fail(ImportErrorCategory::InvalidValue, child(at, "max_s"), "is less than mean_s");
  if (s.p50_s && s.p95_s && !le(*s.p50_s, *s.p95_s))
    r.fail(ImportErrorCategory::InvalidValue, child(at, "p95_s"), "is less than p50_s");
  if (s.n == 1 && s.sd_s != 0) r.fail(ImportErrorCategory::InvalidValue, child(at, "sd_s"), "must be 0 when n is 1");
  return s;
}

}  // namespace

bool is_pipeline_stage(std::string_view s) {
  for (const char* k : kStages)
    if (s == k) return true;
  return false;
}

static int sniff_pipeline_json(std::string_view head, std::string_view) {
  // Any version: a newer one is then refused as unsupported rather than as an unknown format.
  if (head.find("\"benchscope-pipeline-v") != std::string_view::npos) return 100;
  if (head.find("\"stages\"") != std::string_view::npos && head.find("\"mean_s\"") != std::string_view::npos) return 40;
  return 0;
}

ImportBatch parse_pipeline_json(const std::string& text, const std::string& file, const ParseOptions& /*options*/,
                                const ImportLimits& limits, const CancelToken& cancel) {
  const json doc = json_access::parse(text, file, limits, &cancel);
  const Reader r(file, text);
  r.require_object(doc, "");
  const std::string format = r.require_string(doc, "", "format");
  if (format != kPipelineJsonFormat) {
    if (format.starts_with("benchscope-pipeline-v"))
      r.fail(ImportErrorCategory::Unsupported, "/format",
             "'" + format + "' was written by a newer BenchScope; this build reads benchscope-pipeline-v1");
    r.fail(ImportErrorCategory::InvalidValue, "/format", "'" + format + "' is not \"benchscope-pipeline-v1\"");
  }
  PipelineRun run;
  run.platform = r.require_string(doc, "", "platform");
  if (run.platform.empty()) r.fail(ImportErrorCategory::InvalidValue, "/platform", "must not be empty");
  run.device = r.optional_string(doc, "", "device", run.platform);
  run.backend = r.optional_string(doc, "", "backend", "cpu");
  if (run.backend != "cpu" && run.backend != "opencl" && run.backend != "cuda")
    r.fail(ImportErrorCategory::InvalidValue, "/backend", "'" + run.backend + "' is not one of cpu, opencl, cuda");
  run.demosaic = r.optional_string(doc, "", "demosaic");
  run.detector = r.optional_string(doc, "", "detector");
  if (const json* frame = r.optional(doc, "frame")) {
    r.require_object(*frame, "/frame");
    run.frame_width = static_cast<int>(r.require_integer(*frame, "/frame", "width", 1, kMaxSide));
    run.frame_height = static_cast<int>(r.require_integer(*frame, "/frame", "height", 1, kMaxSide));
  }
  if (const auto fps = r.optional_number(doc, "", "throughput_fps")) {
    if (*fps <= 0) r.fail(ImportErrorCategory::InvalidValue, "/throughput_fps", "must be greater than 0 fps");
    run.throughput_fps = fps;
  }
  const json& stages = r.require_object(r.require(doc, "", "stages"), "/stages");
  if (stages.empty()) r.fail(ImportErrorCategory::MissingField, "/stages", "needs at least one stage");
  // In pipeline order whatever the key order in the file.
  for (const char* name : kStages)
    if (const auto it = stages.find(name); it != stages.end())
      run.stages.push_back(read_stage(r, *it, child("/stages", name), name));
  for (const auto& [key, value] : stages.items())
    if (!is_pipeline_stage(key))
      r.fail(ImportErrorCategory::InvalidValue, child("/stages", key),
             "unknown stage '" + key + "' (expected preprocess, detect, end-to-end)");
  if (const json* p = r.optional(doc, "provenance")) run.provenance = read_provenance(r, *p, "/provenance");
  run.provenance.source_file = file;

  ImportBatch batch;
  batch.source_path = file;
  batch.format = std::string(kPipelineJsonFormat);
  batch.pipeline_runs.push_back(std::move(run));
  return batch;
}

const FileFormat kPipelineJsonFileFormat{kPipelineJsonFormat, "BenchScope pipeline timing JSON v1",
                                         sniff_pipeline_json, parse_text_file_with<parse_pipeline_json>,
                                         parse_pipeline_json, ".json"};

}  // namespace bs
