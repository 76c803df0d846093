// SPDX-License-Identifier: GPL-3.0-or-later
#include "runs/google_benchmark_json.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <set>

#include "analysis/peaks/foreign_sweeps.h"
#include "common/json_access.h"
#include "common/text_file.h"
#include "util/text.h"

namespace bs {
namespace {

using json_access::child;
using json_access::json;
using json_access::Reader;

// Keys of a benchmark row that are bookkeeping, not user counters.
constexpr std::array<std::string_view, 24> kReservedKeys = {"name",
                                                            "family_index",
                                                            "per_family_instance_index",
                                                            "run_name",
                                                            "run_type",
                                                            "repetitions",
                                                            "repetition_index",
                                                            "threads",
                                                            "iterations",
                                                            "real_time",
                                                            "cpu_time",
                                                            "time_unit",
                                                            "aggregate_name",
                                                            "aggregate_unit",
                                                            "error_occurred",
                                                            "error_message",
                                                            "skipped",
                                                            "skip_message",
                                                            "label",
                                                            "big_o",
                                                            "cpu_coefficient",
                                                            "real_coefficient",
                                                            "rms",
                                                            "memory"};

bool is_reserved(std::string_view key) {
  return std::find(kReservedKeys.begin(), kReservedKeys.end(), key) != kReservedKeys.end();
}

struct CounterUnit {
  std::string unit;
  double scale = 1;  // to SI
};

// Google Benchmark stores counters already finalised (rates divided by time), so only the unit is inferred from
// the name. A FLOP counter is a rate when its name says so ("FLOPS", "flops_per_second", "GFLOP/s"); a leading
// G/M/T/K prefix on it ("GFLOPS") is taken as a decimal multiple.
CounterUnit counter_unit(const std::string& name) {
  const std::string n = lower(name);
  if (n == "bytes_per_second") return {"B/s", 1};
  if (n == "items_per_second") return {"1/s", 1};
  const auto flop = n.find("flop");
  if (flop != std::string::npos) {
    const bool rate = n.find("flops") != std::string::npos || n.find("per_second") != std::string::npos ||
                      n.find("/s") != std::string::npos || n.find("_s") == flop + 4;
    if (!rate) return {"", 1};  // a count of operations, not a rate
    double scale = 1;
    if (flop > 0 && (flop == 1 || !std::isalnum(static_cast<unsigned char>(n[flop - 2])))) {
      switch (n[flop - 1]) {
        case 'k':
          scale = 1e3;
          break;
        case 'm':
          scale = 1e6;
          break;
        case 'g':
          scale = 1e9;
          break;
        case 't':
          scale = 1e12;
          break;
        case 'p':
          scale = 1e15;
          break;
        default:
          break;
      }
    }
    return {"FLOP/s", scale};
  }
  return {"", 1};
}

double time_scale(const Reader& r, const std::string& unit, const std::string& at) {
  if (unit == "ns") return 1e-9;
  if (unit == "us") return 1e-6;
  if (unit == "ms") return 1e-3;
  if (unit == "s") return 1.0;
  r.fail(ImportErrorCategory::InvalidValue, at, "unknown time_unit '" + unit + "' (expected ns, us, ms or s)");
}

// Google Benchmark's JSON reporter prints non-finite doubles as bare NaN / Infinity, which is not JSON. Each such
// token outside strings becomes a string of the same length (NaN -> "a"), so byte offsets and therefore error
// locations stay exact, and the row reader reports the field as not finite.
std::size_t quote_non_finite_tokens(std::string& text) {
  std::size_t replaced = 0;
  constexpr std::array<std::string_view, 4> tokens = {"-Infinity", "Infinity", "-NaN", "NaN"};
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '"') {
      for (++i; i < text.size() && text[i] != '"'; ++i)
        if (text[i] == '\\') ++i;
      continue;
    }
    for (std::string_view token : tokens) {
      if (std::string_view(text).substr(i, token.size()) != token) continue;
      text[i] = '"';
      text[i + token.size() - 1] = '"';
      i += token.size() - 1;
      ++replaced;
      break;
    }
  }
  return replaced;
}

// What quote_non_finite_tokens leaves of NaN, -NaN, Infinity and -Infinity once read back as strings.
bool was_non_finite(const std::string& s) { return s == "a" || s == "Na" || s == "nfinit" || s == "Infinit"; }

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

