// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "analysis/peaks/device_table.h"
#include "analysis/peaks/plausibility.h"
#include "analysis/stats/stats.h"
#include "model/flops_run.h"

namespace bs {

// Counted floating-point operations of the rotation kernel: 6 per 2D point per iteration (4 mul + 2 add). The
// paper leaves out the (2D - 1) * W flops of the final dot product, and so do we, to stay comparable.
double rotation_flop_count(int dims, std::int64_t iterations, std::int64_t workers) noexcept;

// FLOPS = 6 * D * N * W / t.
double rotation_flops(int dims, std::int64_t iterations, std::int64_t workers, double seconds) noexcept;

// FLOPS at one worker count over its repetitions: each repetition gives 6DNW/t_i; mean and SD are over those.
// A point with stated_flops (a sweep derived from another tool) gives those instead.
struct CurvePoint {
  std::int64_t workers = 0;
  Summary flops;
};
std::vector<CurvePoint> flops_curve(const FlopsRun& run);

// The highest mean FLOPS of a run and where it occurs. Ties go to the fewest workers.
struct Peak {
  double flops = 0;
  std::int64_t workers = 0;
  Summary at_peak;  // the repetitions at the peak worker count
};
std::optional<Peak> find_peak(const FlopsRun& run);  // nullopt for a run without samples

// One row of the peak table (paper Tables 1 and 2, plus what BenchScope adds).
struct PeakRow {
  std::string platform, device, backend, variant;
  DeviceKind device_kind = DeviceKind::Other;
  int dims = 0;
  std::int64_t iterations = 0;
  Peak peak;
  std::optional<double> reported_flops;
  std::optional<double> ratio_to_reported;  // peak / reported
  std::optional<double> theoretical_flops;
  std::optional<double> fraction_of_theoretical;  // peak / theoretical
  DataOrigin origin = DataOrigin::Unknown;
  std::string source_file;
  // The device table's entry for this device (match_device()), when there is one.
  std::optional<DeviceSpec> spec;
  std::optional<double> fraction_of_spec;  // peak / spec FP32 peak
  std::vector<PlausibilityFlag> flags;     // check_flops() of the peak; empty: plausible (or nothing to check)
  // The device's measured rotation-mix ceiling (apply_empirical_ceilings(), analysis/peak_ceilings.h), when the
  // workspace has one, and the peak as a fraction of it.
  std::optional<double> empirical_ceiling_flops;
  std::optional<double> fraction_of_ceiling;
  std::string ceiling_how;
  std::size_t run_index = 0;  // which of the runs given to peak_table() this row is (runs without a peak are skipped)
};
// Rows in input order; runs without samples are skipped. Each row is checked against the bundled device table
// (bundled_device_table()); when that cannot be loaded every row carries a spec_check_unavailable flag.
std::vector<PeakRow> peak_table(std::span<const FlopsRun> runs);
// The same against a given table.
std::vector<PeakRow> peak_table(std::span<const FlopsRun> runs, const DeviceTable& table);

}  // namespace bs
