// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// FLOPS-vs-workers sweeps inside another tool's results. A Google Benchmark family such as BM_Rotation/threads:N
// or BM_X/4096/real_time swept over an argument is the same curve as BenchScope's own runs: this turns each
// family's FLOP/s counter into a FlopsRun (kernel "google-benchmark") whose points carry the FLOPS the file states,
// so the FLOPS view and the peak table treat it like any run. Derived on load from the stored ResultSet, never
// stored itself. The FLOPS of a point follows BenchScope's one definition: the mean over repetitions with n and
// SD (Google Benchmark's _mean / _stddev aggregates when the file has them, else over the repetitions), never the
// best repetition.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "model/flops_run.h"

namespace bs {

inline constexpr std::string_view kForeignSweepKernel = "google-benchmark";
// Provenance::settings key naming where the worker count comes from: "threads" (the name's threads:N segment,
// 1 when absent, as Google Benchmark runs one thread unless told) or "argument K" (the K-th argument, 0-based).
inline constexpr std::string_view kWorkersFromSetting = "workers from";

// Where the worker count is read: nullopt = the threads:N segment; K = the K-th argument of the name.
using WorkersArgument = std::optional<int>;
WorkersArgument workers_argument(const Provenance& provenance);  // from kWorkersFromSetting
std::string workers_from_text(const WorkersArgument& argument);  // "threads" or "argument K"

// A benchmark name split into its sweep: the family (the name without the worker segment, which an argument
// leaves as "*") and the worker count. nullopt when the name has no such argument or it is not an integer >= 1.
// Arguments are the segments after the function name other than Google Benchmark's own options (min_time:,
// min_warmup_time:, iterations:, repeats:, threads:, real_time, process_time, manual_time); "size:4096" (named
// arguments) counts as an argument with value 4096.
struct SweepPoint {
  std::string family;
  std::int64_t workers = 0;
};
std::optional<SweepPoint> sweep_point(std::string_view run_name, const WorkersArgument& argument);

// The mean, SD, n and range of a measurement by BenchScope's definition (see above). nullopt when it holds no
// finite value. n comes from the ("repetitions", n) aggregate when the file states it.
std::optional<StatedFlops> summarize_measurement(const Measurement& m);

// Whether foreign_sweeps() turns this measurement into a sweep point (a FLOP/s counter of a Google Benchmark set
// whose name yields a worker count).
bool is_swept(const ResultSet& set, const Measurement& m);

// One run per (family, FLOP/s counter), points ascending by workers. Empty for sets of other formats.
std::vector<FlopsRun> foreign_sweeps(const ResultSet& set);
std::vector<FlopsRun> foreign_sweeps(std::span<const ResultSet> sets);

// Whether a run is such a derived sweep (its points carry stated FLOPS, not timings).
bool is_foreign_sweep(const FlopsRun& run);

}  // namespace bs
