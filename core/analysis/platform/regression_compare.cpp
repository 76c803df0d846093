// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/platform/regression_compare.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "analysis/peaks/flops.h"
#include "analysis/peaks/foreign_sweeps.h"
#include "util/enum_words.h"

namespace bs {
namespace {

std::vector<double> flops_of(const FlopsRun& run, const WorkerSample& s) {
  std::vector<double> out;
  out.reserve(s.seconds.size());
  for (double t : s.seconds) out.push_back(rotation_flops(run.dims, run.iterations, s.workers, t));
  return out;
}

const WorkerSample* at_workers(const FlopsRun& run, std::int64_t workers) {
  for (const auto& s : run.samples)
    if (s.workers == workers) return &s;
  return nullptr;
}

std::string run_key(const FlopsRun& r) {
  return r.platform + " | " + r.device + " | " + r.backend + " | " + r.variant + " | D=" + std::to_string(r.dims) +
         " | N=" + std::to_string(r.iterations);
}

std::string set_key(const ResultSet& s, const Measurement& m) {
  return s.platform + " | " + s.device + " | " + s.backend + " | " + m.name;
}

MeasureComparison judge(std::string key, std::string measure, std::string unit, std::span<const double> a,
                        std::span<const double> b, const CompareOptions& o) {
  MeasureComparison c;
  c.key = std::move(key);
  c.measure = std::move(measure);
  c.higher_is_better = higher_is_better_for_unit(unit);
  c.unit = std::move(unit);
  c.a = summarize(a);
  c.b = summarize(b);
  c.change = c.a.mean != 0 ? (c.b.mean - c.a.mean) / std::fabs(c.a.mean) : 0.0;
  c.test = mann_whitney_u(a, b);
  if (!(std::fabs(c.change) > o.threshold)) {
    c.verdict = CompareVerdict::Unchanged;
  } else if (!(c.test.p_value < o.alpha)) {
    c.verdict = CompareVerdict::NotSignificant;
  } else if (!c.higher_is_better) {
    c.verdict = CompareVerdict::Changed;
  } else {
    const bool better = (c.change > 0) == *c.higher_is_better;
    c.verdict = better ? CompareVerdict::Improvement : CompareVerdict::Regression;
  }
  return c;
}

MeasureComparison only_in(std::string key, std::string measure, std::string unit, std::span<const double> v,
                          bool in_a) {
  MeasureComparison c;
  c.key = std::move(key);
  c.measure = std::move(measure);
  c.higher_is_better = higher_is_better_for_unit(unit);
  c.unit = std::move(unit);
  (in_a ? c.a : c.b) = summarize(v);
  c.verdict = in_a ? CompareVerdict::OnlyInA : CompareVerdict::OnlyInB;
  return c;
}

void compare_runs(std::span<const FlopsRun> ra, std::span<const FlopsRun> rb, const CompareOptions& o,
                  std::vector<MeasureComparison>& out) {
  // Sweeps derived from another tool's results hold no repetitions here; their result sets are compared instead.
  std::map<std::string, const FlopsRun*> by_key_b;
  for (const auto& r : rb)
    if (!is_foreign_sweep(r)) by_key_b.emplace(run_key(r), &r);
  std::map<std::string, bool> matched;
  for (const auto& r : ra) {
    if (is_foreign_sweep(r)) continue;
    const std::string key = run_key(r);
    const auto peak = find_peak(r);
    if (!peak) continue;
    const auto it = by_key_b.find(key);
    if (it == by_key_b.end()) {
      out.push_back(only_in(key + " | W=" + std::to_string(peak->workers), "FLOPS", "FLOP/s",
                            flops_of(r, *at_workers(r, peak->workers)), true));
      continue;
    }
    matched[key] = true;
    const FlopsRun& other = *it->second;
    for (const auto& s : r.samples) {
      if (!o.every_point && s.workers != peak->workers) continue;
      const WorkerSample* t = at_workers(other, s.workers);
      if (!t) continue;
      out.push_back(
          judge(key + " | W=" + std::to_string(s.workers), "FLOPS", "FLOP/s", flops_of(r, s), flops_of(other, *t), o));
    }
  }
  for (const auto& r : rb) {
    if (is_foreign_sweep(r)) continue;
    const std::string key = run_key(r);
    const auto peak = find_peak(r);
    if (peak && !matched.count(key))
      out.push_back(only_in(key + " | W=" + std::to_string(peak->workers), "FLOPS", "FLOP/s",
                            flops_of(r, *at_workers(r, peak->workers)), false));
  }
}

void compare_sets(std::span<const ResultSet> sa, std::span<const ResultSet> sb, const CompareOptions& o,
                  std::vector<MeasureComparison>& out) {
  using Key = std::pair<std::string, std::string>;  // (set key, metric)
  std::map<Key, const Measurement*> by_key_b;
  for (const auto& s : sb)
    for (const auto& m : s.measurements) by_key_b.emplace(Key{set_key(s, m), m.metric}, &m);
  std::map<Key, bool> matched;
  for (const auto& s : sa)
    for (const auto& m : s.measurements) {
      if (m.values.empty()) continue;
      const Key key{set_key(s, m), m.metric};
      const auto it = by_key_b.find(key);
      if (it == by_key_b.end() || it->second->values.empty()) {
        out.push_back(only_in(key.first, m.metric, m.unit, m.values, true));
        continue;
      }
      matched[key] = true;
      out.push_back(judge(key.first, m.metric, m.unit, m.values, it->second->values, o));
    }
  for (const auto& s : sb)
    for (const auto& m : s.measurements) {
      const Key key{set_key(s, m), m.metric};
      if (!m.values.empty() && !matched.count(key))
        out.push_back(only_in(key.first, m.metric, m.unit, m.values, false));
    }
}

}  // namespace

std::string_view to_string(CompareVerdict v) {
  constexpr EnumWord<CompareVerdict> kWords[] = {
      {CompareVerdict::Unchanged, "unchanged"},     {CompareVerdict::Regression, "regression"},
      {CompareVerdict::Improvement, "improvement"}, {CompareVerdict::NotSignificant, "not significant"},
      {CompareVerdict::Changed, "changed"},         {CompareVerdict::OnlyInA, "only in A"},
      {CompareVerdict::OnlyInB, "only in B"}};
  static_assert(names_every_value(kWords, CompareVerdict::OnlyInB));
  return word_of(kWords, v, "?");
}

std::optional<bool> higher_is_better_for_unit(std::string_view unit) {
  if (unit == "s" || unit == "ms" || unit == "us" || unit == "ns" || unit == "J" || unit == "W") return false;
  if (unit.ends_with("/s")) return true;  // FLOP/s, B/s, 1/s, items/s
  return std::nullopt;
}

std::vector<MeasureComparison> compare_results(const CompareInput& a, const CompareInput& b,
                                               const CompareOptions& options) {
  std::vector<MeasureComparison> out;
  compare_runs(a.runs, b.runs, options, out);
  compare_sets(a.result_sets, b.result_sets, options, out);
  std::stable_sort(out.begin(), out.end(), [](const auto& x, const auto& y) {
    return std::tie(x.key, x.measure) < std::tie(y.key, y.measure);
  });
  return out;
}

}  // namespace bs
