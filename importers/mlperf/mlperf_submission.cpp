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
    // Strictly inside, as the submission checker takes it: power_begin < t < power_end.
    if (at <= *begin || at >= *end || std::isnan(power->values[i])) continue;
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

void loose_system(const fs::path& folder, const std::string& summary_name, const ImportLimits& limits,
                  MlperfCompanions& w);
void loose_measurements(const fs::path& folder, const std::string& summary_name, const ImportLimits& limits,
                        MlperfCompanions& w);

}  // namespace

std::vector<std::string> mlperf_companion_paths(const std::string& summary_path) {
  // A summary named "<prefix>mlperf_log_summary<suffix>" has its detail log and power log beside it under the same
  // prefix and suffix ("orin-ss-mlperf_log_detail.txt", "orin-ss-spl.txt"): a lab's loose download keeps them so.
  const fs::path p(summary_path);
  const std::string name = p.filename().string();
  const std::size_t at = name.find("mlperf_log_summary");
  std::vector<std::string> out;
  if (at == std::string::npos) return out;
  const std::string prefix = name.substr(0, at), suffix = name.substr(at + std::string("mlperf_log_summary").size());
  for (const std::string& n : {prefix + "mlperf_log_detail" + suffix, prefix + "spl" + suffix})
    if (std::error_code ec; fs::is_regular_file(p.parent_path() / n, ec)) out.push_back((p.parent_path() / n).string());
  // Loose files: the system description taken beside it (companions_of) is read with it too.
  const fs::path perf = p.parent_path().parent_path();
  if (perf.filename() != "performance") {
    MlperfCompanions w;
    loose_system(p.parent_path(), name, ImportLimits{}, w);
    if (!w.system_file.empty()) out.push_back(w.system_file);
    loose_measurements(p.parent_path(), name, ImportLimits{}, w);
    if (!w.measurements_file.empty()) out.push_back(w.measurements_file);
  }
  return out;
}

std::string network_from_name(std::string_view path) {
  // MLPerf's benchmark names as results folders and file names spell them, most specific first.
  static const std::vector<std::pair<std::string_view, std::string_view>> kNames = {{"ssd-mobilenet", "ssd-mobilenet"},
                                                                                    {"ssd_mobilenet", "ssd-mobilenet"},
                                                                                    {"ssd-small", "ssd-mobilenet"},
                                                                                    {"ssd-resnet34", "ssd-resnet34"},
                                                                                    {"ssd-large", "ssd-resnet34"},
                                                                                    {"retinanet", "retinanet"},
                                                                                    {"resnet50", "resnet50"},
                                                                                    {"resnet", "resnet50"},
                                                                                    {"3d-unet", "3d-unet"},
                                                                                    {"bert", "bert"},
                                                                                    {"rnnt", "rnnt"},
                                                                                    {"dlrm", "dlrm"},
                                                                                    {"gptj", "gptj"},
                                                                                    {"mobilenet", "mobilenet"}};
  std::string lower(path);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const auto& [k, v] : kNames)
    if (lower.find(k) != std::string::npos) return std::string(v);
  return {};
}

namespace {

// An MLPerf system description (systems/<system>.json): a JSON object with system_name and submitter.
bool is_system_json(const std::string& text) {
  return text.find("\"system_name\"") != std::string::npos && text.find("\"submitter\"") != std::string::npos &&
         text.find("\"host_processor_model_name\"") != std::string::npos;
}

// The system description beside loose files: the one system JSON in the summary's folder (or its systems/
// subfolder), or among several the one whose file stem the summary's file name contains. None when the files do
// not say: the computer is then "not stated", never the harness's SUT name.
void loose_system(const fs::path& folder, const std::string& summary_name, const ImportLimits& limits,
                  MlperfCompanions& w) {
  std::vector<fs::path> found;
  for (const fs::path& dir : {folder, folder / "systems"}) {
    std::error_code ec;
    for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator(); it.increment(ec))
      if (it->path().extension() == ".json" && is_system_json(read_optional(it->path(), limits)))
        found.push_back(it->path());
  }
  std::sort(found.begin(), found.end());
  const fs::path* chosen = found.size() == 1 ? &found.front() : nullptr;
  for (const fs::path& f : found)
    if (found.size() > 1 && summary_name.find(f.stem().string()) != std::string::npos &&
        (!chosen || f.stem().string().size() > chosen->stem().string().size()))
      chosen = &f;
  if (!chosen) {
    if (found.size() > 1)
      w.system_note = std::to_string(found.size()) + " system descriptions beside it, none named by it";
    return;
  }
  w.system_json = read_optional(*chosen, limits);
  w.system_file = chosen->string();
}

