// SPDX-License-Identifier: GPL-3.0-or-later
// The run JSON writer (write_run_json, save_run_json; declared in run_json.h). Apart from the reader so that the
// reader's file holds only what an import runs (what the fuzz coverage of the run-json importer measures).
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#if __has_include(<unistd.h>)
#include <unistd.h>
#define BENCHSCOPE_HAVE_FSYNC 1
#endif

#include <nlohmann/json.hpp>

#include "analysis/peaks/flops.h"
#include "model/provenance_json.h"
#include "runs/run_json.h"
#include "runs/run_json_limits.h"

namespace bs {
namespace {

using namespace run_json_limits;

using ojson = nlohmann::ordered_json;

[[noreturn]] void refuse(std::size_t run, const std::string& field, const std::string& why) {
  throw std::invalid_argument("run JSON writer: /runs/" + std::to_string(run) + field + ": " + why);
}

void check_writable(const FlopsRun& run, std::size_t i) {
  if (run.platform.empty()) refuse(i, "/platform", "must not be empty");
  if (run.device.empty()) refuse(i, "/device", "must not be empty");
  if (run.backend.empty()) refuse(i, "/backend", "must not be empty");
  if (run.iterations < 1 || run.iterations > kMaxIterations) refuse(i, "/params/iterations", "out of range");
  if (run.dims < 1 || run.dims > kMaxDims) refuse(i, "/params/dims", "must be 1 to 64");
  for (const auto& [key, peak] : {std::pair{"/reported_peak_flops", run.reported_peak_flops},
                                  std::pair{"/theoretical_peak_flops", run.theoretical_peak_flops}})
    if (peak && !(std::isfinite(*peak) && *peak > 0)) refuse(i, key, "must be a finite number > 0");
  if (run.samples.empty()) refuse(i, "/samples", "a run needs at least one sample");
  for (std::size_t k = 0; k < run.samples.size(); ++k) {
    const WorkerSample& s = run.samples[k];
    const std::string at = "/samples/" + std::to_string(k);
    if (s.workers < 1 || s.workers > kMaxWorkers) refuse(i, at + "/workers", "out of range");
    if (k > 0 && s.workers <= run.samples[k - 1].workers) refuse(i, at + "/workers", "not strictly ascending");
    if (s.seconds.empty()) refuse(i, at + "/seconds", "needs at least one timing");
    for (double t : s.seconds)
      if (!(std::isfinite(t) && t > 0)) refuse(i, at + "/seconds", "times must be finite and > 0 s");
  }
}

ojson provenance_object(const Provenance& p) {
  ojson out = ojson::object();
  // The one shared mapping (core/model/provenance_json.h) decides the keys; iteration order is alphabetical.
  const nlohmann::json shared = provenance_to_json(p, false);
  for (const auto& [key, value] : shared.items()) out[key] = value.get<std::string>();
  return out;
}

bool same_provenance(const Provenance& a, const Provenance& b) {
  return provenance_to_json(a, false) == provenance_to_json(b, false);
}

ojson run_object(const FlopsRun& run, const Provenance* file_default) {
  ojson samples = ojson::array();
  const auto curve = flops_curve(run);
  for (std::size_t i = 0; i < run.samples.size(); ++i) {
    ojson s = ojson::object();
    s["workers"] = run.samples[i].workers;
    s["seconds"] = run.samples[i].seconds;
    s["flops_mean"] = curve[i].flops.mean;
    samples.push_back(std::move(s));
  }
  ojson j = ojson::object();
  j["platform"] = run.platform;
  j["device"] = run.device;
  j["device_kind"] = std::string(to_string(run.device_kind));
  j["backend"] = run.backend;
  j["kernel"] = run.kernel;
  j["variant"] = run.variant;
  j["params"] = ojson::object();
  j["params"]["iterations"] = run.iterations;
  j["params"]["dims"] = run.dims;
  if (run.reported_peak_flops) j["reported_peak_flops"] = *run.reported_peak_flops;
  if (run.theoretical_peak_flops) j["theoretical_peak_flops"] = *run.theoretical_peak_flops;
  j["samples"] = std::move(samples);
  if (!file_default || !same_provenance(run.provenance, *file_default))
    j["provenance"] = provenance_object(run.provenance);
  return j;
}

std::string temp_name_beside(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  const auto ticks = std::chrono::steady_clock::now().time_since_epoch().count();
  return path + ".tmp-" + std::to_string(ticks) + "-" + std::to_string(counter.fetch_add(1));
}

}  // namespace

std::string write_run_json(std::span<const FlopsRun> runs, const Provenance* file_default) {
  ojson out_runs = ojson::array();
  for (std::size_t i = 0; i < runs.size(); ++i) {
    check_writable(runs[i], i);
    out_runs.push_back(run_object(runs[i], file_default));
  }
  ojson doc = ojson::object();
  doc["format"] = "benchscope-run";
  doc["version"] = kRunJsonVersion;
  doc["generator"] = std::string("benchscope ") + BENCHSCOPE_VERSION;
  if (file_default) doc["provenance"] = provenance_object(*file_default);
  doc["runs"] = std::move(out_runs);
  // nlohmann prints doubles in the shortest form that parses back to the same bits. Strict UTF-8: a name with
  // invalid bytes is refused rather than silently altered.
  try {
    return doc.dump(2, ' ', false, ojson::error_handler_t::strict) + "\n";
  } catch (const ojson::type_error& e) {
    throw std::invalid_argument(std::string("run JSON writer: a text field is not valid UTF-8 (") + e.what() + ")");
  }
}

void save_run_json(const std::string& path, std::span<const FlopsRun> runs, const Provenance* file_default) {
  const std::string text = write_run_json(runs, file_default);
  const std::string tmp = temp_name_beside(path);
  auto fail = [&](const std::string& why) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw std::runtime_error(path + ": " + why);
  };
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) fail(std::string("cannot write a temporary file beside it (") + std::strerror(errno) + ")");
  const bool written = std::fwrite(text.data(), 1, text.size(), f) == text.size() && std::fflush(f) == 0;
  const int write_errno = errno;
#ifdef BENCHSCOPE_HAVE_FSYNC
  // On disk before the rename, so a crash leaves either the old file or the complete new one.
  const bool synced = written && ::fsync(::fileno(f)) == 0;
#else
  const bool synced = written;
#endif
  const bool closed = std::fclose(f) == 0;
  if (!written || !synced || !closed) fail(std::string("write failed (") + std::strerror(write_errno) + ")");
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) fail("cannot replace the file (" + ec.message() + ")");
}

}  // namespace bs
