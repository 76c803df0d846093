// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Candidates: a lab's own platforms beside published ones (the library), ranked under the same constraints and
// compared like with like only. Inference results fall into classes of the same network, scenario and precision;
// a platform is ranked only within its class (most inferences per second among those that meet every constraint),
// and what still differs inside a class (latency statistic, how power was measured, power setting, software) is
// said in the row. Compute peaks fall into classes of the same precision, with the kernel named in the row. Every
// row carries its origin (measured, reconstructed, published) and its source.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "analysis/library/library.h"
#include "analysis/platform/platform_comparison.h"
#include "headroom/loop_requirement.h"
#include "model/dnn_run.h"
#include "model/flops_run.h"
#include "model/pipeline_run.h"
#include "sustain/sustain_requirement.h"
#include "util/table_export.h"

namespace bs {

struct Candidate {
  std::string platform;
  DataOrigin origin = DataOrigin::Unknown;
  std::string network, scenario, precision;  // the class
  std::optional<double> latency_s;
  std::string latency_statistic;  // "p90", "mean of 20 frames", ...
  std::optional<double> throughput_per_s;
  std::string throughput_statistic;
  std::optional<double> power_w;
  std::string power_how;     // "external meter (SPEC PTDaemon), wall power", "mean of nuc-current.csv x 16 V", ...
  std::string power_kind{};  // power_kind_of(): "AC wall", "DC supply", "module rail", "not stated"
  std::vector<double> power_samples_w{};  // the samples behind power_w, when known (share above a budget)
  std::optional<double> energy_per_inference_j;
  std::optional<double> battery_runtime_h;
  std::string conditions;  // power setting, clocks, cooling, round
  std::string software;
  std::string source;      // URL (published) or file (own)
  std::string difference;  // what still differs from the class's first row; "" for that row
  std::vector<PlausibilityFlag> flags;
  std::vector<ConstraintCheck> checks;
  bool meets_all = false;
  bool recommended = false;  // the most inferences per second among the class's rows that meet every constraint
  std::string not_ranked{};  // why this row is listed but never ranked (one run of one image); "" when ranked
  std::string framework{};   // framework_of() its software ("TensorRT", "TensorFlow"); "" when nothing says
};

// A precision "not stated" says nothing about the arithmetic: such rows are ranked only with rows of the same
// framework (a TensorRT run of unknown precision is likely INT8, a TensorFlow one FP32), and a row whose framework is
// not stated either forms a class of its own. A stated precision is never in a class with "not stated".
struct CandidateClass {
  std::string network, scenario, precision;
  std::string framework{};      // only for precision "not stated": the framework the class shares
  std::vector<Candidate> rows;  // ranked: constraints met first, then by throughput; rows not ranked last
  std::string note{};           // why the class has no pick although rows meet the constraints, or ""
  std::string title() const;  // "resnet50, SingleStream, int8"; "ssd-mobilenet, SingleStream, not stated (TensorFlow)"
};

struct PeakCandidate {
  std::string platform;
  DataOrigin origin = DataOrigin::Unknown;
  std::string device, kernel, precision;  // kernel: "rotation2d (BenchScope)", "clpeak Single-precision compute"
  double flops = 0;
  std::optional<double> power_w;
  std::optional<double> flops_per_watt;
  std::string source, difference;
  std::vector<PlausibilityFlag> flags;
};

struct PeakClass {
  std::string precision;
  std::vector<PeakCandidate> rows;  // by FLOPS, highest first
};

struct CandidateInputs {
  std::span<const PlatformRow> platforms;     // own: peaks, power, pipeline (compare_platforms())
  std::span<const PipelineRun> pipelines;     // own: the detection stage as an inference result
  std::span<const DnnRun> dnn_runs;           // own: bench dnn
  std::span<const ResultSet> result_sets;     // own: imported MLPerf LoadGen results (source_format mlperf-loadgen)
  std::vector<const LibraryResult*> library;  // published
  const Library* lib = nullptr;               // names of library computers
  // With a control-loop requirement: its verdicts, whose checks join every row's (a published row has none: its
  // loop is unknown and it never passes), so that no class picks a row the Platforms verdict would reject.
  const std::vector<headroom::LoopVerdict>* loop = nullptr;
  // With a sustained requirement: its verdicts, the same way (a published row has no sustained run: unknown).
  const std::vector<sustain::SustainVerdict>* sustained = nullptr;
};

// The network names of all sources in one spelling: "resnet"/"ResNet-50" -> "resnet50"; "ssd-small"/
// "mobilenet-ssd"/"ssd_mobilenet" -> "ssd-mobilenet"; anything else lowercased.
std::string canonical_network(std::string_view name);

// The inference framework a software description names ("TensorRT 8.5.2, CUDA 11.4" -> "TensorRT", "SSD MobileNet
// (TensorFlow, MS COCO)" -> "TensorFlow", "tflite-v2.11.0-ruy" -> "TFLite"); "" when it names none BenchScope knows.
std::string framework_of(std::string_view software);

std::vector<CandidateClass> rank_candidates(const CandidateInputs& in, const Constraints& constraints,
                                            const ComparisonOptions& options = {});
std::vector<PeakClass> peak_candidates(const CandidateInputs& in);

// One table each, shared by the CLI, the Platforms view's export and the report: a "Class" column first, then
// Rank, Platform, Origin, Latency (ms), Throughput (1/s), Power (W), Energy per inference (mJ), Battery (h), Meets
// constraints, Differences and conditions, Source; flags as footnotes.
ExportTable candidates_table(std::span<const CandidateClass> classes, bool with_verdicts);
ExportTable peak_candidates_table(std::span<const PeakClass> classes);

// What kind of power a row's "how" describes, so that a budget never compares unlike watts silently: "AC wall"
// (a PTDaemon meter at the plug, MLPerf's power), "module rail" (on-board sensors: tegrastats, jtop, RAPL,
// nvidia-smi), "DC supply" (the computer's supply current x voltage), else "not stated".
std::string power_kind_of(std::string_view how);

// The origin as a row shows it: "measured", "reconstructed", "published" (never blank: "unknown").
std::string origin_label(DataOrigin origin);

}  // namespace bs