bool flag(const json& row, const char* key) {
  const auto it = row.find(key);
  return it != row.end() && it->is_boolean() && it->get<bool>();
}

// "L1 Data 32 KiB (x2)", as Google Benchmark's console header prints a cache.
std::string cache_text(const json& c) {
  if (!c.is_object()) return {};
  auto str = [&](const char* key) {
    const auto it = c.find(key);
    return it != c.end() && it->is_string() ? it->get<std::string>() : std::string();
  };
  auto num = [&](const char* key) -> std::optional<double> {
    const auto it = c.find(key);
    if (it == c.end() || !it->is_number()) return std::nullopt;
    return it->get<double>();
  };
  std::string out =
      "L" + (num("level") ? std::to_string(std::llround(*num("level"))) : std::string("?")) + " " + str("type");
  if (const auto size = num("size"); size && *size > 0) {
    const double kib = *size / 1024.0;
    out += kib >= 1024 && std::fmod(kib, 1024.0) == 0 ? " " + std::to_string(std::llround(kib / 1024)) + " MiB"
                                                      : " " + std::to_string(std::llround(kib)) + " KiB";
  }
  if (const auto sharing = num("num_sharing"); sharing && *sharing > 1)
    out += " (x" + std::to_string(std::llround(*sharing)) + ")";
  return out;
}

std::string scalar_text(const json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  if (v.is_number_integer()) return v.dump();
  if (v.is_number()) {
    const double d = v.get<double>();
    if (d == std::floor(d) && std::abs(d) < 1e15) return std::to_string(std::llround(d));
    return v.dump();
  }
  return {};
}

ResultSet result_set_from_context(const Reader& r, const json& context, const std::string& file,
                                  const WorkersArgument& workers) {
  ResultSet set;
  set.platform = r.optional_string(context, "/context", "host_name");
  if (set.platform.empty()) set.platform = "unknown host";
  set.device = "CPU";
  const auto cpus = r.optional_number(context, "/context", "num_cpus");
  const auto mhz = r.optional_number(context, "/context", "mhz_per_cpu");
  if (cpus && mhz && *cpus > 0 && *mhz > 0)
    set.device += " (" + std::to_string(std::llround(*cpus)) + " x " + std::to_string(std::llround(*mhz)) + " MHz)";
  set.device_kind = DeviceKind::Cpu;
  set.backend = "Google Benchmark";
  set.source_format = "google-benchmark-json";
  Provenance& p = set.provenance;
  p.origin = DataOrigin::Measured;
  p.host = set.platform == "unknown host" ? std::string() : set.platform;
  p.date = r.optional_string(context, "/context", "date");
  p.tool = "google-benchmark";
  const std::string version = r.optional_string(context, "/context", "library_version");
  if (!version.empty()) p.tool += " " + version;
  const std::string build = r.optional_string(context, "/context", "library_build_type");
  std::string note = "executable: " + r.optional_string(context, "/context", "executable", "unknown") +
                     ", library build type: " + (build.empty() ? std::string("unknown") : build);
  if (const json* scaling = r.optional(context, "cpu_scaling_enabled"); scaling && scaling->is_boolean())
    note += scaling->get<bool>() ? ", CPU frequency scaling was on (timings may be noisy)" : ", CPU scaling off";
  p.note = note;
  p.source_file = file;
  // Everything the context states about the machine, in file order: the library's own keys and custom context
  // (--benchmark_context=key=value, AddCustomContext), which labs use for compiler, clocks, power mode.
  for (const auto& [key, value] : context.items()) {
    if (key == "date") continue;  // already the provenance date
    if (key == "caches" && value.is_array()) {
      std::string caches;
      for (const json& c : value) {
        const std::string text = cache_text(c);
        if (text.empty()) continue;
        caches += (caches.empty() ? "" : ", ") + text;
      }
      if (!caches.empty()) p.settings.emplace_back("caches", caches);
      continue;
    }
    if (key == "load_avg" && value.is_array()) {
      std::string loads;
      for (const json& v : value)
        if (v.is_number()) loads += (loads.empty() ? "" : " ") + scalar_text(v);
      if (!loads.empty()) p.settings.emplace_back(key, loads);  // Windows writes []
      continue;
    }
    const std::string text = scalar_text(value);
    if (!text.empty()) p.settings.emplace_back(key, text);
  }
  p.settings.emplace_back(std::string(kWorkersFromSetting), workers_from_text(workers));
  return set;
}

