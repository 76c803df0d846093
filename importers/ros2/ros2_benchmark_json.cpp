// SPDX-License-Identifier: GPL-3.0-or-later
#include "ros2/ros2_benchmark_json.h"

#include <cmath>
#include <cstdlib>
#include <string_view>

#include "common/json_access.h"
#include "util/text.h"

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
    {"CPUProfilingMetrics.BASELINE_CPU_UTIL", "CPU use baseline, measured during the run (% of all cores)", "%", 1},
    // The 2024+ schema (ros2_benchmark's ResourceMetrics): the same CPU use under new names, and the GPU's.
    {"ResourceMetrics.MEAN_OVERALL_CPU_UTILIZATION", "CPU use, mean (% of all cores)", "%", 1},
    {"ResourceMetrics.MAX_OVERALL_CPU_UTILIZATION", "CPU use, max (% of all cores)", "%", 1},
    {"ResourceMetrics.MIN_OVERALL_CPU_UTILIZATION", "CPU use, min (% of all cores)", "%", 1},
    {"ResourceMetrics.STDDEV_OVERALL_CPU_UTILIZATION", "CPU use, SD (% of all cores)", "%", 1},
    {"ResourceMetrics.BASELINE_OVERALL_CPU_UTILIZATION", "CPU use baseline, measured during the run (% of all cores)",
     "%", 1},
    {"ResourceMetrics.MEAN_DEVICE_UTILIZATION", "GPU use, mean (%)", "%", 1},
    {"ResourceMetrics.MAX_DEVICE_UTILIZATION", "GPU use, max (%)", "%", 1},
    {"ResourceMetrics.MIN_DEVICE_UTILIZATION", "GPU use, min (%)", "%", 1},
    {"ResourceMetrics.STDDEV_DEVICE_UTILIZATION", "GPU use, SD (%)", "%", 1},
    {"ResourceMetrics.BASELINE_DEVICE_UTILIZATION", "GPU use baseline, measured during the run (%)", "%", 1},
};

// A fixed-rate section ("10.0fps") is one run at that publisher rate, not the kept runs of the peak search: its
// values are that run's, so "mean of runs" and "over runs" would say what they are not.
std::string for_one_run(std::string metric) {
  const std::pair<std::string_view, std::string_view> kWords[] = {
      {"mean of runs", "one run"},
      {"max over runs", "the run's max"},
      {"min over runs", "the run's min"},
      {"the LARGEST of the runs' means (called 'mean': a maximum)", "the run's mean"}};
  for (const auto& [from, to] : kWords)
    if (const std::size_t at = metric.find(from); at != std::string::npos) metric.replace(at, from.size(), to);
  return metric;
}

// The ROS 2 distribution the harness ran from: "/opt/ros/jazzy/..." in the test script's path; "" when not there
// (the 2023 results ran from a workspace checkout, whose path names none).
std::string ros_distro(std::string_view path) {
  constexpr std::string_view kOpt = "/opt/ros/";
  const std::size_t at = path.find(kOpt);
  if (at == std::string_view::npos) return {};
  const std::size_t from = at + kOpt.size(), to = path.find('/', from);
  return std::string(path.substr(from, to == std::string_view::npos ? std::string_view::npos : to - from));
}

std::string fmt(double v) { return format_number("%.1f", v); }

// "  default_config_version: 0.30.0\n" inside the CONFIG text -> "0.30.0".
std::string config_value(const std::string& config, const std::string& key) {
  const std::size_t at = config.find(key + ": ");
  if (at == std::string::npos) return {};
  const std::size_t from = at + key.size() + 2, to = config.find('\n', from);
  return config.substr(from, to == std::string::npos ? std::string::npos : to - from);
}

