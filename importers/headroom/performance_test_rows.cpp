// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/performance_test_rows.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "headroom/imported_latency.h"

namespace bs::headroom_import {
namespace {

enum class RowKind { Interval, RunningTotal };

// The count a row's kind is read from: samples sent (the publisher's, not reduced by losses), else received.
double count_of(const PerfTestRow& r) { return r.sent > 0 ? r.sent : r.received; }

double interval_s(const PerfTestRow& r) { return r.t_loop_s > 0 ? r.t_loop_s : 1.0; }

std::string number(double v) {
  std::ostringstream s;
  s.precision(4);
  s << v;
  return s.str();
}

std::vector<RowKind> classify(const std::vector<PerfTestRow>& rows, std::optional<double> rate_hz) {
  std::vector<RowKind> kinds(rows.size(), RowKind::Interval);
  double rate = rate_hz && *rate_hz > 0 ? *rate_hz : 0;
  if (rate == 0) {
    // No rate: counts that grow row after row, to at least twice the first, are running totals.
    bool rising = rows.size() >= 3;
    for (std::size_t k = 1; k < rows.size() && rising; ++k) rising = count_of(rows[k]) > count_of(rows[k - 1]);
    if (rising && count_of(rows.back()) >= 2 * count_of(rows.front())) {
      std::fill(kinds.begin(), kinds.end(), RowKind::RunningTotal);
      return kinds;
    }
    // Otherwise the typical row is one interval: its rate is the median of count / T_loop.
    std::vector<double> rates;
    for (const PerfTestRow& r : rows) rates.push_back(count_of(r) / interval_s(r));
    std::nth_element(rates.begin(), rates.begin() + static_cast<std::ptrdiff_t>(rates.size() / 2), rates.end());
    rate = rates[rates.size() / 2];
  }
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const double expected = rate * interval_s(rows[k]);
    kinds[k] = count_of(rows[k]) > 1.5 * expected + 2 ? RowKind::RunningTotal : RowKind::Interval;
  }
  return kinds;
}

[[noreturn]] void mixed(const PerfTestRow& row, RowKind kind, const PerfTestRow& first, std::size_t first_index) {
  const std::string count = number(count_of(row));
  const std::string reference = "row " + std::to_string(first_index + 1) +
                                (first.at.line ? " (line " + std::to_string(first.at.line) + ")" : std::string());
  throw ImportError(ImportErrorCategory::InvalidValue, row.at,
                    kind == RowKind::RunningTotal
                        ? "mixed per-interval and cumulative rows: " + count +
                              " samples here is a running total, but the rows from " + reference +
                              " on count one interval each; they cannot be combined without counting samples twice"
                        : "mixed per-interval and cumulative rows: " + count +
                              " samples here is one interval's count, but the rows from " + reference +
                              " on are running totals; they cannot be combined");
}

void check_row(const PerfTestRow& r) {
  const double tolerance = 1e-6 * std::max(std::abs(r.max_s), 1e-9);
  if (r.min_s < 0 || r.min_s > r.mean_s + tolerance || r.mean_s > r.max_s + tolerance)
    throw ImportError(ImportErrorCategory::InvalidValue, r.at,
                      "latency min, mean and max are not in order (" + number(r.min_s * 1e3) + ", " +
                          number(r.mean_s * 1e3) + ", " + number(r.max_s * 1e3) + " ms)");
  if (r.max_s > 1e6 || r.variance_s2 > 1e12)
    throw ImportError(ImportErrorCategory::InvalidValue, r.at, "a latency beyond 10^6 s is not a measurement");
  if (r.received > 1e15 || r.sent > 1e15 || (r.latency_n && *r.latency_n > 1e15))
    throw ImportError(ImportErrorCategory::InvalidValue, r.at, "a sample count beyond 10^15 is not a measurement");
  if (r.variance_s2 < 0) throw ImportError(ImportErrorCategory::InvalidValue, r.at, "a negative latency variance");
  if (r.received < 0 || r.sent < 0 || (r.latency_n && *r.latency_n < 0))
    throw ImportError(ImportErrorCategory::InvalidValue, r.at, "a negative sample count");
}

double n_of(const PerfTestRow& r) { return r.latency_n ? *r.latency_n : r.received; }

}  // namespace

