// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/library/library.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "analysis/peaks/device_table.h"
#include "analysis/stats/units.h"
#include "util/resources.h"
#include "util/text.h"

namespace bs {
namespace {

using json = nlohmann::json;

class Fields {
 public:
  Fields(const json& j, std::string where) : j_(j), where_(std::move(where)) {}
  [[noreturn]] void fail(const std::string& field, const std::string& why) const {
    throw std::runtime_error(where_ + ": " + field + ": " + why);
  }
  std::string text(const char* key, bool required = false) const {
    const auto it = j_.find(key);
    if (it == j_.end() || it->is_null()) {
      if (required) fail(key, "missing");
      return {};
    }
    if (!it->is_string()) fail(key, "not a string");
    return it->get<std::string>();
  }
  std::optional<double> number(const char* key) const {
    const auto it = j_.find(key);
    if (it == j_.end() || it->is_null()) return std::nullopt;
    if (!it->is_number()) fail(key, "not a number");
    const double v = it->get<double>();
    if (!std::isfinite(v)) fail(key, "not finite");
    return v;
  }

 private:
  const json& j_;
  std::string where_;
};

std::vector<std::pair<std::string, std::string>> string_pairs(const json& j, const Fields& f, const char* key) {
  std::vector<std::pair<std::string, std::string>> out;
  const auto it = j.find(key);
  if (it == j.end()) return out;
  if (!it->is_object()) f.fail(key, "not an object");
  for (const auto& [k, v] : it->items()) {
    if (!v.is_string()) f.fail(std::string(key) + "/" + k, "not a string");
    out.emplace_back(k, v.get<std::string>());
  }
  return out;
}

LibrarySource source_of(const json& j, const Fields& f) {
  LibrarySource s;
  const auto it = j.find("source");
  if (it == j.end() || !it->is_object()) f.fail("source", "missing: every published result names its source");
  const Fields sf(*it, "source");
  s.url = sf.text("url");
  if (s.url.empty()) f.fail("source/url", "missing");
  s.repository = sf.text("repository");
  s.commit = sf.text("commit");
  s.path = sf.text("path");
  s.kept = sf.text("kept");
  s.licence = sf.text("licence");
  for (const auto& [key, out] : {std::pair{"lines", &s.lines}, std::pair{"detail_lines", &s.detail_lines}})
    if (const auto l = it->find(key); l != it->end() && l->is_object())
      for (const auto& [k, v] : l->items())
        if (v.is_number_integer()) out->emplace_back(k, v.get<long long>());
  s.system = sf.text("system");
  s.precision_from = sf.text("precision_from");
  s.precision_rule = sf.text("precision_rule");
  s.detail = sf.text("detail");
  s.power_from = sf.text("power_from");
  return s;
}

std::optional<LibraryMetric> metric_of(const json& j, const Fields& f, const char* key) {
  const auto it = j.find(key);
  if (it == j.end() || it->is_null()) return std::nullopt;
  if (!it->is_object()) f.fail(key, "not an object");
  const Fields mf(*it, key);
  LibraryMetric m;
  m.metric = mf.text("metric", true);
  const auto v = mf.number("value");
  if (!v) f.fail(std::string(key) + "/value", "missing");
  m.value = *v;
  m.unit = mf.text("unit", true);
  m.statistic = mf.text("statistic");
  m.definition = mf.text("definition");
  m.differs_by = mf.number("differs_by");
  return m;
}

std::optional<LibraryPowerMetric> power_metric_of(const json& j, const Fields& f) {
  const auto it = j.find("power_metric");
  if (it == j.end() || it->is_null()) return std::nullopt;
  if (!it->is_object()) f.fail("power_metric", "not an object");
  const Fields pf(*it, "power_metric");
  LibraryPowerMetric p;
  const auto v = pf.number("value");
  if (!v) f.fail("power_metric/value", "missing");
  p.value = *v;
  p.unit = pf.text("unit", true);
  p.definition = pf.text("definition");
  p.checker = pf.text("checker");
  return p;
}

// Flags the builder set by a rule (a PoCL FP16 peak at the FP32 rate), kept beside the load-time checks.
std::vector<PlausibilityFlag> source_flags(const json& j, const Fields& f) {
  std::vector<PlausibilityFlag> out;
  const auto it = j.find("flags");
  if (it == j.end()) return out;
  if (!it->is_array()) f.fail("flags", "not an array");
  for (const json& x : *it) {
    if (!x.is_object() || !x.contains("code") || !x["code"].is_string() || !x.contains("reason") ||
        !x["reason"].is_string())
      f.fail("flags", "each flag needs a code and a reason");
    out.push_back({x["code"].get<std::string>(), x["reason"].get<std::string>()});
  }
  return out;
}

std::string fmt(double v, int prec = 3) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*g", prec, v);
  return buf;
}

}  // namespace

