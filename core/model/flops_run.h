// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/provenance.h"

namespace bs {

enum class DeviceKind { Other, Cpu, Gpu };
std::string_view to_string(DeviceKind kind);                // "cpu", "gpu", "other"
DeviceKind device_kind_from_string(std::string_view text);  // unknown -> Other

// FLOP/s at one worker count as another tool states it (a Google Benchmark FLOPS counter): mean over n
// repetitions, their SD (0 for n = 1) and range (min = max = mean when only aggregates were reported).
struct StatedFlops {
  std::size_t n = 0;
  double mean = 0, sd = 0, min = 0, max = 0;
};

// All repeated timings of one worker count: seconds for the whole sweep point (all workers, all iterations).
struct WorkerSample {
  std::int64_t workers = 0;
  std::vector<double> seconds;  // one entry per repetition, each > 0
  // Set only on sweeps derived from another tool's results (analysis/foreign_sweeps.h), whose flop count per
  // point is unknown: then `seconds` is empty and this is the point's FLOPS. Never stored: the workspace keeps the
  // tool's ResultSet and derives the sweep again on load.
  std::optional<StatedFlops> stated_flops{};
};

// One FLOPS-vs-workers sweep of the paper's rotation kernel (or a kernel with the same flop accounting) on one
// device and backend. FLOPS at a point = 6 * dims * iterations * workers / seconds (paper, section 5.1).
// A sweep derived from another tool (kernel "google-benchmark") has iterations = dims = 0 (not stated) and its
// points carry stated_flops instead.
struct FlopsRun {
  std::string platform;  // the computer: "NUC", "Jetson TX2", "Desktop (Alienware Area-51)"
  std::string device;    // the compute device: "NUC GPU", "GTX1080Ti", "i7-7800X"
  DeviceKind device_kind = DeviceKind::Other;
  std::string backend;  // "OpenCL", "CUDA", "CPU SIMD (AVX2)", "CPU scalar", ...
  std::string kernel = "rotation2d";
  std::string variant = "paper";                 // "paper" (faithful) or a named throughput variant, e.g. "float16x4"
  std::int64_t iterations = 40000;               // N
  int dims = 1;                                  // D: 2D points rotated per worker (1, 2 or 4 in the paper)
  std::vector<WorkerSample> samples;             // ascending by workers, unique worker counts
  std::optional<double> reported_peak_flops;     // literature / vendor figure, FLOP/s
  std::optional<double> theoretical_peak_flops;  // this kernel's peak on this device, FLOP/s
  Provenance provenance;
};

// A single named measurement with its repetitions, in SI units (seconds, FLOP/s, B/s, 1/s).
struct Measurement {
  std::string name;            // "BM_Rotate/4096", or the clpeak variant "float4"
  std::string metric;          // "real_time", "cpu_time", a user counter name, "single-precision compute", ...
  std::string unit;            // "s", "FLOP/s", "B/s", "1/s" or "" for dimensionless
  std::vector<double> values;  // one per repetition
  // Aggregates as the source reported them (Google Benchmark's mean/median/stddev/cv rows), keyed by name, plus
  // ("repetitions", n) when the source states how many repetitions its aggregates summarise.
  std::vector<std::pair<std::string, double>> reported_aggregates;
};

// Results of a generic benchmark tool (Google Benchmark JSON, clpeak) for one device.
struct ResultSet {
  std::string platform;
  std::string device;
  DeviceKind device_kind = DeviceKind::Other;
  std::string backend;        // "OpenCL" for clpeak, "CPU" / library name for Google Benchmark
  std::string source_format;  // importer id: "google-benchmark-json", "clpeak-text"
  std::vector<Measurement> measurements;
  Provenance provenance;
};

}  // namespace bs
