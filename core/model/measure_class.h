// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a result-set measurement measures: its kind (vector compute, matrix compute, memory bandwidth, transfer
// bandwidth, latency, ...) and, for compute, its number format (FP32, FP16, INT8, ...). Derived from the metric,
// the name and the unit, so clpeak 1.x ("Single-precision compute"), clpeak 2.x ("Half-precision compute
// fp16xfp16+fp16", "Cooperative-matrix fp8(E4M3)xfp8(E4M3)+fp32 16x16x16", "fdiv fp32 ST") and Google Benchmark
// counters all land in the same classes without a workspace schema change. Views pick a device's peak per class
// and never put two precisions in one column; the paper compares FP32 vector compute, the default everywhere.
#include <optional>
#include <string_view>

#include "model/flops_run.h"

namespace bs {

enum class Precision {
  Unknown,  // not stated, or not a compute measurement (bandwidth, latency)
  FP64,
  FP32,
  TF32,
  FP16,
  BF16,
  MixedFP16FP32,  // fp16 inputs, fp32 accumulation (clpeak "Mixed-precision compute")
  FP8,
  FP4,
  INT64,
  INT32,
  INT24,  // OpenCL mad24 ("Integer compute Fast 24bit")
  INT16,
  INT8,
  INT4,
};

enum class MeasureKind {
  VectorCompute,      // FMA/MAD chains on the ALUs: clpeak's "X-precision compute", the paper's kind of peak
  MatrixCompute,      // matrix engines, dot-product instructions, tuned BLAS (coopmat, WMMA, MFMA, XMX, DP4a)
  OtherCompute,       // divide / square root, atomics, crypto: not a peak of the ALUs
  MemoryBandwidth,    // device (global / DRAM) memory: the roofline's memory ceiling
  OnChipBandwidth,    // local / shared memory, caches, images, string scans
  TransferBandwidth,  // host <-> device copies and maps
  Latency,
  Other,
};

struct MeasureClass {
  MeasureKind kind = MeasureKind::Other;
  Precision precision = Precision::Unknown;
};

MeasureClass classify_measurement(std::string_view metric, std::string_view name, std::string_view unit);
inline MeasureClass classify_measurement(const Measurement& m) {
  return classify_measurement(m.metric, m.name, m.unit);
}

std::string_view to_string(Precision p);        // "fp32", "fp16", "mixed", "int8", "unknown", ...
std::string_view to_string(MeasureKind k);      // "vector-compute", "memory-bandwidth", ...
std::string_view precision_label(Precision p);  // "FP32 (single)", "FP16 (half)", "INT24", "unstated"
std::optional<Precision> precision_from_string(std::string_view text);  // to_string's names, also "single", "half"
bool is_compute(MeasureKind k);

}  // namespace bs