CombinedLatency combine_rows(const std::vector<PerfTestRow>& rows, std::optional<double> rate_hz) {
  CombinedLatency c;
  if (rows.empty()) throw ImportError(ImportErrorCategory::MissingField, {}, "no statistics rows");
  for (const PerfTestRow& r : rows) check_row(r);
  const std::vector<RowKind> kinds = classify(rows, rate_hz);
  // The first row of a log of running totals covers one interval and looks like one: the kind is read from the
  // second row on.
  const std::size_t from = rows.size() > 1 ? 1 : 0;
  const RowKind kind = kinds[from];
  for (std::size_t k = from + 1; k < rows.size(); ++k)
    if (kinds[k] != kind) mixed(rows[k], kinds[k], rows[from], from);
  c.running_totals = kind == RowKind::RunningTotal;
  if (c.running_totals) {
    for (std::size_t k = 1; k < rows.size(); ++k)
      if (count_of(rows[k]) < count_of(rows[k - 1]))
        throw ImportError(ImportErrorCategory::InvalidValue, rows[k].at,
                          "a running total falls from " + number(count_of(rows[k - 1])) + " to " +
                              number(count_of(rows[k])) + " samples (the log restarted?)");
    const PerfTestRow& last = rows.back();
    const double n = n_of(last);
    if (n <= 0) throw ImportError(ImportErrorCategory::MissingField, last.at, "the last row holds no latency sample");
    c.n = static_cast<std::uint64_t>(std::llround(n));
    c.min_s = last.min_s;
    c.max_s = last.max_s;
    c.mean_s = last.mean_s;
    c.sd_s = n > 1 ? std::sqrt(last.variance_s2 * n / (n - 1)) : 0.0;
    c.rows = 1;
    return c;
  }
  double total = 0, sum = 0;
  bool any = false;
  const PerfTestRow* worst = nullptr;
  for (const PerfTestRow& r : rows) {
    const double n = n_of(r);
    if (n <= 0) continue;  // an interval without samples has no latency statistics
    c.min_s = any ? std::min(c.min_s, r.min_s) : r.min_s;
    c.max_s = any ? std::max(c.max_s, r.max_s) : r.max_s;
    if (!worst || r.max_s > worst->max_s) worst = &r;
    any = true;
    total += n;
    sum += n * r.mean_s;
    ++c.rows;
  }
  if (!any) throw ImportError(ImportErrorCategory::MissingField, rows.front().at, "no row holds a latency sample");
  c.mean_s = sum / total;
  double m2 = 0;
  for (const PerfTestRow& r : rows) {
    const double n = n_of(r);
    if (n <= 0) continue;
    m2 += r.variance_s2 * n + n * (r.mean_s - c.mean_s) * (r.mean_s - c.mean_s);
  }
  c.n = static_cast<std::uint64_t>(std::llround(total));
  c.sd_s = total > 1 ? std::sqrt(m2 / (total - 1)) : 0.0;
  c.worst_interval = "largest latency " + number(worst->max_s * 1e3) +
                     " ms in the interval ending at T = " + number(worst->t_experiment_s) + " s";
  return c;
}

headroom::HeadroomMeasurement perf_test_measurement(const CombinedLatency& c,
                                                    std::vector<std::pair<std::string, std::string>> settings,
                                                    const std::string& file) {
  headroom::HeadroomMeasurement m =
      imported_measurement(headroom::LatencyKind::MessageLatency, "performance_test", file);
  headroom::Phase& phase = m.phases.front();
  const auto ns = [](double s) { return static_cast<std::int64_t>(std::llround(s * 1e9)); };
  phase.threads.push_back(summary_only_thread(0, c.n, ns(c.min_s), ns(c.max_s), c.mean_s * 1e9, c.sd_s * 1e9));
  phase.notes.push_back(std::string(kSummaryOnlyNote) + " (performance_test keeps per-second statistics only)");
  phase.notes.push_back(c.running_totals ? "rows are running totals: the last row is the whole run"
                                         : "rows are per-interval statistics: " + std::to_string(c.rows) +
                                               " intervals pooled (n-weighted mean, pooled variance)");
  if (!c.worst_interval.empty()) phase.notes.push_back(c.worst_interval);
  m.provenance.settings = std::move(settings);
  m.provenance.settings.emplace_back("rows", c.running_totals ? "running totals" : "per interval");
  return m;
}

}  // namespace bs::headroom_import
