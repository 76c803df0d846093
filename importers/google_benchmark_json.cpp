// SPDX-License-Identifier: GPL-3.0-or-later
#include "google_benchmark_json.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <map>

#include "json_access.h"

namespace bs {
namespace {

using json_access::child;
using json_access::json;
using json_access::Reader;

// Keys of a benchmark row that are bookkeeping, not user counters.
constexpr std::array<std::string_view, 20> kReservedKeys = {
    "name",       "family_index", "per_family_instance_index", "run_name",        "run_type",
    "repetitions", "repetition_index", "threads",              "iterations",      "real_time",
    "cpu_time",   "time_unit",    "aggregate_name",            "aggregate_unit",  "error_occurred",
    "error_message", "label",     "big_o",                     "cpu_coefficient", "real_coefficient"};

bool is_reserved(std::string_view key) {
  return key == "rms" || std::find(kReservedKeys.begin(), kReservedKeys.end(), key) != kReservedKeys.end();
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// Google Benchmark stores counters already finalised (rates divided by time), so only the unit is inferred.
std::string counter_unit(const std::string& name) {
  const std::string n = lower(name);
  if (n == "bytes_per_second") return "B/s";
  if (n == "items_per_second") return "1/s";
  if (n.find("flop") != std::string::npos) return "FLOP/s";
  return "";
}

double time_scale(const Reader& r, const std::string& unit, const std::string& at) {
  if (unit == "ns") return 1e-9;
  if (unit == "us") return 1e-6;
  if (unit == "ms") return 1e-3;
  if (unit == "s") return 1.0;
  r.fail(ImportErrorCategory::InvalidValue, at, "unknown time_unit '" + unit + "' (expected ns, us, ms or s)");
}

class MeasurementTable {
 public:
  Measurement& at(const std::string& name, const std::string& metric, const std::string& unit) {
    const auto key = std::make_pair(name, metric);
    auto it = index_.find(key);
    if (it == index_.end()) {
      it = index_.emplace(key, list_.size()).first;
      list_.push_back(Measurement{name, metric, unit, {}, {}});
    }
    return list_[it->second];
  }
  std::vector<Measurement> take() { return std::move(list_); }

 private:
  std::map<std::pair<std::string, std::string>, std::size_t> index_;
  std::vector<Measurement> list_;
};

}  // namespace

int GoogleBenchmarkJsonImporter::sniff(std::string_view head, std::string_view) const {
  const bool benchmarks = head.find("\"benchmarks\"") != std::string_view::npos;
  const bool context = head.find("\"context\"") != std::string_view::npos;
  if (benchmarks && context) return 90;
  if (context && (head.find("\"num_cpus\"") != std::string_view::npos ||
                  head.find("\"library_build_type\"") != std::string_view::npos))
    return 80;
  return 0;
}

ImportBatch GoogleBenchmarkJsonImporter::parse(const std::string& path, const ImportLimits& limits,
                                               const CancelToken& cancel) const {
  const std::string text = read_whole_file(path, limits.max_json_bytes);
  cancel.throw_if_cancelled();
  return parse_google_benchmark_json(text, path, limits);
}

ImportBatch parse_google_benchmark_json(std::string_view text, const std::string& file, const ImportLimits& limits) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  const json doc = json_access::parse(text, file, limits.max_json_depth);
  const Reader r(file);
  r.require_object(doc, "");
  const json& context = r.require_object(r.require(doc, "", "context"), "/context");
  const json& rows = r.require_array(r.require(doc, "", "benchmarks"), "/benchmarks");

  ResultSet set;
  set.platform = r.optional_string(context, "/context", "host_name", "unknown host");
  set.device = "CPU";
  const auto cpus = r.optional_number(context, "/context", "num_cpus");
  const auto mhz = r.optional_number(context, "/context", "mhz_per_cpu");
  if (cpus && mhz)
    set.device += " (" + std::to_string(static_cast<long long>(*cpus)) + " x " +
                  std::to_string(static_cast<long long>(*mhz)) + " MHz)";
  set.device_kind = DeviceKind::Cpu;
  set.backend = "Google Benchmark";
  set.source_format = "google-benchmark-json";
  set.provenance.origin = DataOrigin::Measured;
  set.provenance.host = set.platform;
  set.provenance.date = r.optional_string(context, "/context", "date");
  set.provenance.tool = "google-benchmark";
  if (const json* v = r.optional(context, "library_version"); v && v->is_string())
    set.provenance.tool += " " + v->get<std::string>();
  set.provenance.note = "executable: " + r.optional_string(context, "/context", "executable", "unknown") +
                        ", build type: " + r.optional_string(context, "/context", "library_build_type", "unknown");
  set.provenance.source_file = file;

  ImportBatch batch;
  MeasurementTable table;
  std::size_t values = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string at = child(std::string("/benchmarks"), i);
    const json& row = r.require_object(rows[i], at);
    const std::string name = r.require_string(row, at, "name");
    const std::string run_name = r.optional_string(row, at, "run_name", name);
    if (const json* err = r.optional(row, "error_occurred"); err && err->is_boolean() && err->get<bool>()) {
      batch.warnings.push_back(file + ": " + at + ": benchmark '" + name + "' reported an error (" +
                               r.optional_string(row, at, "error_message", "no message") + "); row skipped");
      continue;
    }
    const std::string run_type = r.optional_string(row, at, "run_type", "iteration");
    const std::string aggregate = r.optional_string(row, at, "aggregate_name");
    if (run_type == "aggregate" && aggregate != "mean" && aggregate != "median" && aggregate != "stddev" &&
        aggregate != "cv") {
      continue;  // BigO / RMS complexity rows describe a fit, not a measurement
    }
    const std::string unit_at = child(at, "time_unit");
    const double scale = time_scale(r, r.optional_string(row, at, "time_unit", "ns"), unit_at);
    // cv rows are ratios (aggregate_unit "percentage"), so their times carry no time unit.
    const bool ratio = r.optional_string(row, at, "aggregate_unit") == "percentage";

    auto record = [&](const std::string& metric, const std::string& unit, double value, double to_si) {
      Measurement& m = table.at(run_name, metric, unit);
      if (run_type == "aggregate") {
        m.reported_aggregates.emplace_back(aggregate, ratio ? value : value * to_si);
      } else {
        if (++values > limits.max_samples)
          r.fail(ImportErrorCategory::TooLarge, at, "more than " + std::to_string(limits.max_samples) + " values");
        m.values.push_back(value * to_si);
      }
    };
    record("real_time", "s", r.require_number(row, at, "real_time"), scale);
    record("cpu_time", "s", r.require_number(row, at, "cpu_time"), scale);
    for (const auto& [key, value] : row.items()) {
      if (is_reserved(key) || !value.is_number()) continue;
      record(key, counter_unit(key), r.number(value, child(at, key)), 1.0);
    }
  }
  set.measurements = table.take();
  if (set.measurements.empty())
    r.fail(ImportErrorCategory::InvalidValue, "/benchmarks", "the file holds no benchmark results");
  batch.result_sets.push_back(std::move(set));
  return batch;
}

}  // namespace bs
