// SPDX-License-Identifier: GPL-3.0-or-later
#include "mlperf/mlperf_submission.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "analysis/power/power_time.h"
#include "common/json_access.h"
#include "mlperf/loadgen_detail.h"
#include "power/ptd_log.h"

namespace bs {
namespace fs = std::filesystem;
namespace {

constexpr double kNs = 1e-9;

std::string fmt(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

void add(ResultSet& set, const std::string& name, const std::string& metric, const std::string& unit, double v) {
  Measurement m;
  m.name = name;
  m.metric = metric;
  m.unit = unit;
  m.values = {v};
  set.measurements.push_back(std::move(m));
}

// "90.00 percentile latency (ns)" -> "p90 latency"; "99.90 ..." -> "p99.9 latency".
std::string percentile_metric(const std::string& key) {
  const std::size_t sp = key.find(' ');
  std::string p = key.substr(0, sp);
  while (p.find('.') != std::string::npos && (p.back() == '0' || p.back() == '.')) {
    const bool dot = p.back() == '.';
    p.pop_back();
    if (dot) break;
  }
  return "p" + p + " latency";
}

// The system description: every non-empty scalar field becomes a setting, in the file's order of interest.
void read_system(const MlperfCompanions& w, const ImportLimits& limits, ResultSet& set) {
  if (w.system_json.empty()) return;
  const json_access::json j = json_access::parse(w.system_json, w.system_file, limits);
  const json_access::Reader r(w.system_file, w.system_json);
  r.require_object(j, "");
  const auto text = [&](const char* key) -> std::string {
    const auto it = j.find(key);
    if (it == j.end() || it->is_null()) return {};
    if (it->is_string()) return it->get<std::string>();
    if (it->is_number_integer()) return std::to_string(it->get<long long>());
    if (it->is_number()) return fmt(it->get<double>());
    if (it->is_boolean()) return it->get<bool>() ? "true" : "false";
    r.fail(ImportErrorCategory::WrongType, std::string("/") + key, "not a string or number");
  };
  if (const std::string name = text("system_name"); !name.empty()) set.platform = name;
  const std::string accel = text("accelerator_model_name");
  const std::string accels = text("accelerators_per_node");
  const bool has_accel = !accel.empty() && accel != "N/A" && accel != "-" && accels != "0";
  set.device = has_accel ? accel : text("host_processor_model_name");
  set.device_kind = has_accel ? DeviceKind::Gpu : DeviceKind::Cpu;
  if (const std::string fw = text("framework"); !fw.empty()) set.backend = fw;
  set.provenance.cpu_model = text("host_processor_model_name");
  set.provenance.gpu_model = has_accel ? accel : std::string();
  set.provenance.os = text("operating_system");
  for (const char* key :
       {"division", "submitter", "status", "system_type", "accelerator_model_name", "accelerators_per_node",
        "host_processor_model_name", "host_processor_core_count", "host_processor_frequency", "host_memory_capacity",
        "framework", "other_software_stack", "power_management", "cooling", "hw_notes", "sw_notes"})
    if (const std::string v = text(key); !v.empty()) set.provenance.settings.emplace_back(key, v);
}

// Weight and input data types from the measurements JSON: "int8", "fp16", ...
void read_precision(const MlperfCompanions& w, const ImportLimits& limits, ResultSet& set) {
  if (w.measurements_json.empty()) return;
  const json_access::json j = json_access::parse(w.measurements_json, w.measurements_file, limits);
  const json_access::Reader r(w.measurements_file, w.measurements_json);
  r.require_object(j, "");
  const std::string weights = r.optional_string(j, "/weight_data_types", "weight_data_types");
  const std::string inputs = r.optional_string(j, "/input_data_types", "input_data_types");
  if (!weights.empty()) set.provenance.settings.emplace_back("precision", weights);
  if (!inputs.empty() && inputs != weights) set.provenance.settings.emplace_back("input precision", inputs);
}

struct PowerResult {
  double mean_w = 0;
  double window_s = 0;
  std::size_t samples = 0;
};

// Mean power over LoadGen's power window from the PTDaemon log, as MLPerf's power result takes it.
std::optional<PowerResult> window_power(const MlperfCompanions& w, const LoadgenDetail& d, const ImportLimits& limits,
                                        const CancelToken& cancel, std::vector<std::string>& warnings) {
  if (w.spl_text.empty()) return std::nullopt;
  if (d.power_begin.empty() || d.power_end.empty()) {
    warnings.push_back(w.spl_file + ": a power log without LoadGen's power_begin/power_end in " +
                       (w.detail_file.empty() ? std::string("mlperf_log_detail.txt (absent)") : w.detail_file) +
                       ": no energy per query");
    return std::nullopt;
  }
  const ImportBatch ptd = kPtdLogFileFormat.parse_text(w.spl_text, w.spl_file, {}, limits, cancel);
  if (ptd.power_traces.empty()) return std::nullopt;
  const PowerTrace& t = ptd.power_traces.front();
  const auto start = parse_date_time(t.start_time);
  const auto begin = ptd_time_to_epoch(d.power_begin), end = ptd_time_to_epoch(d.power_end);
  if (!start || !begin || !end || *end <= *begin) {
    warnings.push_back(w.detail_file + ": power window " + d.power_begin + " .. " + d.power_end +
                       " is empty or unreadable: no energy per query");
    return std::nullopt;
  }
  const PowerChannel* power = nullptr;
  for (const PowerChannel& c : t.channels)
    if (c.name == "power") power = &c;
  if (!power) return std::nullopt;
  PowerResult r;
  double sum = 0;
  for (std::size_t i = 0; i < t.time_s.size(); ++i) {
    const double at = *start + t.time_s[i];
    if (at < *begin || at > *end || std::isnan(power->values[i])) continue;
    sum += power->values[i];
    ++r.samples;
  }
  if (r.samples == 0) {
    warnings.push_back(w.spl_file + ": no power sample inside LoadGen's power window " + d.power_begin + " .. " +
                       d.power_end + ": no energy per query");
    return std::nullopt;
  }
  r.mean_w = sum / static_cast<double>(r.samples);
  r.window_s = *end - *begin;
  return r;
}

std::string read_optional(const fs::path& p, const ImportLimits& limits) {
  std::error_code ec;
  if (!fs::is_regular_file(p, ec)) return {};
  return std::string(strip_utf8_bom(read_whole_file(p.string(), limits.max_json_bytes)));
}

// The companions of a summary at `path` in a submission tree (results/<system>/<network>/<scenario>/performance/
// run_N/): what exists is read, what does not stays empty.
MlperfCompanions companions_of(const std::string& path, const ImportLimits& limits) {
  MlperfCompanions w;
  const fs::path run = fs::path(path).parent_path();
  const auto read = [&](const fs::path& p, std::string& text, std::string& file) {
    text = read_optional(p, limits);
    if (!text.empty()) file = p.string();
  };
  read(run / "mlperf_log_detail.txt", w.detail_text, w.detail_file);
  read(run / "spl.txt", w.spl_text, w.spl_file);
  const fs::path perf = run.parent_path();
  if (perf.filename() != "performance") return w;
  const fs::path scenario = perf.parent_path(), network = scenario.parent_path(), system = network.parent_path();
  const fs::path results = system.parent_path();
  if (results.filename() != "results") return w;
  w.network = network.filename().string();
  w.system = system.filename().string();
  const fs::path root = results.parent_path();
  read(root / "systems" / (w.system + ".json"), w.system_json, w.system_file);
  // The measurements folder holds one <system>_<...>.json per scenario beside READMEs and configs.
  const fs::path m = root / "measurements" / w.system / w.network / scenario.filename();
  std::error_code ec;
  std::vector<fs::path> jsons;
  for (auto it = fs::directory_iterator(m, ec); !ec && it != fs::directory_iterator(); it.increment(ec))
    if (it->path().extension() == ".json" && it->path().filename() != "config.json") jsons.push_back(it->path());
  std::sort(jsons.begin(), jsons.end());
  if (!jsons.empty()) read(jsons.front(), w.measurements_json, w.measurements_file);
  return w;
}

}  // namespace

ImportBatch parse_mlperf_summary(const std::string& text, const std::string& file, const MlperfCompanions& with,
                                 const ImportLimits& limits, const CancelToken& cancel) {
  const LoadgenSummary s = parse_loadgen_summary(text, file);
  if (!s.mode.starts_with("Performance"))
    throw ImportError(ImportErrorCategory::Unsupported, {file, 0, 0, "Mode"},
                      "a " + s.mode + " run has no performance result (import the performance/run_1 summary)");
  cancel.throw_if_cancelled();
  ImportBatch batch;
  ResultSet set;
  set.platform = !with.system.empty() ? with.system : s.sut_name.empty() ? "MLPerf SUT" : s.sut_name;
  set.device = set.platform;
  set.backend = "MLPerf LoadGen";
  set.source_format = "mlperf-loadgen";
  set.provenance.origin = DataOrigin::Measured;
  set.provenance.source_file = file;
  read_system(with, limits, set);
  const std::string network = with.network.empty() ? std::string("network not stated") : with.network;
  const std::string name = network + " " + s.scenario;
  auto& st = set.provenance.settings;
  st.insert(st.begin(),
            {{"network", network}, {"scenario", s.scenario}, {"mode", s.mode}, {"result validity", s.validity}});
  for (const auto& [check, ok] : s.checks) st.emplace_back(check, ok ? "Yes" : "No");
  if (s.samples_per_query) st.emplace_back("samples per query", fmt(*s.samples_per_query));
  read_precision(with, limits, set);
  if (!s.valid)
    batch.warnings.push_back(file + ":" + std::to_string(s.validity_line) +
                             ": LoadGen marked this result INVALID; it is imported but is not a valid MLPerf result");

  // The headline metric in SI units, then the statistics LoadGen lists.
  const LoadgenValue& r = *s.result;
  const bool latency = r.key.find("(ns)") != std::string::npos;
  const bool per_query_count = r.key == "Samples per query";
  add(set, name, std::string(mlperf_metric::kResult) + ": " + r.key,
      latency           ? "s"
      : per_query_count ? ""
                        : "1/s",
      latency ? r.value * kNs : r.value);
  for (const LoadgenValue& v : s.values) {
    if (v.per_query) continue;
    if (v.key == "Min latency (ns)") add(set, name, mlperf_metric::kMinLatency, "s", v.value * kNs);
    if (v.key == "Max latency (ns)") add(set, name, mlperf_metric::kMaxLatency, "s", v.value * kNs);
    if (v.key == "Mean latency (ns)") add(set, name, mlperf_metric::kMeanLatency, "s", v.value * kNs);
    if (v.key.find("percentile latency (ns)") != std::string::npos && v.key[0] >= '0' && v.key[0] <= '9')
      add(set, name, percentile_metric(v.key), "s", v.value * kNs);
    if (v.key == "Samples per second" || v.key == "Completed samples per second")
      add(set, name, mlperf_metric::kSamplesPerSecond, "1/s", v.value);
  }
  const LoadgenValue* qps = s.find("QPS w/o loadgen overhead");
  if (!qps) qps = s.find("QPS w/ loadgen overhead");
  if (qps) add(set, name, mlperf_metric::kQps, "1/s", qps->value);
  if (qps && s.samples_per_query && s.scenario != "Offline" && !s.find("Samples per second"))
    add(set, name, mlperf_metric::kSamplesPerSecond, "1/s", qps->value * *s.samples_per_query);

  LoadgenDetail d;
  if (!with.detail_text.empty()) d = parse_loadgen_detail(with.detail_text, with.detail_file, limits);
  if (!d.loadgen_version.empty()) set.provenance.tool = "MLPerf LoadGen " + d.loadgen_version;
  set.provenance.date = d.test_datetime;
  if (const auto p = window_power(with, d, limits, cancel, batch.warnings)) {
    add(set, name, mlperf_metric::kMeanPower, "W", p->mean_w);
    set.provenance.measurement = MeasurementKind::ExternalMeter;
    set.provenance.sensor =
        "SPEC PTDaemon (spl.txt), " + std::to_string(p->samples) + " samples in LoadGen's power window";
    const double spq = s.samples_per_query.value_or(1);
    if (d.result_query_count) {
      const double per_query = p->mean_w * p->window_s / *d.result_query_count;
      add(set, name, mlperf_metric::kEnergyPerQuery, "J", per_query);
      add(set, name, mlperf_metric::kEnergyPerSample, "J", per_query / spq);
    } else if (const LoadgenValue* sps = s.find("Samples per second")) {
      if (sps->value > 0) add(set, name, mlperf_metric::kEnergyPerSample, "J", p->mean_w / sps->value);
    } else if (qps && qps->value > 0) {  // no query count in the detail log (v1.1): mean power / query rate
      add(set, name, mlperf_metric::kEnergyPerQuery, "J", p->mean_w / qps->value);
      add(set, name, mlperf_metric::kEnergyPerSample, "J", p->mean_w / qps->value / spq);
    }
  }
  batch.result_sets.push_back(std::move(set));
  return batch;
}

static int sniff_mlperf_submission(std::string_view head, std::string_view path) {
  if (head.substr(0, 512).find("MLPerf Results Summary") == std::string_view::npos) return 0;
  // Not results: accuracy runs, the power ranging pass, compliance (audit) tests. A folder walk passes them over.
  const std::string p(path);
  if (p.find("/ranging/") != std::string::npos || p.find("/compliance/") != std::string::npos) return 0;
  const std::size_t mode = head.find("Mode");
  if (mode != std::string_view::npos && head.substr(mode, 40).find("Accuracy") != std::string_view::npos) return 0;
  return 95;
}

static bool mlperf_submission_extension(std::string_view path) { return path.ends_with("mlperf_log_summary.txt"); }

static ImportBatch parse_mlperf_submission_file(const std::string& path, const ParseOptions& /*options*/,
                                                const ImportLimits& limits, const CancelToken& cancel) {
  const std::string text(strip_utf8_bom(read_whole_file(path, limits.max_json_bytes)));
  return parse_mlperf_summary(text, path, companions_of(path, limits), limits, cancel);
}

const FileFormat kMlperfLoadgenFileFormat{"mlperf-loadgen",
                                          "MLPerf Inference LoadGen result (mlperf_log_summary.txt)",
                                          sniff_mlperf_submission,
                                          parse_mlperf_submission_file,
                                          nullptr,
                                          mlperf_submission_extension};

}  // namespace bs
