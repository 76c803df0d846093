// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/stats/mann_whitney.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace bs {
namespace {

// Number of arrangements of n_a + n_b distinct values giving each U, by the recurrence
// f(m, n, u) = f(m - 1, n, u - n) + f(m, n - 1, u): the largest value belongs to the first or the second sample.
std::vector<double> exact_u_counts(int n_a, int n_b) {
  // counts[n][u] for the current m, built up over m.
  std::vector<std::vector<double>> prev(n_b + 1), cur(n_b + 1);
  for (int n = 0; n <= n_b; ++n) prev[n] = {1.0};  // m = 0: one arrangement, U = 0
  for (int m = 1; m <= n_a; ++m) {
    cur[0] = {1.0};
    for (int n = 1; n <= n_b; ++n) {
      std::vector<double> f(static_cast<std::size_t>(m * n + 1), 0.0);
      for (std::size_t u = 0; u < prev[n].size(); ++u) f[u + n] += prev[n][u];    // largest in a: +n
      for (std::size_t u = 0; u < cur[n - 1].size(); ++u) f[u] += cur[n - 1][u];  // largest in b
      cur[n] = std::move(f);
    }
    std::swap(prev, cur);
  }
  return prev[n_b];
}

}  // namespace

MannWhitney mann_whitney_u(std::span<const double> a, std::span<const double> b) {
  MannWhitney r;
  const std::size_t na = a.size(), nb = b.size();
  if (na == 0 || nb == 0) return r;
  // Ranks of the pooled sample, ties getting their mean rank.
  std::vector<std::pair<double, int>> pooled;
  pooled.reserve(na + nb);
  for (double x : a) pooled.push_back({x, 0});
  for (double x : b) pooled.push_back({x, 1});
  std::sort(pooled.begin(), pooled.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  double rank_sum_a = 0, tie_term = 0;
  bool ties = false;
  for (std::size_t i = 0; i < pooled.size();) {
    std::size_t j = i;
    while (j < pooled.size() && pooled[j].first == pooled[i].first) ++j;
    const double mean_rank = (static_cast<double>(i + 1) + static_cast<double>(j)) / 2.0;
    const double t = static_cast<double>(j - i);
    if (t > 1) {
      ties = true;
      tie_term += t * t * t - t;
    }
    for (std::size_t k = i; k < j; ++k)
      if (pooled[k].second == 0) rank_sum_a += mean_rank;
    i = j;
  }
  const double n1 = static_cast<double>(na), n2 = static_cast<double>(nb);
  r.u = rank_sum_a - n1 * (n1 + 1) / 2.0;
  const double mean_u = n1 * n2 / 2.0;

  if (!ties && na + nb <= 20) {
    const auto counts = exact_u_counts(static_cast<int>(na), static_cast<int>(nb));
    double total = 0;
    for (double c : counts) total += c;
    // Two-sided: twice the smaller tail, capped at 1.
    const auto u_int = static_cast<std::size_t>(std::lround(r.u));
    double lower = 0, upper = 0;
    for (std::size_t u = 0; u < counts.size(); ++u) {
      if (u <= u_int) lower += counts[u];
      if (u >= u_int) upper += counts[u];
    }
    r.p_value = std::min(1.0, 2.0 * std::min(lower, upper) / total);
    r.exact = true;
    return r;
  }
  const double n = n1 + n2;
  const double var_u = n1 * n2 / 12.0 * ((n + 1) - tie_term / (n * (n - 1)));
  if (var_u <= 0) return r;  // every value equal: no evidence of a difference
  const double z = (std::fabs(r.u - mean_u) - 0.5) / std::sqrt(var_u);
  r.p_value = std::min(1.0, std::erfc(std::max(z, 0.0) / std::sqrt(2.0)));
  return r;
}

}  // namespace bs