// The worker argument: the caller's option, else the custom context key.
WorkersArgument workers_argument_of(const Reader& r, const json& context, const ParseOptions& options) {
  if (options.workers_argument) return options.workers_argument;
  const json* v = r.optional(context, "benchscope_workers_argument");
  if (!v) return std::nullopt;
  const std::string at = "/context/benchscope_workers_argument";
  if (v->is_string()) {
    const std::string text = v->get<std::string>();
    if (text == "threads") return std::nullopt;
    if (text.empty() || text.size() > 3 || text.find_first_not_of("0123456789") != std::string::npos)
      r.fail(ImportErrorCategory::InvalidValue, at,
             "'" + text + "' is neither \"threads\" nor an argument index 0-999");
    return std::stoi(text);
  }
  return static_cast<int>(r.integer(*v, at, 0, 999));
}

// Integer fields of a row. NaN / Infinity arrive here as the strings quote_non_finite_tokens made of them.
std::optional<std::int64_t> optional_count(const Reader& r, const json& row, const std::string& at, const char* key,
                                           std::int64_t min) {
  const json* v = r.optional(row, key);
  if (!v) return std::nullopt;
  const std::string field = child(at, key);
  if (v->is_string() && was_non_finite(v->get<std::string>()))
    r.fail(ImportErrorCategory::InvalidValue, field, "is not a finite number (NaN or Infinity)");
  return r.integer(*v, field, min, std::numeric_limits<std::int64_t>::max());
}

// The threads:N segment of a benchmark name, when it has one.
std::optional<std::int64_t> threads_in_name(const std::string& name) {
  const auto point = sweep_point(name, std::nullopt);
  if (!point || point->family == name) return std::nullopt;
  return point->workers;
}

}  // namespace

static int sniff_google_benchmark_json(std::string_view head, std::string_view) {
  const bool benchmarks = head.find("\"benchmarks\"") != std::string_view::npos;
  const bool context = head.find("\"context\"") != std::string_view::npos;
  const bool machine = head.find("\"num_cpus\"") != std::string_view::npos ||
                       head.find("\"library_build_type\"") != std::string_view::npos ||
                       head.find("\"mhz_per_cpu\"") != std::string_view::npos;
  if (benchmarks && context) return 90;
  if (context && machine) return 80;
  if (benchmarks &&
      (head.find("\"run_type\"") != std::string_view::npos || head.find("\"cpu_time\"") != std::string_view::npos))
    return 60;
  return 0;
}

