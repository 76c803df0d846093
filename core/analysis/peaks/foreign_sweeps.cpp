// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/peaks/foreign_sweeps.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <map>

#include "analysis/stats/stats.h"

namespace bs {
namespace {

std::vector<std::string_view> split(std::string_view name) {
  std::vector<std::string_view> out;
  for (std::size_t start = 0;;) {
    const std::size_t slash = name.find('/', start);
    out.push_back(name.substr(start, slash == std::string_view::npos ? std::string_view::npos : slash - start));
    if (slash == std::string_view::npos) return out;
    start = slash + 1;
  }
}

bool is_option_segment(std::string_view s) {
  constexpr std::array<std::string_view, 5> prefixed = {
      "min_time:", "min_warmup_time:", "iterations:", "repeats:", "threads:"};
  constexpr std::array<std::string_view, 3> flags = {"real_time", "process_time", "manual_time"};
  for (std::string_view p : prefixed)
    if (s.starts_with(p)) return true;
  return std::find(flags.begin(), flags.end(), s) != flags.end();
}

std::optional<std::int64_t> positive_integer(std::string_view text) {
  std::int64_t v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || v < 1) return std::nullopt;
  return v;
}

// The name's segments joined again, with segment `skip` replaced (or dropped when `replacement` is empty).
std::string join(const std::vector<std::string_view>& parts, std::size_t skip, std::string_view replacement) {
  std::string out;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (i == skip && replacement.empty()) continue;
    if (i > 0) out += '/';
    out += i == skip ? replacement : parts[i];
  }
  return out;
}

const double* aggregate(const Measurement& m, std::string_view name) {
  for (const auto& [key, value] : m.reported_aggregates)
    if (key == name) return &value;
  return nullptr;
}

}  // namespace

WorkersArgument workers_argument(const Provenance& provenance) {
  for (const auto& [key, value] : provenance.settings) {
    if (key != kWorkersFromSetting || !value.starts_with("argument ")) continue;
    int k = 0;
    const std::string_view digits = std::string_view(value).substr(9);
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), k);
    if (ec == std::errc() && end == digits.data() + digits.size() && k >= 0) return k;
  }
  return std::nullopt;
}

std::string workers_from_text(const WorkersArgument& argument) {
  return argument ? "argument " + std::to_string(*argument) : std::string("threads");
}

std::optional<SweepPoint> sweep_point(std::string_view run_name, const WorkersArgument& argument) {
  const std::vector<std::string_view> parts = split(run_name);
  if (!argument) {
    for (std::size_t i = 1; i < parts.size(); ++i) {
      if (!parts[i].starts_with("threads:")) continue;
      const auto threads = positive_integer(parts[i].substr(8));
      if (!threads) return std::nullopt;
      return SweepPoint{join(parts, i, {}), *threads};
    }
    return SweepPoint{std::string(run_name), 1};  // Google Benchmark runs one thread unless told otherwise
  }
  int seen = 0;
  for (std::size_t i = 1; i < parts.size(); ++i) {
    if (is_option_segment(parts[i])) continue;
    if (seen++ != *argument) continue;
    std::string_view value = parts[i];
    if (const auto colon = value.rfind(':'); colon != std::string_view::npos) value = value.substr(colon + 1);
    const auto workers = positive_integer(value);
    if (!workers) return std::nullopt;
    const std::string_view label = parts[i].substr(0, parts[i].size() - value.size());  // "size:" or ""
    return SweepPoint{join(parts, i, std::string(label) + "*"), *workers};
  }
  return std::nullopt;
}

std::optional<StatedFlops> summarize_measurement(const Measurement& m) {
  std::vector<double> finite;
  for (double v : m.values)
    if (std::isfinite(v)) finite.push_back(v);
  const Summary over = summarize(finite);
  const double* mean = aggregate(m, "mean");
  if (mean && std::isfinite(*mean)) {
    StatedFlops s;
    s.mean = *mean;
    const double* reps = aggregate(m, "repetitions");
    s.n = reps && std::isfinite(*reps) && *reps >= 1 ? static_cast<std::size_t>(*reps) : finite.size();
    const double* sd = aggregate(m, "stddev");
    s.sd = sd && std::isfinite(*sd) ? *sd : over.n >= 2 ? over.sd : 0.0;
    s.min = finite.empty() ? *mean : over.min;
    s.max = finite.empty() ? *mean : over.max;
    if (s.n == 0) s.n = 1;  // a reported mean summarises at least one repetition
    return s;
  }
  if (finite.empty()) return std::nullopt;
  return StatedFlops{over.n, over.mean, over.sd, over.min, over.max};
}

bool is_swept(const ResultSet& set, const Measurement& m) {
  return set.source_format == "google-benchmark-json" && m.unit == "FLOP/s" &&
         sweep_point(m.name, workers_argument(set.provenance)).has_value() && summarize_measurement(m).has_value();
}

std::vector<FlopsRun> foreign_sweeps(const ResultSet& set) {
  std::vector<FlopsRun> runs;
  if (set.source_format != "google-benchmark-json") return runs;
  const WorkersArgument argument = workers_argument(set.provenance);
  std::map<std::pair<std::string, std::string>, std::size_t> index;  // (family, counter) -> run
  for (const Measurement& m : set.measurements) {
    if (m.unit != "FLOP/s") continue;
    const auto point = sweep_point(m.name, argument);
    const auto flops = summarize_measurement(m);
    if (!point || !flops) continue;
    auto [it, added] = index.emplace(std::make_pair(point->family, m.metric), runs.size());
    if (added) {
      FlopsRun run;
      run.platform = set.platform;
      run.device = set.device;
      run.device_kind = set.device_kind;
      run.backend = set.backend;
      run.kernel = std::string(kForeignSweepKernel);
      run.variant = point->family + " (" + m.metric + ")";
      run.iterations = 0;  // not stated: the file gives FLOPS, not BenchScope's 6*D*N*W accounting
      run.dims = 0;
      run.provenance = set.provenance;
      runs.push_back(std::move(run));
    }
    FlopsRun& run = runs[it->second];
    const bool repeated = std::any_of(run.samples.begin(), run.samples.end(),
                                      [&](const WorkerSample& s) { return s.workers == point->workers; });
    if (repeated) continue;  // the importer refuses conflicting rows; an equal name twice adds nothing
    WorkerSample sample;
    sample.workers = point->workers;
    sample.stated_flops = flops;
    run.samples.push_back(std::move(sample));
  }
  for (FlopsRun& run : runs)
    std::sort(run.samples.begin(), run.samples.end(),
              [](const WorkerSample& a, const WorkerSample& b) { return a.workers < b.workers; });
  return runs;
}

std::vector<FlopsRun> foreign_sweeps(std::span<const ResultSet> sets) {
  std::vector<FlopsRun> runs;
  for (const ResultSet& s : sets) {
    std::vector<FlopsRun> more = foreign_sweeps(s);
    std::move(more.begin(), more.end(), std::back_inserter(runs));
  }
  return runs;
}

bool is_foreign_sweep(const FlopsRun& run) {
  return std::any_of(run.samples.begin(), run.samples.end(),
                     [](const WorkerSample& s) { return s.stated_flops.has_value(); });
}

}  // namespace bs
