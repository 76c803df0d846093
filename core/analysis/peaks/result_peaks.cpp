// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/peaks/result_peaks.h"

#include "analysis/peaks/foreign_sweeps.h"

#include <map>
#include <utility>

namespace bs {
namespace {

bool wanted(const MeasureClass& c, const ResultPeakQuery& q) {
  if (!is_compute(c.kind)) return false;
  if (!q.precision) return true;
  return c.precision == *q.precision && c.kind == q.kind;
}

}  // namespace

std::vector<ResultPeak> result_peaks(std::span<const ResultSet> sets, const ResultPeakQuery& query) {
  std::vector<ResultPeak> out;
  for (const ResultSet& s : sets) {
    // Per (kind, precision) of this set, the measurement with the highest mean; ordered so rows read the same way
    // every time (vector compute first, then by precision as declared).
    std::map<std::pair<int, int>, ResultPeak> best;
    for (const Measurement& m : s.measurements) {
      // A Google Benchmark counter that forms a workers sweep is a peak-table row (analysis/foreign_sweeps.h), not
      // repeated here.
      if (m.values.empty() || is_swept(s, m)) continue;
      const MeasureClass c = classify_measurement(m);
      if (!wanted(c, query)) continue;
      // BenchScope's one definition of a figure: the mean over repetitions with n and SD (Google Benchmark's
      // _mean / _stddev aggregates when the file has them), never the best repetition.
      const auto stated = summarize_measurement(m);
      if (!stated) continue;
      const Summary sum{stated->n, stated->mean, stated->sd, stated->min, stated->max};
      const auto key = std::make_pair(static_cast<int>(c.kind), static_cast<int>(c.precision));
      const auto it = best.find(key);
      if (it == best.end() || sum.mean > it->second.summary.mean) best[key] = ResultPeak{&s, &m, c, sum};
    }
    for (auto& [key, peak] : best) out.push_back(peak);
  }
  return out;
}

std::size_t compute_measurements_left_out(std::span<const ResultSet> sets, const ResultPeakQuery& query) {
  std::size_t n = 0;
  for (const ResultSet& s : sets)
    for (const Measurement& m : s.measurements) {
      const MeasureClass c = classify_measurement(m);
      n += is_compute(c.kind) && !m.values.empty() && !wanted(c, query);
    }
  return n;
}

}  // namespace bs
