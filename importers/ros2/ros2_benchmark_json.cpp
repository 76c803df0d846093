// SPDX-License-Identifier: GPL-3.0-or-later
#include "ros2/ros2_benchmark_json.h"

#include <cmath>
#include <cstdio>

#include "common/json_access.h"

namespace bs {
namespace {

struct Field {
  const char* key;     // after "BasicPerformanceMetrics." / "CPUProfilingMetrics."
  const char* metric;  // what the value is
  const char* unit;    // as stored (SI)
  double scale;        // file unit -> SI
};

// What each value is (basic_performance_calculator.py, conclude_performance()).
constexpr Field kFields[] = {
    {"BasicPerformanceMetrics.MEAN_FRAME_RATE", "frame rate (received frames / received duration, mean of runs)", "1/s",
     1},
    {"BasicPerformanceMetrics.MEAN_PLAYBACK_FRAME_RATE", "playback rate (sent frames / sent duration, mean of runs)",
     "1/s", 1},
    {"BasicPerformanceMetrics.NUM_FRAMES_SENT", "frames sent (mean of runs)", "", 1},
    {"BasicPerformanceMetrics.NUM_MISSED_FRAMES", "frames missed (mean of runs)", "", 1},
    {"BasicPerformanceMetrics.FIRST_SENT_RECEIVED_LATENCY",
     "latency of the FIRST message only (mean of runs; not a latency distribution)", "s", 1e-3},
    {"BasicPerformanceMetrics.LAST_SENT_RECEIVED_LATENCY",
     "latency of the LAST message only (mean of runs; not a latency distribution)", "s", 1e-3},
    {"BasicPerformanceMetrics.MAX_JITTER", "frame-to-frame jitter, max over runs", "s", 1e-3},
    {"BasicPerformanceMetrics.MIN_JITTER", "frame-to-frame jitter, min over runs", "s", 1e-3},
    {"BasicPerformanceMetrics.MEAN_JITTER",
     "frame-to-frame jitter, the LARGEST of the runs' means (called 'mean': a maximum)", "s", 1e-3},
    {"BasicPerformanceMetrics.STD_DEV_JITTER", "frame-to-frame jitter SD (mean of runs)", "s", 1e-3},
    {"BasicPerformanceMetrics.RECEIVED_DURATION", "received duration (mean of runs)", "s", 1e-3},
    {"CPUProfilingMetrics.MEAN_CPU_UTIL", "CPU use, mean (% of all cores)", "%", 1},
    {"CPUProfilingMetrics.MAX_CPU_UTIL", "CPU use, max (% of all cores)", "%", 1},
    {"CPUProfilingMetrics.MIN_CPU_UTIL", "CPU use, min (% of all cores)", "%", 1},
    {"CPUProfilingMetrics.STD_DEV_CPU_UTIL", "CPU use, SD (% of all cores)", "%", 1},
    {"CPUProfilingMetrics.BASELINE_CPU_UTIL", "CPU use before the run (% of all cores)", "%", 1},
};

// "  default_config_version: 0.30.0\n" inside the CONFIG text -> "0.30.0".
std::string config_value(const std::string& config, const std::string& key) {
  const std::size_t at = config.find(key + ": ");
  if (at == std::string::npos) return {};
  const std::size_t from = at + key.size() + 2, to = config.find('\n', from);
  return config.substr(from, to == std::string::npos ? std::string::npos : to - from);
}

void add_run(const json_access::Reader& r, const json_access::json& obj, const std::string& pointer,
             const std::string& name, ResultSet& set, std::vector<std::string>& warnings, const std::string& file) {
  for (const Field& f : kFields) {
    const auto it = obj.find(f.key);
    if (it == obj.end()) continue;
    if (!it->is_number()) r.fail(ImportErrorCategory::WrongType, pointer + "/" + f.key, "not a number");
    const double v = it->get<double>();
    if (!std::isfinite(v) || v < 0)
      r.fail(ImportErrorCategory::InvalidValue, pointer + "/" + f.key, "a negative or non-finite value");
    Measurement m;
    m.name = name;
    m.metric = f.metric;
    m.unit = f.unit;
    m.values = {v * f.scale};
    set.measurements.push_back(std::move(m));
  }
  const auto missed = obj.find("BasicPerformanceMetrics.NUM_MISSED_FRAMES");
  if (missed != obj.end() && missed->is_number() && missed->get<double>() > 0)
    warnings.push_back(file + ": " + name + ": " + std::to_string(missed->get<double>()) + " frames missed");
}

ImportBatch parse_ros2_benchmark(const std::string& text, const std::string& file, const ParseOptions&,
                                 const ImportLimits& limits, const CancelToken& cancel) {
  const json_access::json j = json_access::parse(text, file, limits);
  const json_access::Reader r(file, text);
  r.require_object(j, "");
  const auto meta = j.find("metadata");
  if (meta == j.end() || !meta->is_object())
    r.fail(ImportErrorCategory::MissingField, "/metadata", "no metadata object: not a ros2_benchmark result");
  const std::string bench = r.optional_string(*meta, "/metadata/BenchmarkMetadata.NAME", "BenchmarkMetadata.NAME");
  if (bench.empty()) r.fail(ImportErrorCategory::MissingField, "/metadata/BenchmarkMetadata.NAME", "missing");
  const std::string config = r.optional_string(*meta, "/metadata/BenchmarkMetadata.CONFIG", "BenchmarkMetadata.CONFIG");
  ImportBatch batch;
  ResultSet set;
  set.source_format = "ros2-benchmark-json";
  set.backend = "ROS 2 (ros2_benchmark)";
  set.device = r.optional_string(*meta, "/metadata/BenchmarkMetadata.DEVICE_ARCH", "BenchmarkMetadata.DEVICE_ARCH");
  set.device_kind = DeviceKind::Other;
  // The hostname is a container's; the computer is not in the file: not stated, unless the user names it.
  set.platform = "computer not stated (" + file + ")";
  auto& p = set.provenance;
  p.origin = DataOrigin::Measured;
  p.tool = "NVIDIA ros2_benchmark";
  p.source_file = file;
  p.date = r.optional_string(*meta, "/metadata/BenchmarkMetadata.TEST_DATETIME", "BenchmarkMetadata.TEST_DATETIME");
  p.os = r.optional_string(*meta, "/metadata/BenchmarkMetadata.DEVICE_OS", "BenchmarkMetadata.DEVICE_OS");
  p.host = r.optional_string(*meta, "/metadata/BenchmarkMetadata.DEVICE_HOSTNAME", "BenchmarkMetadata.DEVICE_HOSTNAME");
  p.settings.emplace_back("benchmark", bench);
  std::string input;
  if (const auto c = j.find("custom"); c != j.end() && c->is_object())
    input = r.optional_string(*c, "/custom/data_resolution", "data_resolution");
  p.settings.emplace_back("input", input.empty() ? "not stated" : input);
  const std::string release = config_value(config, "default_config_version");
  p.settings.emplace_back("release", release.empty() ? "not stated" : "ros2_benchmark config " + release);
  p.settings.emplace_back("iterations", config_value(config, "test_iterations"));
  p.settings.emplace_back("latency fields", "first and last message only");
  p.settings.emplace_back("mean jitter", "the largest of the runs' means: a maximum");
  if (const auto pk = meta->find("BenchmarkMetadata.PEAK_THROUGHPUT_PREDICTION"); pk != meta->end() && pk->is_number())
    p.settings.emplace_back("peak throughput prediction", std::to_string(pk->get<double>()) + " fps");
  add_run(r, j, "", bench + " at peak throughput", set, batch.warnings, file);
  for (const auto& [key, value] : j.items()) {
    cancel.throw_if_cancelled();
    if (!key.ends_with("fps") || !value.is_object()) continue;
    add_run(r, value, "/" + key, bench + " at " + key, set, batch.warnings, file);
  }
  if (set.measurements.empty())
    r.fail(ImportErrorCategory::MissingField, "", "no BasicPerformanceMetrics values: not a ros2_benchmark result");
  batch.warnings.push_back(file + ": the file does not name the computer (DEVICE_HOSTNAME '" + p.host +
                           "' is a container's): give it with --platform");
  batch.result_sets.push_back(std::move(set));
  return batch;
}

int sniff_ros2_benchmark(std::string_view head, std::string_view) {
  return head.find("\"BasicPerformanceMetrics.") != std::string_view::npos ? 96 : 0;
}

bool json_extension(std::string_view path) { return path.ends_with(".json"); }

}  // namespace

const FileFormat kRos2BenchmarkJsonFileFormat{"ros2-benchmark-json", "NVIDIA ros2_benchmark result JSON",
                                              sniff_ros2_benchmark,  parse_text_file_with<parse_ros2_benchmark>,
                                              parse_ros2_benchmark,  json_extension};

}  // namespace bs
