// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The library of published results (resources/library/library.json, built by scripts/build-library.py from public
// files it keeps with their sources): MLPerf Inference edge results, clpeak peaks, HPL results and timing reports of
// candidate robot computers a lab does not own yet. Every result is origin "published" and names its URL, commit,
// kept file and the line of each value; every result is checked for plausibility on load, as imports are.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "analysis/peaks/plausibility.h"

namespace bs {

struct LibrarySource {
  std::string url;  // with the commit for repository files
  std::string repository, commit, path;
  // The kept copy, relative to the kept tree's resources/library/ ("sources/..."): the kept files live outside the
  // project (BENCHSCOPE_PUBLIC_DATA_DIR/resources/library/), never in it.
  std::string kept;
  std::string licence;
  std::vector<std::pair<std::string, long long>> lines;  // value -> line in the kept file
  // Companions in the same repository (paths as in `path`): the system description, the measurements JSON the
  // precision comes from (and which field said it), the detail log and the PTDaemon log of a power run.
  std::string system, precision_from, precision_rule, detail, power_from;
  std::vector<std::pair<std::string, long long>> detail_lines;  // power_begin, power_end, result_query_count, ...
};

// MLPerf's official metric of a result's round and scenario, as that round's submission checker takes it.
struct LibraryMetric {
  std::string metric;      // the summary's key: "Early stopping 90th percentile estimate", "Samples per second"
  double value = 0;        // in `unit`
  std::string unit;        // "s", "1/s", "streams"
  std::string statistic;   // "p90 early-stopping estimate", "p90", "streams", ...
  std::string definition;  // the round's definition, in words
  std::optional<double> differs_by;  // plain percentile: (official - plain) / plain
};

// MLPerf's power metric as the round's checker computes it: "W" (Offline), "J/query" (v1.1 SingleStream),
// "mJ/query" (v2.0 on SingleStream, MultiStream).
struct LibraryPowerMetric {
  double value = 0;
  std::string unit, definition, checker;
};

struct LibraryResult {
  std::string id;
  std::string kind;      // "mlperf-inference", "clpeak", "hpl", "tensorrt-timing"
  std::string computer;  // LibraryComputer::id
  // Inference results (mlperf-inference, tensorrt-timing).
  std::string network, scenario;  // "resnet50", "SingleStream"
  std::optional<double> latency_s, throughput_per_s;
  std::string latency_statistic, throughput_statistic;  // "p90", "samples per second", ...
  // Peaks (clpeak, hpl): what was measured, its value and unit ("FLOP/s", "B/s").
  std::string device, measure, variant, unit;
  std::optional<double> value;
  std::string precision;  // "int8", "fp32", "fp64", "not stated", "not applicable"
  std::optional<double> mean_power_w, energy_per_sample_j;
  std::string power_measurement;
  std::string power_kind;        // "AC wall", "DC supply", "module rail", "wall (not stated whether AC or DC)", ""
  std::string energy_statistic;  // "MLPerf's power metric / 8 samples per query", "derived: ..."
  std::vector<double> power_samples_w;  // the power log's samples the mean is over (a budget's share above it)
  std::optional<LibraryMetric> official, plain_percentile;  // MLPerf: the round's result, the plain percentile
  std::optional<LibraryPowerMetric> power_metric;
  // Why the result is never ranked ("one run of one image is not a benchmark result: ..."); "" when it may be.
  std::string not_ranked;
  std::string note;  // the source's own words where the result is kept as a note
  // ROS 2 graph benchmarks (ros2-benchmark, robotperf): the node or benchmark, its input, the release it ran on
  // and what the value is ("the maximum of the run", "the latency of the FIRST message only").
  std::string benchmark, input, release, statistic;
  std::string round, date, division, submitter, system, software, validity;
  std::vector<std::pair<std::string, std::string>> conditions;  // power setting, clocks, cooling, ...
  LibrarySource source;
  std::vector<PlausibilityFlag> flags;  // set by check_library_result() on load

  bool is_inference() const { return kind == "mlperf-inference" || kind == "tensorrt-timing"; }
  bool is_graph_benchmark() const { return kind == "ros2-benchmark" || kind == "robotperf"; }
  std::string condition(std::string_view key) const;  // "" when absent
};

struct LibraryComputer {
  std::string id, name;  // a stand-in's name says so: "... [stand-in for the paper's NUC]"
  std::vector<std::string> aliases;
  std::string stand_in;  // which computer it stands in for and why it is not that one; "" for the real thing
};

// A file in the kept folder that no result reads, and why (an empty file, one not at the cited commit).
struct LibraryKeptNote {
  std::string kept, why;
};

struct Library {
  std::string path;
  std::vector<LibraryComputer> computers;
  std::vector<LibraryResult> results;
  std::vector<LibraryKeptNote> kept_not_used;
  const LibraryComputer* computer(std::string_view id_or_alias) const;  // case-insensitive; nullptr when unknown
  const LibraryResult* result(std::string_view id) const;
  std::string computer_name(std::string_view id) const;  // the id itself when unknown
};

// Throws std::runtime_error naming `origin`, the result (index and id) and the field for malformed input, a result
// whose computer is not listed, or an id used twice.
Library parse_library(std::string_view json_text, const std::string& origin);
Library load_library(const std::filesystem::path& path);

// The bundled library (find_resource("library/library.json")), loaded once; `error` says why when it is absent.
struct BundledLibrary {
  Library library;
  std::string error;
};
const BundledLibrary& bundled_library();

// The results a comma-separated list names: computer ids or aliases ("orin,pi5") select all of a computer's
// results, result ids select one. Throws std::invalid_argument naming an unknown word and the known computers.
std::vector<const LibraryResult*> select_library(const Library& lib, std::string_view spec);

// Plausibility of one published result (the same checks as imports: core/analysis/peaks/plausibility.h): a peak
// above the device's vendor peak, a power outside what a robot computer draws or above 10x its platform's TDP, an
// energy per sample that does not agree with the mean power and the throughput, a non-positive latency or rate.
std::vector<PlausibilityFlag> check_library_result(const LibraryResult& r, const Library& lib);

// ROS 2 graph benchmark results compared like with like only: one class per tool, benchmark (node), input, release
// and measure; a result whose release is not stated is never in a class with another.
struct GraphBenchmarkClass {
  // "ros2-benchmark: image_proc::RectifyNode Benchmark, input HD (1280,720), ros2_benchmark config 0.30.0, ..."
  std::string title;
  std::vector<const LibraryResult*> rows;  // highest value first for rates, lowest first for latency and CPU use
};
std::vector<GraphBenchmarkClass> graph_benchmark_classes(const std::vector<const LibraryResult*>& results);

// "p90 early-stopping estimate 1.638 ms (plain p90 1.638 ms, -0.01 %); 676.4 /s (...); 14.8 W AC wall; power
// metric 22.19 mJ/query" / "230.95 GFLOPS fp32"; a result kept as a note starts "not ranked: ...".
std::string library_result_summary(const LibraryResult& r);

// The official metric in its unit as a text: "1.638 ms", "3463 /s", "102 streams".
std::string official_text(const LibraryMetric& m);

// A ROS 2 graph benchmark's value in its unit: "5.93 ms", "185.25 1/s", "9.2 %" (CPU use never gets an SI prefix);
// "–" when the result has none.
std::string graph_value_text(const LibraryResult& r);

}  // namespace bs
