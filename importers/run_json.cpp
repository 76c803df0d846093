// SPDX-License-Identifier: GPL-3.0-or-later
#include "run_json.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "analysis/flops.h"
#include "json_access.h"
#include "model/provenance_json.h"

namespace bs {
namespace {

using json_access::child;
using json_access::json;
using json_access::Reader;

Provenance read_provenance(const Reader& r, const json& value, const std::string& at, Provenance p) {
  r.require_object(value, at);
  const std::string origin = r.optional_string(value, at, "origin", std::string(to_string(p.origin)));
  if (origin != "measured" && origin != "reconstructed" && origin != "unknown")
    r.fail(ImportErrorCategory::InvalidValue, child(at, "origin"),
           "'" + origin + "' is not one of measured, reconstructed, unknown");
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
  if (v && *v <= 0) r.fail(ImportErrorCategory::InvalidValue, child(at, key), "must be greater than 0");
  return v;
}

FlopsRun read_run(const Reader& r, const json& run, const std::string& at, const Provenance& file_provenance,
                  std::size_t& total_values, const ImportLimits& limits, ImportBatch& batch) {
  r.require_object(run, at);
  FlopsRun out;
  out.platform = r.require_string(run, at, "platform");
  out.device = r.require_string(run, at, "device");
  const std::string kind = r.optional_string(run, at, "device_kind", "other");
  if (kind != "cpu" && kind != "gpu" && kind != "other")
    r.fail(ImportErrorCategory::InvalidValue, child(at, "device_kind"), "'" + kind + "' is not one of cpu, gpu, other");
  out.device_kind = device_kind_from_string(kind);
  out.backend = r.require_string(run, at, "backend");
  out.kernel = r.optional_string(run, at, "kernel", "rotation2d");
  out.variant = r.optional_string(run, at, "variant", "paper");
  if (out.platform.empty() || out.device.empty() || out.backend.empty())
    r.fail(ImportErrorCategory::InvalidValue, at, "platform, device and backend must not be empty");

  const std::string params_at = child(at, "params");
  const json& params = r.require_object(r.require(run, at, "params"), params_at);
  out.iterations = r.require_integer(params, params_at, "iterations", 1, std::int64_t{1} << 40);
  out.dims = static_cast<int>(r.require_integer(params, params_at, "dims", 1, 64));
  out.reported_peak_flops = positive_optional(r, run, at, "reported_peak_flops");
  out.theoretical_peak_flops = positive_optional(r, run, at, "theoretical_peak_flops");

  const std::string samples_at = child(at, "samples");
  const json& samples = r.require_array(r.require(run, at, "samples"), samples_at);
  if (samples.empty()) r.fail(ImportErrorCategory::InvalidValue, samples_at, "a run needs at least one sample");
  out.samples.reserve(samples.size());  // bounded: the array already exists in memory, parsed under the size limit
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const std::string s_at = child(samples_at, i);
    const json& s = r.require_object(samples[i], s_at);
    WorkerSample ws;
    ws.workers = r.require_integer(s, s_at, "workers", 1, std::int64_t{1} << 40);
    if (!out.samples.empty() && ws.workers <= out.samples.back().workers)
      r.fail(ImportErrorCategory::InvalidValue, child(s_at, "workers"),
             "workers must be strictly ascending (" + std::to_string(ws.workers) + " after " +
                 std::to_string(out.samples.back().workers) + ")");
    const std::string sec_at = child(s_at, "seconds");
    const json& secs = r.require_array(r.require(s, s_at, "seconds"), sec_at);
    if (secs.empty()) r.fail(ImportErrorCategory::InvalidValue, sec_at, "needs at least one timing");
    total_values += secs.size();
    if (total_values > limits.max_samples)
      r.fail(ImportErrorCategory::TooLarge, sec_at,
             "more than " + std::to_string(limits.max_samples) + " timings in one file");
    for (std::size_t k = 0; k < secs.size(); ++k) {
      const double t = r.number(secs[k], child(sec_at, k));
      if (t <= 0) r.fail(ImportErrorCategory::InvalidValue, child(sec_at, k), "a time must be greater than 0 s");
      ws.seconds.push_back(t);
    }
    if (const json* fm = r.optional(s, "flops_mean")) {
      const double stated = r.number(*fm, child(s_at, "flops_mean"));
      RunningStats st;
      for (double t : ws.seconds) st.add(rotation_flops(out.dims, out.iterations, ws.workers, t));
      if (std::abs(stated - st.mean()) > 1e-6 * std::abs(st.mean()))
        batch.warnings.push_back(r.file() + ": " + child(s_at, "flops_mean") + ": stated " + std::to_string(stated) +
                                 " differs from 6*D*N*W/t = " + std::to_string(st.mean()) + "; using the timings");
    }
    out.samples.push_back(std::move(ws));
  }
  const json* prov = r.optional(run, "provenance");
  out.provenance = prov ? read_provenance(r, *prov, child(at, "provenance"), file_provenance) : file_provenance;
  out.provenance.source_file = r.file();
  return out;
}

}  // namespace