std::string LibraryResult::condition(std::string_view key) const {
  for (const auto& [k, v] : conditions)
    if (k == key) return v;
  return {};
}

const LibraryComputer* Library::computer(std::string_view id_or_alias) const {
  const std::string w = lower(id_or_alias);
  for (const LibraryComputer& c : computers) {
    if (lower(c.id) == w) return &c;
    for (const std::string& a : c.aliases)
      if (lower(a) == w) return &c;
  }
  return nullptr;
}

const LibraryResult* Library::result(std::string_view id) const {
  for (const LibraryResult& r : results)
    if (r.id == id) return &r;
  return nullptr;
}

std::string Library::computer_name(std::string_view id) const {
  const LibraryComputer* c = computer(id);
  return c ? c->name : std::string(id);
}

Library parse_library(std::string_view json_text, const std::string& origin) {
  const json doc = json::parse(json_text, nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) throw std::runtime_error(origin + ": not a JSON object");
  if (doc.value("format", "") != "benchscope-library")
    throw std::runtime_error(origin + ": format is not \"benchscope-library\"");
  if (doc.value("version", 0) != 1) throw std::runtime_error(origin + ": version is not 1");
  Library lib;
  lib.path = origin;
  const auto comps = doc.find("computers");
  if (comps == doc.end() || !comps->is_array()) throw std::runtime_error(origin + ": computers: missing");
  for (std::size_t i = 0; i < comps->size(); ++i) {
    const Fields f((*comps)[i], origin + ": computers[" + std::to_string(i) + "]");
    LibraryComputer c{f.text("id", true), f.text("name", true), {}, f.text("stand_in")};
    if (const auto a = (*comps)[i].find("aliases"); a != (*comps)[i].end() && a->is_array())
      for (const auto& v : *a)
        if (v.is_string()) c.aliases.push_back(v.get<std::string>());
    lib.computers.push_back(std::move(c));
  }
  const auto results = doc.find("results");
  if (results == doc.end() || !results->is_array()) throw std::runtime_error(origin + ": results: missing");
  for (std::size_t i = 0; i < results->size(); ++i) {
    const json& j = (*results)[i];
    if (!j.is_object()) throw std::runtime_error(origin + ": results[" + std::to_string(i) + "]: not an object");
    const Fields f(j, origin + ": results[" + std::to_string(i) + "] (" + j.value("id", std::string("?")) + ")");
    LibraryResult r;
    r.id = f.text("id", true);
    r.kind = f.text("kind", true);
    r.computer = f.text("computer", true);
    if (!lib.computer(r.computer)) f.fail("computer", "'" + r.computer + "' is not in computers");
    if (lib.result(r.id)) f.fail("id", "used twice");
    if (f.text("origin") != "published") f.fail("origin", "a library result is \"published\"");
    r.network = f.text("network");
    r.scenario = f.text("scenario");
    r.latency_s = f.number("latency_s");
    r.throughput_per_s = f.number("throughput_per_s");
    r.latency_statistic = f.text("latency_statistic");
    r.throughput_statistic = f.text("throughput_statistic");
    r.device = f.text("device");
    r.measure = f.text("measure");
    r.variant = f.text("variant");
    r.unit = f.text("unit");
    r.value = f.number("value");
    r.precision = f.text("precision");
    r.mean_power_w = f.number("mean_power_w");
    r.energy_per_sample_j = f.number("energy_per_sample_j");
    r.power_measurement = f.text("power_measurement");
    r.power_kind = f.text("power_kind");
    r.energy_statistic = f.text("energy_statistic");
    if (const auto ps = j.find("power_samples_w"); ps != j.end()) {
      if (!ps->is_array()) f.fail("power_samples_w", "not an array");
      for (const json& w : *ps) {
        if (!w.is_number() || !std::isfinite(w.get<double>())) f.fail("power_samples_w", "not all numbers");
        r.power_samples_w.push_back(w.get<double>());
      }
    }
    r.official = metric_of(j, f, "official");
    r.plain_percentile = metric_of(j, f, "plain_percentile");
    r.power_metric = power_metric_of(j, f);
    r.not_ranked = f.text("not_ranked");
    r.benchmark = f.text("benchmark");
    r.input = f.text("input");
    r.release = f.text("release");
    r.statistic = f.text("statistic");
    r.note = f.text("note");
    r.round = f.text("round");
    r.date = f.text("date");
    r.division = f.text("division");
    r.submitter = f.text("submitter");
    r.system = f.text("system");
    r.software = f.text("software");
    r.validity = f.text("validity");
    r.conditions = string_pairs(j, f, "conditions");
    r.source = source_of(j, f);
    if (r.is_inference() && (r.network.empty() || r.scenario.empty() || !r.throughput_per_s))
      f.fail("network/scenario/throughput_per_s", "an inference result needs all three");
    if (!r.is_inference() && (!r.value || r.unit.empty())) f.fail("value/unit", "a peak needs both");
    if (r.kind == "mlperf-inference" && !r.official)
      f.fail("official", "an MLPerf result names its round's official metric");
    r.flags = source_flags(j, f);
    lib.results.push_back(std::move(r));
  }
  if (const auto k = doc.find("kept_not_used"); k != doc.end() && k->is_array())
    for (const json& x : *k)
      if (x.is_object()) lib.kept_not_used.push_back({x.value("kept", std::string()), x.value("why", std::string())});
  for (LibraryResult& r : lib.results) merge_flags(r.flags, check_library_result(r, lib));
  return lib;
}

