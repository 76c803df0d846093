// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/result_peaks.h"

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
      if (m.values.empty()) continue;
      const MeasureClass c = classify_measurement(m);
      if (!wanted(c, query)) continue;
      const Summary sum = summarize(m.values);
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
