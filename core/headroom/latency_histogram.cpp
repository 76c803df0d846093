// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/latency_histogram.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace bs::headroom {

std::uint64_t LatencyHistogram::binned() const { return std::accumulate(bins.begin(), bins.end(), std::uint64_t{0}); }

std::string LatencyHistogram::bookkeeping_error() const {
  const std::uint64_t in_bins = binned();
  if (cycles != in_bins + overflows)
    return "cycles " + std::to_string(cycles) + " != " + std::to_string(in_bins) + " in bins + " +
           std::to_string(overflows) + " overflows";
  if (bin_ns <= 0) return "bin width " + std::to_string(bin_ns) + " ns is not positive";
  if (max_ns && overflows > 0 && *max_ns < limit_ns())
    return "maximum " + std::to_string(*max_ns) + " ns lies below the limit " + std::to_string(limit_ns()) +
           " ns although " + std::to_string(overflows) + " cycles overflowed";
  if (min_ns && max_ns && *min_ns > *max_ns)
    return "minimum " + std::to_string(*min_ns) + " ns above maximum " + std::to_string(*max_ns) + " ns";
  if (max_ns && cycles > 0 && overflows == 0) {
    // The highest non-empty bin must hold the maximum.
    for (std::size_t i = bins.size(); i-- > 0;)
      if (bins[i] != 0) {
        const std::int64_t lo = static_cast<std::int64_t>(i) * bin_ns;
        if (*max_ns < lo || *max_ns >= lo + bin_ns)
          return "maximum " + std::to_string(*max_ns) + " ns is not in the highest non-empty bin [" +
                 std::to_string(lo) + ", " + std::to_string(lo + bin_ns) + ") ns";
        break;
      }
  }
  return {};
}

void LatencyHistogram::add(std::int64_t latency_ns) {
  latency_ns = std::max<std::int64_t>(latency_ns, 0);
  const std::int64_t index = latency_ns / bin_ns;
  if (index < static_cast<std::int64_t>(bins.size()))
    ++bins[static_cast<std::size_t>(index)];
  else
    ++overflows;
  ++cycles;
  if (!min_ns || latency_ns < *min_ns) min_ns = latency_ns;
  if (!max_ns || latency_ns > *max_ns) max_ns = latency_ns;
}

void LatencyHistogram::merge(const LatencyHistogram& other) {
  if (other.bin_ns != bin_ns || other.bins.size() != bins.size())
    throw std::invalid_argument("cannot merge latency histograms of different bins (" + std::to_string(bins.size()) +
                                " x " + std::to_string(bin_ns) + " ns and " + std::to_string(other.bins.size()) +
                                " x " + std::to_string(other.bin_ns) + " ns)");
  for (std::size_t i = 0; i < bins.size(); ++i) bins[i] += other.bins[i];
  overflows += other.overflows;
  cycles += other.cycles;
  if (other.min_ns && (!min_ns || *other.min_ns < *min_ns)) min_ns = other.min_ns;
  if (other.max_ns && (!max_ns || *other.max_ns > *max_ns)) max_ns = other.max_ns;
}

HistogramPercentile LatencyHistogram::percentile(double q) const {
  if (cycles == 0) return {};
  q = std::clamp(q, 0.0, 100.0);
  const double exact_rank = q / 100.0 * static_cast<double>(cycles);
  // ceil with a tolerance so that 99.9 % of 1000 is rank 999, not 1000 through rounding of 0.999 * 1000.
  auto rank = static_cast<std::uint64_t>(std::ceil(exact_rank - 1e-9 * exact_rank));
  rank = std::clamp<std::uint64_t>(rank, 1, cycles);
  if (rank == cycles && max_ns) return {*max_ns, false};
  std::uint64_t cumulative = 0;
  for (std::size_t i = 0; i < bins.size(); ++i) {
    cumulative += bins[i];
    if (cumulative >= rank) return {static_cast<std::int64_t>(i) * bin_ns, false};
  }
  return {limit_ns(), true};  // among the overflows, below the maximum
}

LatencyHistogram::Beyond LatencyHistogram::count_above(std::int64_t threshold_ns) const {
  Beyond out;
  if (threshold_ns < 0) {
    out.count = cycles;
    return out;
  }
  if (threshold_ns >= limit_ns()) {
    // Only overflows can lie above it, and the histogram does not say where; the true maximum settles the cases
    // "none" (maximum not above) and "the one overflow"; otherwise at least the maximum is above, count unknown.
    if (overflows == 0 || (max_ns && *max_ns <= threshold_ns)) return out;
    out.count = max_ns ? 1 : 0;
    out.exact = max_ns && overflows == 1;
    return out;
  }
  out.count = overflows;
  const auto cut = static_cast<std::size_t>(threshold_ns / bin_ns);  // the bin holding the threshold
  // Latencies of that bin above the threshold cannot be told from those below it, unless the threshold is the
  // bin's last nanosecond (then none of the bin is above it).
  if ((threshold_ns + 1) % bin_ns != 0 && bins[cut] != 0) out.exact = false;
  for (std::size_t i = cut + 1; i < bins.size(); ++i) out.count += bins[i];
  return out;
}

std::optional<double> LatencyHistogram::binned_mean_ns() const {
  if (cycles == 0) return std::nullopt;
  double sum = 0;
  for (std::size_t i = 0; i < bins.size(); ++i)
    sum += static_cast<double>(bins[i]) * (static_cast<double>(i) + 0.5) * static_cast<double>(bin_ns);
  sum += static_cast<double>(overflows) * static_cast<double>(max_ns ? *max_ns : limit_ns());
  return sum / static_cast<double>(cycles);
}

LatencyHistogram make_histogram(std::int64_t limit_ns, std::int64_t bin_ns) {
  if (bin_ns <= 0) throw std::invalid_argument("latency histogram bin width must be positive");
  LatencyHistogram h;
  h.bin_ns = bin_ns;
  h.bins.assign(static_cast<std::size_t>(std::max<std::int64_t>(0, (limit_ns + bin_ns - 1) / bin_ns)), 0);
  return h;
}

}  // namespace bs::headroom
