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
  std::string kept;  // the copy under resources/library/, relative to it
  std::string licence;
  std::vector<std::pair<std::string, long long>> lines;  // value -> line in the kept file
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
  std::string round, date, division, submitter, system, software, validity;
  std::vector<std::pair<std::string, std::string>> conditions;  // power setting, clocks, cooling, ...
  LibrarySource source;
  std::vector<PlausibilityFlag> flags;  // set by check_library_result() on load

  bool is_inference() const { return kind == "mlperf-inference" || kind == "tensorrt-timing"; }
  std::string condition(std::string_view key) const;  // "" when absent
};

struct LibraryComputer {
  std::string id, name;
  std::vector<std::string> aliases;
};

struct Library {
  std::string path;
  std::vector<LibraryComputer> computers;
  std::vector<LibraryResult> results;
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

// "p90 latency 1.64 ms; 676 /s; 14.8 W (external meter ...); 22.2 mJ per sample" / "230.95 GFLOPS fp32".
std::string library_result_summary(const LibraryResult& r);

}  // namespace bs
