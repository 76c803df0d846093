// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/power/power_phases.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "analysis/power/power_time.h"

namespace bs {
namespace {

// Centred moving average over a time window, O(n) with two pointers over a prefix sum.
std::vector<double> smooth(std::span<const double> t, std::span<const double> v, double window_s) {
  const std::size_t n = v.size();
  std::vector<double> prefix(n + 1, 0.0);
  for (std::size_t k = 0; k < n; ++k) prefix[k + 1] = prefix[k] + v[k];
  std::vector<double> out(n);
  std::size_t lo = 0, hi = 0;
  const double half = window_s / 2;
  for (std::size_t k = 0; k < n; ++k) {
    while (t[k] - t[lo] > half) ++lo;
    while (hi + 1 < n && t[hi + 1] - t[k] <= half) ++hi;
    if (hi < k) hi = k;
    out[k] = (prefix[hi + 1] - prefix[lo]) / static_cast<double>(hi + 1 - lo);
  }
  return out;
}

struct Segment {
  std::size_t first, end;  // [first, end)
};

}  // namespace

double noise_sd(std::span<const double> values) {
  if (values.size() < 3) return 0;
  std::vector<double> d(values.size() - 1);
  for (std::size_t k = 0; k + 1 < values.size(); ++k) d[k] = std::abs(values[k + 1] - values[k]);
  std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
  return d[d.size() / 2] / (0.6745 * std::sqrt(2.0));
}

std::vector<DetectedPhase> detect_phases(std::span<const double> t, std::span<const double> v, const PhaseOptions& o) {
  if (t.size() != v.size()) throw std::invalid_argument("phase detection: time and values differ in length");
  if (!(o.smooth_s >= 0) || !(o.min_phase_s > 0) || (o.min_step && !(*o.min_step > 0)))
    throw std::invalid_argument("phase detection: smoothing >= 0 s, minimum phase > 0 s and minimum step > 0");
  if (std::any_of(v.begin(), v.end(), [](double x) { return std::isnan(x); })) {
    // Missing samples: phases are time ranges, so they are found on the present samples alone.
    std::vector<double> tp, vp;
    for (std::size_t k = 0; k < v.size(); ++k)
      if (!std::isnan(v[k])) {
        tp.push_back(t[k]);
        vp.push_back(v[k]);
      }
    return detect_phases(tp, vp, o);
  }
  const std::size_t n = v.size();
  if (n < 2) return {};
  const auto [lo_it, hi_it] = std::minmax_element(v.begin(), v.end());
  const double range = *hi_it - *lo_it;
  const double step = o.min_step ? *o.min_step : std::max(6 * noise_sd(v), 0.02 * range);
  const std::vector<double> s = smooth(t, v, o.smooth_s);
  std::vector<double> prefix(n + 1, 0.0);
  for (std::size_t k = 0; k < n; ++k) prefix[k + 1] = prefix[k] + s[k];
  const auto mean = [&](std::size_t a, std::size_t b) { return (prefix[b] - prefix[a]) / static_cast<double>(b - a); };

  // Binary segmentation with an explicit stack (a long trace may have many phases).
  std::vector<Segment> done, todo{{0, n}};
  while (!todo.empty()) {
    const Segment seg = todo.back();
    todo.pop_back();
    double best_gain = 0;
    std::size_t best = 0;
    for (std::size_t k = seg.first + 1; k < seg.end; ++k) {
      if (t[k] - t[seg.first] < o.min_phase_s) continue;
      if (t[seg.end - 1] - t[k] < o.min_phase_s) break;
      const double n1 = static_cast<double>(k - seg.first), n2 = static_cast<double>(seg.end - k);
      const double d = mean(seg.first, k) - mean(k, seg.end);
      const double gain = n1 * n2 / (n1 + n2) * d * d;  // reduction of the squared error by splitting at k
      if (gain > best_gain) {
        best_gain = gain;
        best = k;
      }
    }
    if (best != 0 && std::abs(mean(seg.first, best) - mean(best, seg.end)) >= step) {
      todo.push_back({best, seg.end});
      todo.push_back({seg.first, best});
    } else {
      done.push_back(seg);
    }
  }
  std::sort(done.begin(), done.end(), [](const Segment& a, const Segment& b) { return a.first < b.first; });
  // Levels from the raw values; merge neighbours whose levels are within a step of each other.
  const auto raw_mean = [&](const Segment& g) {
    double sum = 0;
    for (std::size_t k = g.first; k < g.end; ++k) sum += v[k];
    return sum / static_cast<double>(g.end - g.first);
  };
  std::vector<Segment> merged;
  for (const Segment& g : done) {
    if (!merged.empty() && std::abs(raw_mean(merged.back()) - raw_mean(g)) < step)
      merged.back().end = g.end;
    else
      merged.push_back(g);
  }
  std::vector<DetectedPhase> phases;
  double lowest = 0;
  for (std::size_t i = 0; i < merged.size(); ++i) {
    const Segment& g = merged[i];
    DetectedPhase p;
    p.first = g.first;
    p.last = g.end - 1;
    p.start_s = t[g.first];
    p.end_s = i + 1 < merged.size() ? t[merged[i + 1].first] : t[n - 1];
    p.mean = raw_mean(g);
    lowest = i == 0 ? p.mean : std::min(lowest, p.mean);
    phases.push_back(p);
  }
  for (DetectedPhase& p : phases) p.name = p.mean - lowest < step ? "idle" : "load";
  return phases;
}

std::vector<TracePhase> to_trace_phases(const std::vector<DetectedPhase>& phases) {
  std::vector<TracePhase> out;
  for (const DetectedPhase& p : phases) out.push_back({p.name, p.start_s, p.end_s});
  return out;
}

std::optional<TimeWindow> align_run(const PowerTrace& trace, std::string_view run_start_iso,
                                    std::string_view run_end_iso) {
  if (trace.start_time.empty() || trace.time_s.empty()) return std::nullopt;
  const auto origin = parse_iso8601(trace.start_time);
  const auto start = parse_iso8601(run_start_iso);
  const auto end = parse_iso8601(run_end_iso);
  if (!origin || !start || !end || *end < *start) return std::nullopt;
  TimeWindow w{*start - *origin, *end - *origin};
  if (w.to_s < trace.time_s.front() || w.from_s > trace.time_s.back()) return std::nullopt;
  w.from_s = std::max(w.from_s, trace.time_s.front());
  w.to_s = std::min(w.to_s, trace.time_s.back());
  return w;
}

std::optional<DetectedPhase> match_load_phase(const std::vector<DetectedPhase>& phases, double run_duration_s,
                                              double tolerance) {
  std::optional<DetectedPhase> best;
  double best_err = 0;
  for (const DetectedPhase& p : phases) {
    if (p.name != "load") continue;
    const double err = std::abs((p.end_s - p.start_s) - run_duration_s);
    if (err > tolerance * run_duration_s) continue;
    if (!best || err < best_err) {
      best = p;
      best_err = err;
    }
  }
  return best;
}

}  // namespace bs
