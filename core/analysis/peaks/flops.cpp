// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/peaks/flops.h"

namespace bs {

double rotation_flop_count(int dims, std::int64_t iterations, std::int64_t workers) noexcept {
  return 6.0 * static_cast<double>(dims) * static_cast<double>(iterations) * static_cast<double>(workers);
}

double rotation_flops(int dims, std::int64_t iterations, std::int64_t workers, double seconds) noexcept {
  return rotation_flop_count(dims, iterations, workers) / seconds;
}

std::vector<CurvePoint> flops_curve(const FlopsRun& run) {
  std::vector<CurvePoint> curve;
  curve.reserve(run.samples.size());
  for (const WorkerSample& s : run.samples) {
    if (s.stated_flops) {
      const StatedFlops& f = *s.stated_flops;
      curve.push_back({s.workers, {f.n, f.mean, f.sd, f.min, f.max}});
      continue;
    }
    RunningStats stats;
    for (double t : s.seconds) stats.add(rotation_flops(run.dims, run.iterations, s.workers, t));
    curve.push_back({s.workers, {stats.count(), stats.mean(), stats.sd(), stats.min(), stats.max()}});
  }
  return curve;
}

std::optional<Peak> find_peak(const FlopsRun& run) {
  std::optional<Peak> best;
  for (const CurvePoint& p : flops_curve(run)) {
    if (p.flops.n == 0) continue;
    if (!best || p.flops.mean > best->flops) best = Peak{p.flops.mean, p.workers, p.flops};
  }
  return best;
}

std::vector<PeakRow> peak_table(std::span<const FlopsRun> runs) {
  const BundledDeviceTable& bundled = bundled_device_table();
  std::vector<PeakRow> rows = peak_table(runs, bundled.table);
  if (!bundled.error.empty())
    for (PeakRow& row : rows)
      row.flags.push_back(
          {flag_code::kSpecCheckUnavailable, "Not checked against the device's vendor peak: " + bundled.error});
  return rows;
}

std::vector<PeakRow> peak_table(std::span<const FlopsRun> runs, const DeviceTable& table) {
  std::vector<PeakRow> rows;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const FlopsRun& run = runs[i];
    const auto peak = find_peak(run);
    if (!peak) continue;
    PeakRow row;
    row.run_index = i;
    row.platform = run.platform;
    row.device = run.device;
    row.backend = run.backend;
    row.variant = run.variant;
    row.device_kind = run.device_kind;
    row.dims = run.dims;
    row.iterations = run.iterations;
    row.peak = *peak;
    row.reported_flops = run.reported_peak_flops;
    if (run.reported_peak_flops && *run.reported_peak_flops > 0)
      row.ratio_to_reported = peak->flops / *run.reported_peak_flops;
    row.theoretical_flops = run.theoretical_peak_flops;
    if (run.theoretical_peak_flops && *run.theoretical_peak_flops > 0)
      row.fraction_of_theoretical = peak->flops / *run.theoretical_peak_flops;
    row.origin = run.provenance.origin;
    row.source_file = run.provenance.source_file;
    if (const DeviceSpec* spec = match_device(table, run.device, run.device_kind, run.platform)) {
      row.spec = *spec;
      row.fraction_of_spec = peak->flops / spec->fp32_peak_flops;
    }
    row.flags = check_flops(peak->flops, row.spec ? &*row.spec : nullptr, run.theoretical_peak_flops);
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace bs