ImportBatch parse_google_benchmark_json(const std::string& original, const std::string& file,
                                        const ParseOptions& options, const ImportLimits& limits,
                                        const CancelToken& cancel) {
  std::string text(original);
  quote_non_finite_tokens(text);
  const json doc = json_access::parse(text, file, limits, &cancel);
  const Reader r(file, text);
  r.require_object(doc, "");
  const json& context = r.require_object(r.require(doc, "", "context"), "/context");
  const json& rows = r.require_array(r.require(doc, "", "benchmarks"), "/benchmarks");

  ImportBatch batch;
  const WorkersArgument workers = workers_argument_of(r, context, options);
  ResultSet set = result_set_from_context(r, context, file, workers);
  // items_per_second counts whatever the benchmark calls an item; it is a FLOP rate only when the file says each
  // item is one floating-point operation (--benchmark_context=benchscope_item=flop, SetItemsProcessed(flops)).
  const std::string item = r.optional_string(context, "/context", "benchscope_item");
  if (!item.empty() && item != "flop")
    r.fail(ImportErrorCategory::InvalidValue, "/context/benchscope_item", "'" + item + "' is not \"flop\"");
  const bool items_are_flop = item == "flop";
  if (r.optional_string(context, "/context", "library_build_type") == "debug")
    batch.warnings.push_back(r.where("/context/library_build_type") +
                             ": ***WARNING*** Library was built as DEBUG. Timings may be affected.");
  MeasurementTable table;
  std::size_t values = 0;
  // Which row first gave each repetition / aggregate of a benchmark, and each benchmark's thread count: the same
  // one twice with different data is refused, since no reading of the file says which is right.
  std::map<std::pair<std::string, std::string>, std::size_t> first_row;
  std::map<std::string, std::pair<std::int64_t, std::size_t>> threads_of;  // run_name -> (threads, row)
  std::set<std::string> iteration_names;                                   // for aggregates of versions < 1.5
  std::set<std::string> unswept_warned;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if ((i & 0x3FF) == 0) cancel.throw_if_cancelled();
    const std::string at = child("/benchmarks", i);
    const json& row = r.require_object(rows[i], at);
    const std::string name = r.require_string(row, at, "name");
    std::string run_name = r.optional_string(row, at, "run_name", name);
    (void)optional_count(r, row, at, "iterations", 0);  // checked only: times are already per iteration
    const auto threads = optional_count(r, row, at, "threads", 1);
    if (flag(row, "error_occurred")) {
      batch.warnings.push_back(r.where(at) + ": benchmark '" + name + "' reported an error (" +
                               r.optional_string(row, at, "error_message", "no message") + "); row skipped");
      continue;
    }
    if (flag(row, "skipped")) {
      batch.warnings.push_back(r.where(at) + ": benchmark '" + name + "' was skipped (" +
                               r.optional_string(row, at, "skip_message", "no message") + ")");
      continue;
    }
    const json* run_type_value = r.optional(row, "run_type");
    std::string run_type = r.optional_string(row, at, "run_type", "iteration");
    if (run_type != "iteration" && run_type != "aggregate")
      r.fail(ImportErrorCategory::InvalidValue, child(at, "run_type"),
             "'" + run_type + "' is neither \"iteration\" nor \"aggregate\"");
    std::string aggregate = r.optional_string(row, at, "aggregate_name");
    // Before version 1.5 aggregates had no run_type: a row "BM_X_mean" after rows named "BM_X" is one.
    if (!run_type_value && !row.contains("run_name")) {
      for (const char* suffix : {"_mean", "_median", "_stddev", "_cv"}) {
        const std::string base =
            name.size() > std::strlen(suffix) ? name.substr(0, name.size() - std::strlen(suffix)) : "";
        if (name.ends_with(suffix) && iteration_names.count(base)) {
          run_type = "aggregate";
          aggregate = suffix + 1;
          run_name = base;
        }
      }
    }
    const bool is_aggregate = run_type == "aggregate";
    if (is_aggregate && aggregate.empty())
      r.fail(ImportErrorCategory::MissingField, child(at, "aggregate_name"), "an aggregate row needs its name");
    // BigO / RMS complexity rows describe a fit over arguments, not a measurement of this run.
    if (is_aggregate && (aggregate == "BigO" || aggregate == "RMS" || row.contains("big_o") || row.contains("rms")))
      continue;
    if (!is_aggregate) iteration_names.insert(run_name);

    if (threads) {
      if (const auto named = threads_in_name(run_name); named && *named != *threads)
        r.fail(ImportErrorCategory::InvalidValue, child(at, "threads"),
               std::to_string(*threads) + " disagrees with the name '" + run_name +
                   "' (threads:" + std::to_string(*named) + ")");
      const auto [it, added] = threads_of.emplace(run_name, std::make_pair(*threads, i));
      if (!added && it->second.first != *threads)
        r.fail(ImportErrorCategory::InvalidValue, child(at, "threads"),
               "benchmark '" + run_name + "' ran with " + std::to_string(it->second.first) + " threads in " +
                   r.where(child("/benchmarks", it->second.second)) + " and with " + std::to_string(*threads) +
                   " here; one benchmark has one thread count");
    }
    // One row per repetition (repetition_index, version >= 1.5) and per aggregate of a benchmark.
    std::string slot;
    if (is_aggregate) {
      slot = "aggregate " + aggregate;
    } else if (const auto rep = optional_count(r, row, at, "repetition_index", 0)) {
      slot = "repetition " + std::to_string(*rep);
    }
    if (!slot.empty()) {
      const auto [it, added] = first_row.emplace(std::make_pair(run_name, slot), i);
      if (!added) {
        const std::string first = r.where(child("/benchmarks", it->second));
        if (rows[it->second] != row)
          r.fail(ImportErrorCategory::InvalidValue, at,
                 "benchmark '" + run_name + "' has its " + slot + " twice with different data (first at " + first +
                     "); the file does not say which is right");
        batch.warnings.push_back(r.where(at) + ": benchmark '" + run_name + "' repeats its " + slot +
                                 " identically (first at " + first + "); the copy is skipped");
        continue;
      }
    }
    const double scale = time_scale(r, r.optional_string(row, at, "time_unit", "ns"), child(at, "time_unit"));
    // cv rows (aggregate_unit "percentage", or named cv in versions before that key) are ratios, not times.
    const bool ratio = r.optional_string(row, at, "aggregate_unit") == "percentage" || aggregate == "cv";
    // How many repetitions an aggregate summarises: its "repetitions" (since 1.5). Older aggregates carry the
    // first repetition's iteration count instead (google/benchmark#586), so their n is the number of repetition
    // rows read, which summarize_measurement() uses when no ("repetitions", n) is recorded.
    const std::optional<std::int64_t> reps = is_aggregate ? optional_count(r, row, at, "repetitions", 1) : std::nullopt;

    auto record = [&](const std::string& metric, const std::string& unit, double value, double to_si) {
      Measurement& m = table.at(run_name, metric, unit);
      if (is_aggregate) {
        m.reported_aggregates.emplace_back(aggregate, ratio ? value : value * to_si);
        const bool has_n = std::any_of(m.reported_aggregates.begin(), m.reported_aggregates.end(),
                                       [](const auto& a) { return a.first == "repetitions"; });
        if (reps && !has_n) m.reported_aggregates.emplace_back("repetitions", static_cast<double>(*reps));
        return;
      }
      if (++values > limits.max_samples)
        r.fail(ImportErrorCategory::TooLarge, at,
               "more than " + std::to_string(limits.max_samples) + " values (the documented limit)");
      m.values.push_back(value * to_si);
    };
    // A time that is not a finite number (NaN from a benchmark that never ran) drops the row, with a warning.
    bool times_ok = true;
    for (const char* key : {"real_time", "cpu_time"}) {
      const json& v = r.require(row, at, key);
      if (v.is_string()) times_ok = false;
    }
    if (!times_ok) {
      batch.warnings.push_back(r.where(at) + ": benchmark '" + name +
                               "' has a time that is not a finite number; "
                               "row skipped");
      continue;
    }
    for (const char* key : {"real_time", "cpu_time"}) {
      const double t = r.require_number(row, at, key);
      if (t < 0 && !(is_aggregate && ratio))
        r.fail(ImportErrorCategory::InvalidValue, child(at, key), "a time must not be negative");
      record(key, "s", t, scale);
    }
    for (const auto& [key, value] : row.items()) {
      if (is_reserved(key) || value.is_boolean() || value.is_null()) continue;
      if (value.is_string()) {
        batch.warnings.push_back(r.where(child(at, key)) + ": counter '" + key + "' of '" + name +
                                 "' is not a finite number (NaN, Infinity or text); left out as missing data");
        continue;
      }
      if (!value.is_number()) continue;  // objects/arrays are not counters in any known version
      CounterUnit unit = counter_unit(key);
      if (key == "items_per_second" && items_are_flop) unit = {"FLOP/s", 1};
      if (unit.unit == "FLOP/s" && workers && !sweep_point(run_name, workers) && unswept_warned.insert(run_name).second)
        batch.warnings.push_back(r.where(at) + ": '" + run_name + "' has no argument " + std::to_string(*workers) +
                                 " that is an integer >= 1, so its FLOPS is no point of a workers sweep (kept as a "
                                 "throughput result)");
      record(key, unit.unit, r.number(value, child(at, key)), unit.scale);
    }
  }
  set.measurements = table.take();
  if (set.measurements.empty())
    r.fail(ImportErrorCategory::InvalidValue, "/benchmarks",
           rows.empty() ? "the file holds no benchmark rows" : "no benchmark row holds a usable result");
  batch.result_sets.push_back(std::move(set));
  return batch;
}

const FileFormat kGoogleBenchmarkJsonFileFormat{
    "google-benchmark-json",     "Google Benchmark JSON",
    sniff_google_benchmark_json, parse_text_file_with<parse_google_benchmark_json>,
    parse_google_benchmark_json, ".json"};

}  // namespace bs
