// SPDX-License-Identifier: GPL-3.0-or-later
#include "mlperf/mlperf_submission.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "analysis/library/precision_words.h"
#include "analysis/power/power_time.h"
#include "common/json_access.h"
#include "mlperf/loadgen_detail.h"
#include "mlperf/loose_files.h"
#include "power/ptd_log.h"
#include "util/text.h"

namespace bs {
namespace fs = std::filesystem;
namespace {

constexpr double kNs = 1e-9;

std::string fmt(double v) { return format_number("%.6g", v); }

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
  // A system description with a submitter is a submission's: someone published it, this lab did not measure it.
  if (!text("submitter").empty()) set.provenance.origin = DataOrigin::Published;
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

// The precision from the measurements JSON by the library's words-to-type rule (precision_words.h): the type the
// weights end up in ("int8"), never the raw sentence, which is kept beside it. Words that name no type leave the
// precision not stated, with a warning quoting them.
void read_precision(const MlperfCompanions& w, const ImportLimits& limits, ResultSet& set,
                    std::vector<std::string>& warnings) {
  if (w.measurements_json.empty()) return;
  const json_access::json j = json_access::parse(w.measurements_json, w.measurements_file, limits);
  const json_access::Reader r(w.measurements_file, w.measurements_json);
  r.require_object(j, "");
  const std::string weights = r.optional_string(j, "/weight_data_types", "weight_data_types");
  const std::string transformations = r.optional_string(j, "/weight_transformations", "weight_transformations");
  const std::string inputs = r.optional_string(j, "/input_data_types", "input_data_types");
  auto& st = set.provenance.settings;
  if (!weights.empty()) st.emplace_back("stated weight data types", weights);
  const auto p = precision_from_words(weights, transformations);
  if (p) {
    st.emplace_back("precision", p->type);
    st.emplace_back("precision from", w.measurements_file + " (" + p->field + ")");
  } else {
    warnings.push_back(
        w.measurements_file + ": weight_data_types '" + weights + "'" +
        (transformations.empty() ? std::string() : " and weight_transformations '" + transformations + "'") +
        " name no data type: the precision is \"not stated\"");
  }
  const auto input_type = precision_from_words(inputs, {});
  const std::string input = input_type ? input_type->type : inputs;
  if (!input.empty() && (!p || input != p->type)) st.emplace_back("input precision", input);
}

struct PowerResult {
  double mean_w = 0;
  double window_s = 0;
  std::size_t samples = 0;
  bool whole_log = false;  // no LoadGen window: the mean over every sample of the log, not MLPerf's power
};

// The whole log's mean, when no detail log gives LoadGen's window: the result's own power still, but not MLPerf's
// (the log runs before and after the measured queries), so the caller flags it and derives no energy per query.
std::optional<PowerResult> whole_log_power(const PowerTrace& t, const std::string& file,
                                           std::vector<std::string>& warnings) {
  const PowerChannel* power = nullptr;
  for (const PowerChannel& c : t.channels)
    if (c.name == "power") power = &c;
  if (!power) return std::nullopt;
  PowerResult r;
  r.whole_log = true;
  double sum = 0;
  for (double v : power->values)
    if (!std::isnan(v)) {
      sum += v;
      ++r.samples;
    }
  if (r.samples == 0) {
    warnings.push_back(file + ": no power sample in the log");
    return std::nullopt;
  }
  r.mean_w = sum / static_cast<double>(r.samples);
  return r;
}

// Mean power over LoadGen's power window from the PTDaemon log, as MLPerf's power result takes it.
std::optional<PowerResult> window_power(const MlperfCompanions& w, const LoadgenDetail& d, const ImportLimits& limits,
                                        const CancelToken& cancel, std::vector<std::string>& warnings) {
  if (w.spl_text.empty()) return std::nullopt;
  const ImportBatch ptd = kPtdLogFileFormat.parse_text(w.spl_text, w.spl_file, {}, limits, cancel);
  if (ptd.power_traces.empty()) return std::nullopt;
  const PowerTrace& t = ptd.power_traces.front();
  if (d.power_begin.empty() || d.power_end.empty()) {
    warnings.push_back(w.spl_file + ": a power log without LoadGen's power_begin/power_end in " +
                       (w.detail_file.empty() ? std::string("mlperf_log_detail.txt (absent)") : w.detail_file) +
                       ": its mean is over the whole log, not MLPerf's power window (flagged), and no energy per "
                       "query is derived");
    return whole_log_power(t, w.spl_file, warnings);
  }
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

// MultiStream's rate as the library computes it (scripts/build-library.py): from v1.0 on, samples per query /
// the official latency per query (3,656.8 /s for 8 samples in 2.188 ms, not 1 / latency = 457.1 /s); v0.5, whose
// result is a number of streams, streams / the latency bound. Its definition is kept as the "throughput" setting,
// and the official statistic as "latency statistic", in the library's words, so rows of one class compare alike.
void multistream_rate(const LoadgenSummary& s, const LoadgenValue& official, const std::string& name, ResultSet& set) {
  auto& st = set.provenance.settings;
  const bool latency = official.key.find("(ns)") != std::string::npos || official.key.starts_with("Early stopping");
  if (latency && s.samples_per_query && *s.samples_per_query > 0 && official.value > 0) {
    const std::string stat =
        official.key.starts_with("Early stopping") ? "p99 per query early-stopping estimate" : "p99 per query";
    add(set, name, mlperf_metric::kSamplesPerSecond, "1/s", *s.samples_per_query / (official.value * kNs));
    st.emplace_back("latency statistic", stat + " of " + fmt(*s.samples_per_query) + " samples");
    st.emplace_back("throughput", "samples per query / " + stat + " latency");
    return;
  }
  const LoadgenValue* bound = s.find("target_latency (ns)");
  if (!latency && bound && bound->value > 0 && official.value > 0) {
    add(set, name, mlperf_metric::kSamplesPerSecond, "1/s", official.value / (bound->value * kNs));
    st.emplace_back("throughput", "streams / latency bound");
  }
}

std::string read_optional(const fs::path& p, const ImportLimits& limits) {
  std::error_code ec;
  if (!fs::is_regular_file(p, ec)) return {};
  return std::string(strip_utf8_bom(read_whole_file(p.string(), limits.max_json_bytes)));
}

// Whether the summary lies in a submission tree: results/<system>/<network>/<scenario>/performance/run_N/.
bool in_submission_tree(const fs::path& summary) {
  const fs::path perf = summary.parent_path().parent_path();
  return perf.filename() == "performance" &&
         perf.parent_path().parent_path().parent_path().parent_path().filename() == "results";
}

}  // namespace

std::vector<std::string> mlperf_companion_paths(const std::string& summary_path) {
  const fs::path p(summary_path);
  std::vector<std::string> out;
  if (in_submission_tree(p)) {
    // run_N/ holds the run's detail log and power log under their plain names.
    for (const char* n : {"mlperf_log_detail.txt", "spl.txt"})
      if (std::error_code ec; fs::is_regular_file(p.parent_path() / n, ec))
        out.push_back((p.parent_path() / n).string());
    return out;
  }
  // Loose files (loose_files.h): what pairs with it unambiguously, the system and measurements JSONs included.
  const mlperf_loose::LooseFiles f = mlperf_loose::loose_files_of(p, ImportLimits{});
  for (const std::string* c : {&f.detail, &f.spl, &f.system, &f.measurements})
    if (!c->empty()) out.push_back(*c);
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
  const std::string path_lower = bs::lower(path);
  for (const auto& [k, v] : kNames)
    if (path_lower.find(k) != std::string::npos) return std::string(v);
  return {};
}

namespace {

// The companions of a summary at `path` in a submission tree (results/<system>/<network>/<scenario>/performance/
// run_N/), or loose beside it: what exists is read, what does not stays empty.
MlperfCompanions companions_of(const std::string& path, const ImportLimits& limits) {
  MlperfCompanions w;
  const fs::path run = fs::path(path).parent_path();
  const auto read = [&](const fs::path& p, std::string& text, std::string& file) {
    text = read_optional(p, limits);
    if (!text.empty()) file = p.string();
  };
  if (!in_submission_tree(path)) {
    const mlperf_loose::LooseFiles f = mlperf_loose::loose_files_of(path, limits);
    if (!f.detail.empty()) read(f.detail, w.detail_text, w.detail_file);
    if (!f.spl.empty()) read(f.spl, w.spl_text, w.spl_file);
    if (!f.system.empty()) read(f.system, w.system_json, w.system_file);
    if (!f.measurements.empty()) read(f.measurements, w.measurements_json, w.measurements_file);
    w.pairing_note = f.pairing_note;
    w.system_note = f.system_note;
    w.measurements_note = f.measurements_note;
    w.network = network_from_name(fs::path(path).filename().string());
    if (w.network.empty()) w.network = network_from_name(run.filename().string());
    w.loose = true;
    return w;
  }
  read(run / "mlperf_log_detail.txt", w.detail_text, w.detail_file);
  read(run / "spl.txt", w.spl_text, w.spl_file);
  const fs::path perf = run.parent_path();
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
  if (!with.pairing_note.empty())
    batch.warnings.push_back(file + ": " + with.pairing_note + " (name each run's files with one prefix)");
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
  read_precision(with, limits, set, batch.warnings);
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
  if (s.scenario == "MultiStream") {
    multistream_rate(s, r, name, set);
  } else if (qps && s.samples_per_query && s.scenario != "Offline" && !s.find("Samples per second")) {
    add(set, name, mlperf_metric::kSamplesPerSecond, "1/s", qps->value * *s.samples_per_query);
  }

  LoadgenDetail d;
  if (!with.detail_text.empty()) d = parse_loadgen_detail(with.detail_text, with.detail_file, limits);
  if (!d.loadgen_version.empty()) set.provenance.tool = "MLPerf LoadGen " + d.loadgen_version;
  set.provenance.date = d.test_datetime;
  const auto power = window_power(with, d, limits, cancel, batch.warnings);
  if (const auto& p = power) {
    add(set, name, mlperf_metric::kMeanPower, "W", p->mean_w);
    set.provenance.measurement = MeasurementKind::ExternalMeter;
    set.provenance.sensor = "SPEC PTDaemon (spl.txt), " + std::to_string(p->samples) +
                            (p->whole_log ? " samples over the whole log (no LoadGen power window: not MLPerf's power)"
                                          : " samples in LoadGen's power window");
    st.emplace_back("power kind", "AC wall");  // PTDaemon meters the whole system at the mains plug
    st.emplace_back("power log", with.spl_file);
    if (p->whole_log) {
      st.emplace_back("power window", "whole log: no LoadGen power_begin/power_end (" + w_detail_name(with) + ")");
      st.emplace_back("flag", "mean power over the whole spl.txt, not MLPerf's power window");
    }
  }
  if (const auto& p = power; p && !p->whole_log) {
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
                                          "mlperf_log_summary.txt"};

}  // namespace bs