Library load_library(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot open");
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return parse_library(text, path.string());
}

const BundledLibrary& bundled_library() {
  static const BundledLibrary lib =
      load_bundled(&BundledLibrary::library, [] { return load_library(find_resource("library/library.json")); });
  return lib;
}

std::vector<const LibraryResult*> select_library(const Library& lib, std::string_view spec) {
  std::vector<const LibraryResult*> out;
  const auto add = [&](const LibraryResult* r) {
    if (std::find(out.begin(), out.end(), r) == out.end()) out.push_back(r);
  };
  std::size_t at = 0;
  while (at <= spec.size()) {
    const std::size_t comma = spec.find(',', at);
    std::string_view word = spec.substr(at, comma == std::string_view::npos ? std::string_view::npos : comma - at);
    while (!word.empty() && word.front() == ' ') word.remove_prefix(1);
    while (!word.empty() && word.back() == ' ') word.remove_suffix(1);
    if (!word.empty()) {
      if (const LibraryComputer* c = lib.computer(word)) {
        for (const LibraryResult& r : lib.results)
          if (r.computer == c->id) add(&r);
      } else if (const LibraryResult* r = lib.result(word)) {
        add(r);
      } else {
        std::string known;
        for (const LibraryComputer& k : lib.computers)
          known += (known.empty() ? "" : ", ") + k.id + (k.aliases.empty() ? "" : " (" + k.aliases.front() + ")");
        throw std::invalid_argument("'" + std::string(word) + "' is neither a library computer nor a result id; " +
                                    "computers: " + known);
      }
    }
    if (comma == std::string_view::npos) break;
    at = comma + 1;
  }
  return out;
}

std::vector<PlausibilityFlag> check_library_result(const LibraryResult& r, const Library& lib) {
  std::vector<PlausibilityFlag> flags;
  const BundledDeviceTable& table = bundled_device_table();
  const std::string computer = lib.computer_name(r.computer);
  // A peak against the device's vendor FP32 peak: an FP32 figure as imports are checked; an FP64 (HPL) figure can
  // never exceed the FP32 peak on these devices; FP16 runs at most twice the FP32 rate (packed half2).
  if (r.value && r.unit == "FLOP/s") {
    const DeviceKind kind = lower(r.device).find("cpu") != std::string::npos   ? DeviceKind::Cpu
                            : lower(r.device).find("gpu") != std::string::npos ? DeviceKind::Gpu
                                                                               : DeviceKind::Other;
    const DeviceSpec* spec = match_device(table.table, computer, kind, computer);
    if (!spec) spec = match_device(table.table, r.device, kind, computer);
    const double factor = r.precision == "fp16" ? 2.0 : 1.0;
    if (r.precision == "fp32" || r.precision == "fp64" || r.precision == "fp16")
      merge_flags(flags, check_flops(*r.value / factor, spec));
  }
  for (const auto& [what, v] : {std::pair{"latency", r.latency_s}, std::pair{"throughput", r.throughput_per_s},
                                std::pair{"mean power", r.mean_power_w}, std::pair{"energy", r.energy_per_sample_j},
                                std::pair{"value", r.value}})
    if (v && *v <= 0)
      merge_flags(flags, {{flag_code::kNegativeValue, std::string(what) + " " + fmt(*v) + " is not positive"}});
  if (r.mean_power_w) {
    if (*r.mean_power_w > kMaxPlausiblePowerW)
      merge_flags(flags, {{flag_code::kImplausibleMagnitude,
                           "mean power " + fmt(*r.mean_power_w) + " W is more than a robot computer draws"}});
    if (const auto tdp = platform_tdp_w(table.table, computer); tdp && *r.mean_power_w > kPlatformTdpFactor * *tdp)
      merge_flags(flags, {{flag_code::kAbovePlatformPower, "mean power " + fmt(*r.mean_power_w) + " W is above " +
                                                               fmt(kPlatformTdpFactor) + "x the platform's TDP (" +
                                                               fmt(*tdp) + " W)"}});
  }
  // Energy per sample x samples per second is the mean power: within a factor of 2 (the power window and the
  // performance run are not the same seconds), else one of the three numbers is off.
  if (r.mean_power_w && r.energy_per_sample_j && r.throughput_per_s && r.scenario != "MultiStream") {
    const double implied = *r.energy_per_sample_j * *r.throughput_per_s;
    if (implied > 2 * *r.mean_power_w || implied < 0.5 * *r.mean_power_w)
      merge_flags(flags, {{"energy_power_mismatch", "energy per sample x throughput = " + fmt(implied) +
                                                        " W, but the mean power is " + fmt(*r.mean_power_w) + " W"}});
  }
  return flags;
}