// An MLPerf measurements description (measurements/<system>/<network>/<scenario>/<system>_<scenario>.json): the
// weight and input data types the result ran with.
bool is_measurements_json(const std::string& text) {
  return text.find("\"weight_data_types\"") != std::string::npos &&
         text.find("\"input_data_types\"") != std::string::npos;
}

// The measurements description beside loose files, in the summary's folder or its measurements/ subfolder. Its
// own name says no network ("Orin_TRT_MaxQ_SingleStream.json" for every network), so it belongs to a summary only
// when it carries the summary's prefix ("orin-retinanet-ss-" for "orin-retinanet-ss-mlperf_log_summary.txt"), or
// when it and the summary are the only ones in the folder. Otherwise the precision stays "not stated", and why.
void loose_measurements(const fs::path& folder, const std::string& summary_name, const ImportLimits& limits,
                        MlperfCompanions& w) {
  const std::string prefix = summary_name.substr(0, summary_name.find("mlperf_log_summary"));
  std::vector<fs::path> found;
  std::size_t summaries = 0;
  for (const fs::path& dir : {folder, folder / "measurements"}) {
    std::error_code ec;
    for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator(); it.increment(ec)) {
      const std::string name = it->path().filename().string();
      if (dir == folder && name.find("mlperf_log_summary") != std::string::npos) ++summaries;
      if (it->path().extension() == ".json" && is_measurements_json(read_optional(it->path(), limits)))
        found.push_back(it->path());
    }
  }
  std::sort(found.begin(), found.end());
  const fs::path* chosen = nullptr;
  for (const fs::path& f : found)
    if (!prefix.empty() && f.filename().string().starts_with(prefix)) {
      if (chosen) {  // two with its prefix: neither is known to be its own
        chosen = nullptr;
        break;
      }
      chosen = &f;
    }
  if (!chosen && found.size() == 1 && summaries == 1) chosen = &found.front();
  if (!chosen) {
    if (!found.empty())
      w.measurements_note = std::to_string(found.size()) + " measurements description(s) beside it, none named " +
                            (prefix.empty() ? std::string("for it") : "with its prefix '" + prefix + "'");
    return;
  }
  w.measurements_json = read_optional(*chosen, limits);
  w.measurements_file = chosen->string();
}

// The companions of a summary at `path` in a submission tree (results/<system>/<network>/<scenario>/performance/
// run_N/), or loose beside it: what exists is read, what does not stays empty.
MlperfCompanions companions_of(const std::string& path, const ImportLimits& limits) {
  MlperfCompanions w;
  const fs::path run = fs::path(path).parent_path();
  const auto read = [&](const fs::path& p, std::string& text, std::string& file) {
    text = read_optional(p, limits);
    if (!text.empty()) file = p.string();
  };
  for (const std::string& c : mlperf_companion_paths(path))
    if (!c.ends_with(".json"))
      read(c, c.find("mlperf_log_detail") != std::string::npos ? w.detail_text : w.spl_text,
           c.find("mlperf_log_detail") != std::string::npos ? w.detail_file : w.spl_file);
  const fs::path perf = run.parent_path();
  if (perf.filename() != "performance" ||
      perf.parent_path().parent_path().parent_path().parent_path().filename() != "results") {
    w.network = network_from_name(fs::path(path).filename().string());
    if (w.network.empty()) w.network = network_from_name(run.filename().string());
    loose_system(run, fs::path(path).filename().string(), limits, w);
    loose_measurements(run, fs::path(path).filename().string(), limits, w);
    w.loose = true;
    return w;
  }
  const fs::path scenario = perf.parent_path(), network = scenario.parent_path(), system = network.parent_path();
  const fs::path results = system.parent_path();
  w.network = network.filename().string();
  w.system = system.filename().string();
  const fs::path root = results.parent_path();
  read(root / "systems" / (w.system + ".json"), w.system_json, w.system_file);
  // The measurements folder holds one <system>_<...>.json per scenario beside READMEs and configs.
  // v0.5 named one benchmark differently in results/ and measurements/ (resnet/ against resnet50/): the result's
  // own benchmark is looked for under both names, so its precision comes from its own measurements.
  std::vector<fs::path> jsons;
  for (const std::string& net : {w.network, network_from_name(w.network)}) {
    const fs::path m = root / "measurements" / w.system / net / scenario.filename();
    std::error_code ec;
    for (auto it = fs::directory_iterator(m, ec); !ec && it != fs::directory_iterator(); it.increment(ec))
      if (it->path().extension() == ".json" && it->path().filename() != "config.json") jsons.push_back(it->path());
    if (!jsons.empty()) break;
  }
  std::sort(jsons.begin(), jsons.end());
  if (!jsons.empty()) read(jsons.front(), w.measurements_json, w.measurements_file);
  return w;
}