void add_run(const json_access::Reader& r, const json_access::json& obj, const std::string& pointer,
             const std::string& name, bool one_run, ResultSet& set, std::vector<std::string>& warnings,
             const std::string& file) {
  for (const Field& f : kFields) {
    const auto it = obj.find(f.key);
    if (it == obj.end()) continue;
    if (!it->is_number()) r.fail(ImportErrorCategory::WrongType, pointer + "/" + f.key, "not a number");
    const double v = it->get<double>();
    if (!std::isfinite(v) || v < 0)
      r.fail(ImportErrorCategory::InvalidValue, pointer + "/" + f.key, "a negative or non-finite value");
    Measurement m;
    m.name = name;
    m.metric = one_run ? for_one_run(f.metric) : std::string(f.metric);
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
  // The release from the file's own facts: default_config_version is 0.30.0 in every version from 2023 on, so it
  // tells no release apart; the test date and the ROS 2 distribution do (Humble-era 2023 workspaces, Jazzy 2025).
  const std::string config_version = config_value(config, "default_config_version");
  const std::string script =
      r.optional_string(*meta, "/metadata/BenchmarkMetadata.TEST_FILE_PATH", "BenchmarkMetadata.TEST_FILE_PATH");
  const std::string distro = ros_distro(script);
  std::string release;
  if (p.date.size() >= 7) release = "run " + p.date.substr(0, 7);
  if (!distro.empty()) release += (release.empty() ? "" : ", ") + std::string("ROS 2 ") + distro;
  p.settings.emplace_back("release", release.empty() ? "not stated" : "ros2_benchmark " + release);
  if (!config_version.empty()) p.settings.emplace_back("config version", config_version);
  if (distro.empty())
    batch.warnings.push_back(file + ": the ROS 2 distribution is not in the file (TEST_FILE_PATH '" + script +
                             "'): the release is told by the test date alone");
  p.settings.emplace_back("iterations", config_value(config, "test_iterations"));
  p.settings.emplace_back("latency fields", "first and last message only");
  p.settings.emplace_back("mean jitter", "the largest of the runs' means: a maximum");
  if (const auto pk = meta->find("BenchmarkMetadata.PEAK_THROUGHPUT_PREDICTION"); pk != meta->end() && pk->is_number())
    p.settings.emplace_back("peak throughput prediction", std::to_string(pk->get<double>()) + " fps");
  add_run(r, j, "", bench + " at peak throughput", false, set, batch.warnings, file);
  for (const auto& [key, value] : j.items()) {
    cancel.throw_if_cancelled();
    if (!key.ends_with("fps") || !value.is_object()) continue;
    add_run(r, value, "/" + key, bench + " at " + key + " (one run at a fixed rate)", true, set, batch.warnings, file);
  }
  // A peak at the harness's publisher ceiling measures the publisher, not the node: flagged.
  const std::string ceiling_text = config_value(config, "publisher_upper_frequency");
  const auto peak = j.find("BasicPerformanceMetrics.MEAN_FRAME_RATE");
  if (char* end = nullptr; !ceiling_text.empty() && peak != j.end() && peak->is_number()) {
    const double ceiling = std::strtod(ceiling_text.c_str(), &end);
    if (end != ceiling_text.c_str() && ceiling > 0 && peak->get<double>() >= 0.99 * ceiling) {
      p.settings.emplace_back("flag", "peak at the publisher ceiling: " + fmt(peak->get<double>()) +
                                          " fps against publisher_upper_frequency " + ceiling_text +
                                          ": the node may be faster than measured");
      batch.warnings.push_back(file + ": the peak frame rate " + fmt(peak->get<double>()) +
                               " fps is at the harness's publisher ceiling (publisher_upper_frequency " + ceiling_text +
                               "): a lower bound of the node's rate, not its peak");
    }
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

}  // namespace

const FileFormat kRos2BenchmarkJsonFileFormat{"ros2-benchmark-json", "NVIDIA ros2_benchmark result JSON",
                                              sniff_ros2_benchmark,  parse_text_file_with<parse_ros2_benchmark>,
                                              parse_ros2_benchmark,  ".json"};

}  // namespace bs
