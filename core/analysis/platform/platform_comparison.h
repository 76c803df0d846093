// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One row per platform with what a lab weighs when choosing a robot computer: peak CPU and GPU FLOPS, power,
// GFLOPS/W, vision pipeline timings, energy per frame and battery runtime; and a recommendation under constraints
// (the paper's conclusion: under a 10 W budget the Jetson, otherwise the NUC). Every number keeps a note of where
// it came from, so a view can show its provenance.
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "analysis/peaks/flops.h"
#include "analysis/peaks/plausibility.h"
#include "analysis/stats/stats.h"
#include "model/pipeline_run.h"
#include "model/power_trace.h"

namespace bs {

// Where a number came from: the file, whether measured or reconstructed, and how it was derived.
struct CellSource {
  std::string source_file;
  DataOrigin origin = DataOrigin::Unknown;
  std::string how;  // "peak of NUC GPU / OpenCL / D=4 at 4096 workers", "mean of nuc-current.csv x 16 V", ...
};

// Per-stage timings of one platform's vision pipeline run (milliseconds), and the time window the run covered
// on the clock of the platform's power trace when known (for energy per frame).
struct PipelineTimings {
  std::string platform;
  Summary preprocess_ms;
  std::optional<Summary> detect_ms;
  std::optional<double> window_from_s, window_to_s;  // seconds from the trace's start
  std::size_t frames = 0;                            // frames processed in the window
  CellSource source;
};

// A stored pipeline run (seconds) as the comparison's timings (milliseconds): preprocess and detect stages, with
// min/max left NaN when the run does not know them (a published mean and SD). No time window: energy per frame
// then comes from the platform's mean power x the frame time. nullopt when the run has no preprocess stage.
std::optional<PipelineTimings> pipeline_timings(const PipelineRun& run);
// One entry per platform: the last run of each platform in `runs` (runs come from the workspace in import order
// within a platform, so a newer import replaces an older one).
std::vector<PipelineTimings> pipeline_timings(std::span<const PipelineRun> runs);

struct PlatformRow {
  std::string platform;
  std::optional<PeakRow> gpu, cpu;  // the highest-FLOPS run of each kind
  std::optional<double> mean_power_w, max_power_w;
  std::optional<double> gflops_per_watt_paper;  // best peak / (supply V x max current), as the paper defines it
  std::optional<double> gflops_per_watt_mean;   // best peak / mean power
  std::optional<Summary> preprocess_ms, detect_ms;
  std::optional<double> fps;                      // 1000 / (preprocess + detect) mean ms: stages in sequence
  std::optional<double> energy_per_frame_j;       // preprocessing (+ detection) of one frame
  std::optional<double> energy_per_preprocess_j;  // preprocessing of one frame alone: mean power x its mean time
  std::optional<double> energy_per_inference_j;   // one detection: mean power x the detection stage's mean time
  std::optional<double> battery_runtime_h;        // constant-power model at the mean power, or over the mission
  std::optional<double> battery_load_w;           // mean load on the pack: computer + parallel load (+ mission)
  // Frames preprocessed and detected per watt-hour of the computer: 3600 / energy per frame (J), i.e. the mean
  // power over (preprocessing + detection) mean time, or the time-aligned energy when the log covers the run.
  std::optional<double> frames_per_wh;
  std::map<std::string, CellSource> sources;  // column id -> where the number came from
  // Column id (platform_table_columns()) -> plausibility flags of that cell: the peaks' own, the power log's on
  // every power-derived column, and both on GFLOPS/W. A column without an entry is not flagged.
  std::map<std::string, std::vector<PlausibilityFlag>> flags;
  std::string power_measurement;  // how the power log was measured (measurement_text())
  // The power log the power columns come from (its label) and how many logs the platform has: with several, every
  // view says which one it uses (the platform's first log that gives power; the user's choice is put first,
  // store/decision_store.h).
  std::string power_log;
  int power_logs = 0;
  double best_peak_flops() const;
  // What the recommendation ranks by: the highest peak, where a peak that carries a plausibility flag counts at
  // most its device's vendor spec or computed peak (0 when neither is known), so an impossible figure (the paper's
  // NUC GPU at 6x its spec) never wins by its excess.
  double trusted_peak_flops() const;
  const PeakRow* best_peak() const;                 // the run behind best_peak_flops(), nullptr when none
  std::vector<PlausibilityFlag> all_flags() const;  // every column's, each once
};

struct ComparisonOptions {
  double battery_nominal_v = 14.8;  // the paper's 4S LiPo
  double battery_capacity_ah = 3.85;
  double usable_fraction = 1.0;
  double extra_load_w = 0;         // in parallel, e.g. servos
  std::optional<double> supply_v;  // overrides the traces' supply voltage
  // A mission profile (parse_mission() text, e.g. "idle:60:12,walk:30:140,kick:5:225": servo loads per phase) in
  // parallel with the computer's mean power and extra_load_w (platform_mission(), as the Battery tab); the runtime
  // is then simulate_discharge()'s with the constant-power model. Empty: the constant load alone.
  std::string mission;
};

// Column ids used in PlatformRow::sources and by the views.
namespace column {
inline constexpr const char* kGpuPeak = "gpu_peak";
inline constexpr const char* kCpuPeak = "cpu_peak";
inline constexpr const char* kPower = "power";
inline constexpr const char* kPipeline = "pipeline";
inline constexpr const char* kEnergyPerFrame = "energy_per_frame";
inline constexpr const char* kEnergyPerStage = "energy_per_stage";  // per preprocessed frame and per inference
inline constexpr const char* kBattery = "battery";
inline constexpr const char* kFramesPerWh = "frames_per_wh";
}  // namespace column

// Throws std::invalid_argument for a malformed options.mission.
std::vector<PlatformRow> compare_platforms(std::span<const FlopsRun> runs, std::span<const PowerTrace> traces,
                                           std::span<const PipelineTimings> pipelines,
                                           const ComparisonOptions& options = {});

// Energy of one frame from a power trace over the pipeline's window: trapezoidal energy in [from, to] / frames.
// nullopt when the trace has no power (and no supply voltage) or the window is outside the trace.
std::optional<double> energy_per_frame_j(const PowerTrace& trace, double from_s, double to_s, std::size_t frames,
                                         std::optional<double> supply_v = std::nullopt);

struct Constraints {
  // {} so that callers can name only the constraints they set ({.min_fps = 30}) without GCC's warning.
  std::optional<double> power_budget_w{};  // against the mean power
  std::optional<double> min_fps{};         // preprocessing + detection in sequence
  std::optional<double> min_runtime_h{};   // on the battery of ComparisonOptions
};

struct ConstraintCheck {
  std::string name;  // "power budget", "frame rate", "battery runtime"
  std::string unit;  // "W", "fps", "min"
  double required = 0;
  std::optional<double> actual;  // nullopt: the platform has no data for it (fails)
  bool met = false;
  double margin = 0;  // how far inside (+) or outside (-) the limit, in `unit`
  // A power budget against a mean: the share of the power log's samples above the budget (nullopt when the samples
  // are not known) and what kind of power was measured ("AC wall", "DC supply", "module rail"), so a mean just
  // under the budget is not read as a board that never exceeds it.
  std::optional<double> share_above{};
  std::size_t samples = 0;
  std::string power_kind{};
};

// Whether the check's limit is a ceiling ("at most": a power budget in W, a control-loop latency in us, a miss
// share in %, a run of misses in cycles, time spent throttled in a sustained run) rather than a floor ("at least":
// frame rate, battery runtime, a sustained run's stability in "% of best").
inline bool is_ceiling(const ConstraintCheck& k) {
  return k.unit == "W" || k.unit == "us" || k.unit == "%" || k.unit == "cycles" || k.unit == "s throttled";
}

// A failed or unknown check in a few words, for the lists of why a platform was not chosen: "p99 (pipeline@30fps)
// 812 us (612 us over)", "frame rate: no data", "control loop: load not applied: ...".
std::string unmet_text(const ConstraintCheck& k);

struct PlatformVerdict {
  std::string platform;
  bool meets_all = false;
  std::vector<ConstraintCheck> checks;
  bool recommended = false;  // the platform with the highest peak FLOPS among those that meet all constraints
  std::string note;          // why a platform that meets the constraints cannot be recommended, if so
  std::string ranking_note;  // how its compute was ranked when its best peak is flagged ("" otherwise)
  // The compute the ranking used (FLOP/s): the best peak, or where that is flagged as implausible the most its
  // device can deliver (spec or computed peak; analysis/peaks/plausibility.h), never the flagged figure itself.
  double ranked_flops = 0;
};

// Only platforms with a power log are candidates: a robot computer whose power draw is unknown cannot be judged
// against a battery (the paper's desktop reference machine is such a platform).
std::vector<PlatformVerdict> recommend(std::span<const PlatformRow> rows, const Constraints& constraints);

// A requirement judged per platform outside the comparison (the control loop, sustained performance) adds its
// checks to each verdict (`checks_of(platform)`; a check not met, or without a value, is not met), then the
// recommendation is made again: the most compute among the platforms that now meet everything.
void add_requirement_checks(std::vector<PlatformVerdict>& verdicts,
                            const std::function<std::vector<ConstraintCheck>(const std::string&)>& checks_of);

// The tightest relative margin (margin / required) among the checks that have a value, for ranking a
// requirement's verdicts; a limit of 0 counts 0 when met and -infinity when not; +infinity when none has a value.
double tightest_relative_margin(std::span<const ConstraintCheck> checks);

}  // namespace bs
