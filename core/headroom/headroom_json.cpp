// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/headroom_json.h"

#include <cmath>
#include <limits>

#include "model/json_fields.h"
#include "model/provenance_json.h"

namespace bs::headroom {
namespace {

using json = nlohmann::json;
constexpr std::int64_t kMaxNs = std::int64_t{1} << 62;  // far beyond any latency, below overflow of sums

template <class T>
void put(json& j, const char* key, const std::optional<T>& v) {
  j[key] = v ? json(*v) : json(nullptr);
}

json histogram_to_json(const LatencyHistogram& h) {
  json counts = json::array();
  for (std::size_t i = 0; i < h.bins.size(); ++i)
    if (h.bins[i] != 0) counts.push_back({i, h.bins[i]});
  json j = {{"bin_ns", h.bin_ns},
            {"bins", h.bins.size()},
            {"overflows", h.overflows},
            {"cycles", h.cycles},
            {"counts", std::move(counts)}};
  put(j, "min_ns", h.min_ns);
  put(j, "max_ns", h.max_ns);
  return j;
}

json percentile_json(const HistogramPercentile& p) {
  return p.at_least ? json{{"ns", p.ns}, {"at_least", true}} : json(p.ns);
}

// --- reading ------------------------------------------------------------------------------------------------

using Fields = JsonFields<HeadroomJsonError>;

std::int64_t integer(const json& v, const std::string& where, std::int64_t min, std::int64_t max) {
  if (!v.is_number_integer()) Fields::fail(where, "'" + v.dump() + "' is not an integer");
  if (v.is_number_unsigned() && v.get<std::uint64_t>() > static_cast<std::uint64_t>(max))
    Fields::fail(where, v.dump() + " is above " + std::to_string(max));
  const auto x = v.get<std::int64_t>();
  if (x < min || x > max)
    Fields::fail(where, v.dump() + " is outside " + std::to_string(min) + " .. " + std::to_string(max));
  return x;
}

std::int64_t integer(const json& obj, const char* key, const std::string& where, std::int64_t min, std::int64_t max) {
  return integer(Fields::member(obj, key, where), where + "." + key, min, max);
}

std::optional<std::int64_t> optional_integer(const json& obj, const char* key, const std::string& where,
                                             std::int64_t min, std::int64_t max) {
  const auto it = obj.find(key);
  if (it == obj.end() || it->is_null()) return std::nullopt;
  return integer(*it, where + "." + key, min, max);
}

std::optional<double> optional_number(const json& obj, const char* key, const std::string& where, bool non_negative) {
  const auto it = obj.find(key);
  if (it == obj.end() || it->is_null()) return std::nullopt;
  if (!it->is_number()) Fields::fail(where + "." + key, "'" + it->dump() + "' is not a number");
  const double v = it->get<double>();
  if (!std::isfinite(v) || (non_negative && v < 0))
    Fields::fail(where + "." + key, it->dump() + " is not allowed here");
  return v;
}

std::optional<bool> optional_flag(const json& obj, const char* key, const std::string& where) {
  const auto it = obj.find(key);
  if (it == obj.end() || it->is_null()) return std::nullopt;
  if (!it->is_boolean()) Fields::fail(where + "." + key, "is not true, false or null");
  return it->get<bool>();
}

LatencyHistogram histogram_from_json(const json& j, const std::string& where) {
  if (!j.is_object()) Fields::fail(where, "is not an object");
  LatencyHistogram h;
  constexpr auto kMaxCount = std::numeric_limits<std::int64_t>::max();
  h.bin_ns = integer(j, "bin_ns", where, 1, kMaxNs);
  const auto n_bins = integer(j, "bins", where, 0, static_cast<std::int64_t>(kMaxHistogramBins));
  if (n_bins > 0 && h.bin_ns > kMaxNs / n_bins) Fields::fail(where + ".bins", "limit beyond 2^62 ns");
  h.overflows = static_cast<std::uint64_t>(integer(j, "overflows", where, 0, kMaxCount));
  h.cycles = static_cast<std::uint64_t>(integer(j, "cycles", where, 0, kMaxCount));
  h.min_ns = optional_integer(j, "min_ns", where, 0, kMaxNs);
  h.max_ns = optional_integer(j, "max_ns", where, 0, kMaxNs);
  const json& counts = Fields::array(j, "counts", where);
  if (counts.size() > static_cast<std::size_t>(n_bins))
    Fields::fail(where + ".counts", std::to_string(counts.size()) + " entries for " + std::to_string(n_bins) + " bins");
  h.bins.assign(static_cast<std::size_t>(n_bins), 0);
  std::uint64_t total = 0;
  for (std::size_t k = 0; k < counts.size(); ++k) {
    const std::string at = where + ".counts[" + std::to_string(k) + "]";
    if (!counts[k].is_array() || counts[k].size() != 2) Fields::fail(at, "is not a [bin, count] pair");
    const auto bin = static_cast<std::size_t>(integer(counts[k][0], at + "[0]", 0, n_bins - 1));
    const auto count = static_cast<std::uint64_t>(integer(counts[k][1], at + "[1]", 1, kMaxCount));
    if (h.bins[bin] != 0) Fields::fail(at, "bin " + std::to_string(bin) + " given twice");
    if (total > static_cast<std::uint64_t>(kMaxCount) - count) Fields::fail(at, "counts add up beyond 2^63");
    total += count;
    h.bins[bin] = count;
  }
  if (const std::string e = h.bookkeeping_error(); !e.empty()) Fields::fail(where, e);
  return h;
}

ThreadLatency thread_from_json(const json& j, const std::string& where) {
  if (!j.is_object()) Fields::fail(where, "is not an object");
  ThreadLatency t;
  t.index = static_cast<int>(integer(j, "index", where, 0, 1 << 20));
  if (auto cpu = optional_integer(j, "cpu", where, 0, 1 << 20)) t.cpu = static_cast<int>(*cpu);
  t.policy = Fields::text(j, "policy", where);
  if (auto prio = optional_integer(j, "priority", where, 0, 99)) t.priority = static_cast<int>(*prio);
  t.memory_locked = optional_flag(j, "memory_locked", where);
  t.period_ns = integer(j, "period_ns", where, 0, kMaxNs);
  t.computation_ns = integer(j, "computation_ns", where, 0, kMaxNs);
  t.deadline_ns = integer(j, "deadline_ns", where, 0, kMaxNs);
  t.histogram = histogram_from_json(Fields::member(j, "histogram", where), where + ".histogram");
  t.mean_ns = optional_number(j, "mean_ns", where, true);
  t.sd_ns = optional_number(j, "sd_ns", where, true);
  if (const auto it = j.find("misses"); it != j.end() && !it->is_null()) {
    const std::string at = where + ".misses";
    if (!it->is_object()) Fields::fail(at, "is not an object");
    const auto cycles = static_cast<std::int64_t>(std::min<std::uint64_t>(t.histogram.cycles, kMaxNs));
    DeadlineMisses m;
    m.count = static_cast<std::uint64_t>(integer(*it, "count", at, 0, cycles));
    m.longest_run = static_cast<std::uint64_t>(integer(*it, "longest_run", at, 0, static_cast<std::int64_t>(m.count)));
    if (m.count > 0 && m.longest_run == 0) Fields::fail(at, "misses without a run");
    t.misses = m;
  }
  t.max_response_ns = optional_integer(j, "max_response_ns", where, 0, kMaxNs);
  return t;
}

Phase phase_from_json(const json& j, const std::string& where) {
  if (!j.is_object()) Fields::fail(where, "is not an object");
  Phase p;
  p.name = Fields::text(j, "name", where);
  p.load = Fields::word(j, "load", where, load_kind_from_id, "load");
  p.load_detail = Fields::text(j, "load_detail", where);
  p.target_rate = optional_number(j, "target_rate", where, true);
  p.achieved_rate = optional_number(j, "achieved_rate", where, true);
  p.rate_unit = Fields::text(j, "rate_unit", where);
  const std::optional<double> duration = optional_number(j, "duration_s", where, true);
  if (!duration) Fields::fail(where + ".duration_s", "is missing");
  p.duration_s = *duration;
  p.mean_power_w = optional_number(j, "mean_power_w", where, true);
  p.power_sensor = Fields::text(j, "power_sensor", where);
  p.probe_cpu_s_per_s = optional_number(j, "probe_cpu_s_per_s", where, true);
  const json& notes = Fields::array(j, "notes", where);
  for (std::size_t k = 0; k < notes.size(); ++k) {
    if (!notes[k].is_string()) Fields::fail(where + ".notes[" + std::to_string(k) + "]", "is not a string");
    p.notes.push_back(notes[k].get<std::string>());
  }
  const json& threads = Fields::array(j, "threads", where);
  for (std::size_t k = 0; k < threads.size(); ++k)
    p.threads.push_back(thread_from_json(threads[k], where + ".threads[" + std::to_string(k) + "]"));
  return p;
}

}  // namespace

json to_json(const KernelFacts& k) {
  json j = {{"release", k.release},   {"version", k.version},     {"preemption", k.preemption},
            {"isolcpus", k.isolcpus}, {"nohz_full", k.nohz_full}, {"governor", k.governor}};
  put(j, "preempt_rt", k.preempt_rt);
  return j;
}

json to_json(const LatencySummary& s) {
  json j = {{"cycles", s.cycles}};
  if (s.no_distribution) {
    // An imported summary without a histogram: no percentile is known (null, never 0).
    j["no_distribution"] = true;
    for (const char* key : {"p50_ns", "p99_ns", "p99.9_ns", "p99.99_ns"}) j[key] = nullptr;
  } else {
    j["p50_ns"] = percentile_json(s.p50);
    j["p99_ns"] = percentile_json(s.p99);
    j["p99.9_ns"] = percentile_json(s.p999);
    j["p99.99_ns"] = percentile_json(s.p9999);
  }
  put(j, "min_ns", s.min_ns);
  put(j, "max_ns", s.max_ns);
  put(j, "mean_ns", s.mean_ns);
  put(j, "sd_ns", s.sd_ns);
  j["mean_from_bins"] = s.mean_from_bins;
  put(j, "misses", s.misses);
  j["misses_exact"] = s.misses_exact;
  j["miss_percent"] = s.miss_percent();
  put(j, "longest_miss_run", s.longest_miss_run);
  return j;
}

json to_json(const HeadroomMeasurement& m, bool with_summary) {
  json phases = json::array();
  for (const Phase& p : m.phases) {
    json threads = json::array();
    for (const ThreadLatency& t : p.threads) {
      json tj = {{"index", t.index},
                 {"policy", t.policy},
                 {"period_ns", t.period_ns},
                 {"computation_ns", t.computation_ns},
                 {"deadline_ns", t.deadline_ns},
                 {"histogram", histogram_to_json(t.histogram)}};
      put(tj, "cpu", t.cpu);
      put(tj, "priority", t.priority);
      put(tj, "memory_locked", t.memory_locked);
      put(tj, "mean_ns", t.mean_ns);
      put(tj, "sd_ns", t.sd_ns);
      tj["misses"] = t.misses ? json{{"count", t.misses->count}, {"longest_run", t.misses->longest_run}} : json();
      put(tj, "max_response_ns", t.max_response_ns);
      if (with_summary) tj["summary"] = to_json(summarize(t));
      threads.push_back(std::move(tj));
    }
    json pj = {{"name", p.name},           {"load", std::string(to_id(p.load))}, {"load_detail", p.load_detail},
               {"rate_unit", p.rate_unit}, {"duration_s", p.duration_s},         {"power_sensor", p.power_sensor},
               {"notes", p.notes},         {"threads", std::move(threads)}};
    put(pj, "target_rate", p.target_rate);
    put(pj, "achieved_rate", p.achieved_rate);
    put(pj, "mean_power_w", p.mean_power_w);
    put(pj, "probe_cpu_s_per_s", p.probe_cpu_s_per_s);
    phases.push_back(std::move(pj));
  }
  json j = {{"platform", m.platform},
            {"kind", std::string(to_id(m.kind))},
            {"tool", m.tool},
            {"command", m.command},
            {"kernel", to_json(m.kernel)},
            {"phases", std::move(phases)},
            {"provenance", provenance_to_json(m.provenance, true)}};
  if (with_summary) {
    j["realtime"] = m.realtime();
    j["flags"] = flags(m);
  }
  return j;
}

HeadroomMeasurement measurement_from_json(const json& j) {
  const std::string where = "headroom";
  if (!j.is_object()) Fields::fail(where, "is not an object");
  HeadroomMeasurement m;
  m.platform = Fields::text(j, "platform", where);
  m.kind = Fields::word(j, "kind", where, latency_kind_from_id, "latency kind", " (known: wakeup, loop, message)");
  m.tool = Fields::text(j, "tool", where);
  m.command = Fields::text(j, "command", where);
  const json& kernel = Fields::member(j, "kernel", where);
  if (!kernel.is_object()) Fields::fail(where + ".kernel", "is not an object");
  const std::string kw = where + ".kernel";
  m.kernel.release = Fields::text(kernel, "release", kw);
  m.kernel.version = Fields::text(kernel, "version", kw);
  m.kernel.preemption = Fields::text(kernel, "preemption", kw);
  m.kernel.isolcpus = Fields::text(kernel, "isolcpus", kw);
  m.kernel.nohz_full = Fields::text(kernel, "nohz_full", kw);
  m.kernel.governor = Fields::text(kernel, "governor", kw);
  m.kernel.preempt_rt = optional_flag(kernel, "preempt_rt", kw);
  const json& phases = Fields::array(j, "phases", where);
  for (std::size_t i = 0; i < phases.size(); ++i)
    m.phases.push_back(phase_from_json(phases[i], where + ".phases[" + std::to_string(i) + "]"));
  if (const auto it = j.find("provenance"); it != j.end()) {
    if (!it->is_object()) Fields::fail(where + ".provenance", "is not an object");
    m.provenance = provenance_from_json(*it);
  }
  return m;
}

}  // namespace bs::headroom
