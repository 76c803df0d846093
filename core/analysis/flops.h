// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "analysis/stats.h"
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
  std::optional<double> ratio_to_reported;       // peak / reported
  std::optional<double> theoretical_flops;
  std::optional<double> fraction_of_theoretical;  // peak / theoretical
  DataOrigin origin = DataOrigin::Unknown;
  std::string source_file;
};
// Rows in input order; runs without samples are skipped.
std::vector<PeakRow> peak_table(std::span<const FlopsRun> runs);

}  // namespace bs