std::string w_detail_name(const MlperfCompanions& w) {
  return w.detail_file.empty() ? std::string("mlperf_log_detail.txt (absent)") : w.detail_file;
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
  // The computer comes from the system description (read_system below), else the folder's system name; the SUT
  // name is the harness's ("LWIS_Server", "SUT"), never the computer's.
  set.platform = !with.system.empty() ? with.system : "computer not stated (" + file + ")";
  set.device = set.platform;
  set.backend = "MLPerf LoadGen";
  set.source_format = "mlperf-loadgen";
  set.provenance.origin = DataOrigin::Measured;
  set.provenance.source_file = file;
  read_system(with, limits, set);
  const std::string network = with.network.empty() ? std::string("network not stated") : with.network;
  if (with.system_json.empty())
    batch.warnings.push_back(file + ": no system description beside it" +
                             (with.system_note.empty() ? std::string() : " (" + with.system_note + ")") +
                             ": the computer is not stated (LoadGen's SUT name '" + s.sut_name +
                             "' is the harness's, not the computer's); give it with --platform");
  if (with.network.empty())
    batch.warnings.push_back(file +
                             ": neither its folders nor its name say the network: \"network not stated\", "
                             "never ranked with another result");
  const std::string name = network + " " + s.scenario;
  auto& st = set.provenance.settings;
  st.insert(st.begin(),
            {{"network", network}, {"scenario", s.scenario}, {"mode", s.mode}, {"result validity", s.validity}});
  for (const auto& [check, ok] : s.checks) st.emplace_back(check, ok ? "Yes" : "No");
  if (s.samples_per_query) st.emplace_back("samples per query", fmt(*s.samples_per_query));
  read_precision(with, limits, set);
  if (with.loose && with.measurements_json.empty())
    batch.warnings.push_back(file + ": no measurements JSON (<system>_<scenario>.json) beside it" +
                             (with.measurements_note.empty() ? std::string() : " (" + with.measurements_note + ")") +
                             ": its precision is \"not stated\", ranked only beside results of unstated precision");
  if (!s.valid)
    batch.warnings.push_back(file + ":" + std::to_string(s.validity_line) +
                             ": LoadGen marked this result INVALID; it is imported but is not a valid MLPerf result");

  // The round's official result in SI units (the early-stopping estimate where LoadGen printed one), then the
  // statistics LoadGen lists (the plain percentiles among them).
  const LoadgenValue& r = *official_result(s);
  st.emplace_back("official metric", r.key + " (line " + std::to_string(r.line) + ")");
  const bool latency = r.key.find("(ns)") != std::string::npos || r.key.starts_with("Early stopping");
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
    st.emplace_back("power kind", "AC wall");  // PTDaemon meters the whole system at the mains plug
    const double spq = s.samples_per_query.value_or(1);
    // MLPerf's power metric as the submission checker defines it: Offline/Server the mean power (W); the stream
    // scenarios energy per query: from v2.0 mean x window / result_query_count (published in mJ), before v2.0
    // (no query count logged) mean x window / (QPS with LoadGen overhead x window) (published in J).
    const bool streams = s.scenario == "SingleStream" || s.scenario == "MultiStream";
    if (streams && d.result_query_count) {
      const double per_query = p->mean_w * p->window_s / *d.result_query_count;
      add(set, name, mlperf_metric::kEnergyPerQuery, "J", per_query);
      add(set, name, mlperf_metric::kEnergyPerSample, "J", per_query / spq);
      st.emplace_back("power metric", fmt(per_query * 1000) +
                                          " mJ/query (mean power x window x 1000 / "
                                          "result_query_count, MLPerf v2.0 on)");
    } else if (s.scenario == "SingleStream" && d.qps_with_loadgen_overhead) {
      const double per_query = p->mean_w / *d.qps_with_loadgen_overhead;
      add(set, name, mlperf_metric::kEnergyPerQuery, "J", per_query);
      add(set, name, mlperf_metric::kEnergyPerSample, "J", per_query);
      st.emplace_back("power metric", fmt(per_query) +
                                          " J/query (mean power / QPS with LoadGen overhead, "
                                          "MLPerf before v2.0)");
    } else if (const LoadgenValue* sps = s.find("Samples per second"); sps && sps->value > 0) {
      add(set, name, mlperf_metric::kEnergyPerSample, "J", p->mean_w / sps->value);
      st.emplace_back("power metric", fmt(p->mean_w) + " W (mean power in LoadGen's window)");
    } else if (streams) {
      batch.warnings.push_back(w_detail_name(with) +
                               ": neither result_query_count nor "
                               "result_qps_with_loadgen_overhead: no energy per query as MLPerf defines it");
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