int RunJsonImporter::sniff(std::string_view head, std::string_view path) const {
  const bool has_format = head.find("\"benchscope-run\"") != std::string_view::npos;
  if (has_format) return 100;
  if (head.find("\"samples\"") != std::string_view::npos && head.find("\"runs\"") != std::string_view::npos)
    return 40;
  return path.ends_with(".bsrun.json") ? 10 : 0;
}

ImportBatch RunJsonImporter::parse(const std::string& path, const ImportLimits& limits,
                                   const CancelToken& cancel) const {
  const std::string text = read_whole_file(path, limits.max_json_bytes);
  cancel.throw_if_cancelled();
  return parse_run_json(text, path, limits);
}

ImportBatch parse_run_json(std::string_view text, const std::string& file, const ImportLimits& limits) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  const json doc = json_access::parse(text, file, limits.max_json_depth);
  const Reader r(file);
  r.require_object(doc, "");
  const std::string format = r.require_string(doc, "", "format");
  if (format != "benchscope-run")
    r.fail(ImportErrorCategory::InvalidValue, "/format", "'" + format + "' is not \"benchscope-run\"");
  const std::int64_t version = r.require_integer(doc, "", "version", 1, 1'000'000);
  if (version > kRunJsonVersion)
    r.fail(ImportErrorCategory::Unsupported, "/version",
           "version " + std::to_string(version) + " was written by a newer BenchScope; this build reads up to " +
               std::to_string(kRunJsonVersion));

  Provenance file_provenance;
  if (const json* p = r.optional(doc, "provenance")) file_provenance = read_provenance(r, *p, "/provenance", {});

  ImportBatch batch;
  batch.source_path = file;
  batch.format = "benchscope-run-v1";
  const json& runs = r.require_array(r.require(doc, "", "runs"), "/runs");
  if (runs.empty()) r.fail(ImportErrorCategory::InvalidValue, "/runs", "the file holds no runs");
  std::size_t total_values = 0;
  for (std::size_t i = 0; i < runs.size(); ++i)
    batch.runs.push_back(read_run(r, runs[i], child(std::string("/runs"), i), file_provenance, total_values,
                                  limits, batch));
  return batch;
}

std::string write_run_json(std::span<const FlopsRun> runs) {
  json out_runs = json::array();
  for (const FlopsRun& run : runs) {
    json samples = json::array();
    const auto curve = flops_curve(run);
    for (std::size_t i = 0; i < run.samples.size(); ++i)
      samples.push_back({{"workers", run.samples[i].workers},
                         {"seconds", run.samples[i].seconds},
                         {"flops_mean", curve[i].flops.mean}});
    json j = {{"platform", run.platform},
              {"device", run.device},
              {"device_kind", std::string(to_string(run.device_kind))},
              {"backend", run.backend},
              {"kernel", run.kernel},
              {"variant", run.variant},
              {"params", {{"iterations", run.iterations}, {"dims", run.dims}}}};
    if (run.reported_peak_flops) j["reported_peak_flops"] = *run.reported_peak_flops;
    if (run.theoretical_peak_flops) j["theoretical_peak_flops"] = *run.theoretical_peak_flops;
    j["samples"] = std::move(samples);
    j["provenance"] = provenance_to_json(run.provenance, false);
    out_runs.push_back(std::move(j));
  }
  // nlohmann prints doubles with max_digits10, so they read back bit-exact.
  const json doc = {{"format", "benchscope-run"},
                    {"version", kRunJsonVersion},
                    {"generator", std::string("benchscope ") + BENCHSCOPE_VERSION},
                    {"runs", std::move(out_runs)}};
  return doc.dump(1) + "\n";
}

void save_run_json(const std::string& path, std::span<const FlopsRun> runs) {
  const std::string text = write_run_json(runs);
  const std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f) throw std::runtime_error(path + ": cannot write (" + std::strerror(errno) + ")");
    f << text;
    f.flush();
    if (!f) throw std::runtime_error(path + ": write failed");
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw std::runtime_error(path + ": cannot replace file (" + ec.message() + ")");
  }
}

}  // namespace bs