std::vector<GraphBenchmarkClass> graph_benchmark_classes(const std::vector<const LibraryResult*>& results) {
  std::vector<GraphBenchmarkClass> out;
  for (const LibraryResult* r : results) {
    if (!r || !r->is_graph_benchmark()) continue;
    const bool unstated = r->release.empty() || r->release.find("not stated") != std::string::npos;
    std::string title = r->kind + ": " + r->benchmark + ", input " + r->input + ", " + r->release + ", " + r->measure;
    if (unstated) title += " (" + r->id + ": release not stated, compared with nothing)";
    auto it = std::find_if(out.begin(), out.end(), [&](const GraphBenchmarkClass& c) { return c.title == title; });
    if (it == out.end()) it = out.insert(out.end(), GraphBenchmarkClass{title, {}});
    it->rows.push_back(r);
  }
  for (GraphBenchmarkClass& c : out)
    std::stable_sort(c.rows.begin(), c.rows.end(), [](const LibraryResult* a, const LibraryResult* b) {
      const bool lower_better = a->unit == "s" || a->unit == "%" || a->unit == "W";
      return lower_better ? a->value.value_or(0) < b->value.value_or(0) : a->value.value_or(0) > b->value.value_or(0);
    });
  return out;
}

std::string official_text(const LibraryMetric& m) {
  if (m.unit == "s") return format_si(m.value, "s", 2);
  if (m.unit == "1/s") return fmt(m.value, 5) + " /s";
  return fmt(m.value, 4) + " " + m.unit;
}

std::string graph_value_text(const LibraryResult& r) {
  if (!r.value) return "–";
  return r.unit == "%" ? fmt(*r.value, 4) + " %" : format_si(*r.value, r.unit, 2);
}

std::string library_result_summary(const LibraryResult& r) {
  std::string s;
  const auto add = [&](const std::string& part) { s += (s.empty() ? "" : "; ") + part; };
  if (!r.not_ranked.empty()) add("not ranked: " + r.not_ranked);
  if (r.official) {
    std::string o = "official " + r.official->statistic + " " + official_text(*r.official);
    if (r.plain_percentile)
      o += " (plain " + r.plain_percentile->statistic + " " + official_text(*r.plain_percentile) + ", " +
           fmt(*r.plain_percentile->differs_by * 100, 2) + " % below)";
    add(o);
  }
  if (r.is_inference()) {
    if (r.latency_s && !(r.official && r.official->unit == "s"))
      add(r.latency_statistic + " latency " + format_si(*r.latency_s, "s", 2));
    if (r.throughput_per_s) add(fmt(*r.throughput_per_s, 4) + " /s (" + r.throughput_statistic + ")");
  } else if (r.is_graph_benchmark() && r.value) {
    add(r.measure + " " + graph_value_text(r) + " (" + r.statistic + "; " + r.benchmark + ", " + r.input + ", " +
        r.release + ")");
  } else if (r.value) {
    add(format_si(*r.value, r.unit == "FLOP/s" ? "FLOPS" : r.unit, 2) + " " + r.precision + " (" + r.measure + ")");
  }
  if (r.mean_power_w)
    add(fmt(*r.mean_power_w) + " W mean" + (r.power_kind.empty() ? "" : ", " + r.power_kind) +
        (r.power_samples_w.empty() ? "" : " (" + std::to_string(r.power_samples_w.size()) + " samples)"));
  if (r.power_metric) add("power metric " + fmt(r.power_metric->value, 4) + " " + r.power_metric->unit);
  if (r.energy_per_sample_j) add(format_si(*r.energy_per_sample_j, "J", 2) + " per sample");
  return s;
}

}  // namespace bs
