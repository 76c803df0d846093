// SPDX-License-Identifier: GPL-3.0-or-later
#include "runs/run_json.h"

#include <cmath>
#include <stdexcept>

#include "analysis/peaks/flops.h"
#include "common/json_access.h"
#include "common/text_file.h"
#include "model/provenance_json.h"
#include "runs/run_json_limits.h"

namespace bs {
namespace {

using json_access::child;
using json_access::json;
using json_access::Reader;
using namespace run_json_limits;

Provenance read_provenance(const Reader& r, const json& value, const std::string& at, Provenance p) {
  r.require_object(value, at);
  const std::string origin = r.optional_string(value, at, "origin", std::string(to_string(p.origin)));
  if (origin != "measured" && origin != "reconstructed" && origin != "published" && origin != "unknown")
    r.fail(ImportErrorCategory::InvalidValue, child(at, "origin"),
           "'" + origin + "' is not one of measured, reconstructed, published, unknown");
  p.origin = data_origin_from_string(origin);
  p.host = r.optional_string(value, at, "host", p.host);
  p.cpu_model = r.optional_string(value, at, "cpu_model", p.cpu_model);
  p.gpu_model = r.optional_string(value, at, "gpu_model", p.gpu_model);
  p.os = r.optional_string(value, at, "os", p.os);
  p.compiler = r.optional_string(value, at, "compiler", p.compiler);
  p.tool = r.optional_string(value, at, "tool", p.tool);
  p.git_revision = r.optional_string(value, at, "git_revision", p.git_revision);
  p.date = r.optional_string(value, at, "date", p.date);
  p.note = r.optional_string(value, at, "note", p.note);
  return p;
}

std::optional<double> positive_optional(const Reader& r, const json& run, const std::string& at, const char* key) {
  auto v = r.optional_number(run, at, key);
  if (v && *v <= 0) r.fail(ImportErrorCategory::InvalidValue, child(at, key), "must be greater than 0 FLOP/s");
  return v;
}

struct ReadState {
  const Reader& r;
  const ImportLimits& limits;
  const CancelToken* cancel;
  const Provenance& file_provenance;
  ImportBatch& batch;
  std::size_t total_values = 0;
};

WorkerSample read_sample(ReadState& st, const FlopsRun& run, const json& s, const std::string& s_at) {
  const Reader& r = st.r;
  r.require_object(s, s_at);
  WorkerSample ws;
  ws.workers = r.require_integer(s, s_at, "workers", 1, kMaxWorkers);
  if (!run.samples.empty() && ws.workers <= run.samples.back().workers)
    r.fail(ImportErrorCategory::InvalidValue, child(s_at, "workers"),
           "workers must be strictly ascending (" + std::to_string(ws.workers) + " after " +
               std::to_string(run.samples.back().workers) + ")");
  const std::string sec_at = child(s_at, "seconds");
  const json& secs = r.require_array(r.require(s, s_at, "seconds"), sec_at);
  if (secs.empty()) r.fail(ImportErrorCategory::InvalidValue, sec_at, "needs at least one timing");
  st.total_values += secs.size();
  if (st.total_values > st.limits.max_samples)
    r.fail(ImportErrorCategory::TooLarge, sec_at,
           "more than " + std::to_string(st.limits.max_samples) + " timings in one file (the documented limit)");
  ws.seconds.reserve(secs.size());  // bounded: the array is already parsed, under the size and value limits
  for (std::size_t k = 0; k < secs.size(); ++k) {
    const double t = r.number(secs[k], child(sec_at, k));
    if (t <= 0) r.fail(ImportErrorCategory::InvalidValue, child(sec_at, k), "a time must be greater than 0 s");
    ws.seconds.push_back(t);
  }
  if (const json* fm = r.optional(s, "flops_mean")) {
    const std::string fm_at = child(s_at, "flops_mean");
    const double stated = r.number(*fm, fm_at);
    RunningStats stats;
    for (double t : ws.seconds) stats.add(rotation_flops(run.dims, run.iterations, ws.workers, t));
    if (std::abs(stated - stats.mean()) > 1e-6 * std::abs(stats.mean())) {
      char text[160];
      std::snprintf(text, sizeof text, "stated %.9g FLOP/s differs from 6*D*N*W/t = %.9g FLOP/s; using the timings",
                    stated, stats.mean());
      st.batch.warnings.push_back(r.where(fm_at) + ": " + text);
    }
  }
  return ws;
}

FlopsRun read_run(ReadState& st, const json& run, const std::string& at) {
  const Reader& r = st.r;
  r.require_object(run, at);
  FlopsRun out;
  out.platform = r.require_string(run, at, "platform");
  out.device = r.require_string(run, at, "device");
  out.backend = r.require_string(run, at, "backend");
  for (const char* key : {"platform", "device", "backend"})
    if (r.require_string(run, at, key).empty())
      r.fail(ImportErrorCategory::InvalidValue, child(at, key), "must not be empty");
  const std::string kind = r.optional_string(run, at, "device_kind", "other");
  if (kind != "cpu" && kind != "gpu" && kind != "other")
    r.fail(ImportErrorCategory::InvalidValue, child(at, "device_kind"), "'" + kind + "' is not one of cpu, gpu, other");
  out.device_kind = device_kind_from_string(kind);
  out.kernel = r.optional_string(run, at, "kernel", "rotation2d");
  out.variant = r.optional_string(run, at, "variant", "paper");

  const std::string params_at = child(at, "params");
  const json& params = r.require_object(r.require(run, at, "params"), params_at);
  out.iterations = r.require_integer(params, params_at, "iterations", 1, kMaxIterations);
  out.dims = static_cast<int>(r.require_integer(params, params_at, "dims", 1, kMaxDims));
  out.reported_peak_flops = positive_optional(r, run, at, "reported_peak_flops");
  out.theoretical_peak_flops = positive_optional(r, run, at, "theoretical_peak_flops");

  const std::string samples_at = child(at, "samples");
  const json& samples = r.require_array(r.require(run, at, "samples"), samples_at);
  if (samples.empty()) r.fail(ImportErrorCategory::InvalidValue, samples_at, "a run needs at least one sample");
  out.samples.reserve(samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (st.cancel && (i & 0x3FF) == 0) st.cancel->throw_if_cancelled();
    WorkerSample ws = read_sample(st, out, samples[i], child(samples_at, i));
    out.samples.push_back(std::move(ws));
  }
  const json* prov = r.optional(run, "provenance");
  out.provenance = prov ? read_provenance(r, *prov, child(at, "provenance"), st.file_provenance) : st.file_provenance;
  out.provenance.source_file = r.file();
  return out;
}

}  // namespace

static int sniff_run_json(std::string_view head, std::string_view) {
  if (head.find("\"benchscope-run\"") != std::string_view::npos) return 100;
  // A run file whose "format" key sits after 64 KiB of other content is unlikely but still recognisable.
  if (head.find("\"samples\"") != std::string_view::npos && head.find("\"runs\"") != std::string_view::npos &&
      head.find("\"seconds\"") != std::string_view::npos)
    return 40;
  return 0;
}

ImportBatch parse_run_json(const std::string& text, const std::string& file, const ParseOptions& /*options*/,
                           const ImportLimits& limits, const CancelToken& cancel) {
  const json doc = json_access::parse(text, file, limits, &cancel);
  const Reader r(file, text);
  r.require_object(doc, "");
  const std::string format = r.require_string(doc, "", "format");
  if (format != "benchscope-run")
    r.fail(ImportErrorCategory::InvalidValue, "/format", "'" + format + "' is not \"benchscope-run\"");
  const std::int64_t version = r.require_integer(doc, "", "version", 1, std::int64_t{1} << 53);
  if (version > kRunJsonVersion)
    r.fail(ImportErrorCategory::Unsupported, "/version",
           "version " + std::to_string(version) + " was written by a newer BenchScope; this build reads up to " +
               std::to_string(kRunJsonVersion));
  r.optional_string(doc, "", "generator");  // type-checked only

  Provenance file_provenance;
  if (const json* p = r.optional(doc, "provenance")) file_provenance = read_provenance(r, *p, "/provenance", {});

  ImportBatch batch;
  batch.source_path = file;
  batch.format = "benchscope-run-v1";
  const json& runs = r.require_array(r.require(doc, "", "runs"), "/runs");
  if (runs.empty()) r.fail(ImportErrorCategory::InvalidValue, "/runs", "the file holds no runs");
  ReadState st{r, limits, &cancel, file_provenance, batch};
  batch.runs.reserve(runs.size());
  for (std::size_t i = 0; i < runs.size(); ++i) batch.runs.push_back(read_run(st, runs[i], child("/runs", i)));
  return batch;
}

const FileFormat kRunJsonFileFormat{"benchscope-run-v1", "BenchScope run JSON v1",
                                    sniff_run_json,      parse_text_file_with<parse_run_json>,
                                    parse_run_json,      ".json"};

}  // namespace bs
