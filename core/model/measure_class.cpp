// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/measure_class.h"
#include "util/enum_words.h"
#include "util/text.h"

#include <array>
#include <cctype>
#include <string>
#include <utility>

namespace bs {
namespace {

bool has(const std::string& text, std::string_view word) { return text.find(word) != std::string::npos; }

template <std::size_t N>
bool has_any(const std::string& text, const std::array<std::string_view, N>& words) {
  for (std::string_view w : words)
    if (has(text, w)) return true;
  return false;
}

// Tokens that name one number format. The leftmost in a title wins: "Cooperative-matrix fp16xfp16+fp32" has fp16
// inputs, "Mixed-precision compute fp16xfp16+fp32" says mixed first, "Half-precision compute fp16xfp16+fp16" half.
constexpr std::array<std::pair<std::string_view, Precision>, 33> kSpecific{{
    {"mixed", Precision::MixedFP16FP32},
    {"bf16", Precision::BF16},
    {"tf32", Precision::TF32},
    {"fp8", Precision::FP8},
    {"e4m3", Precision::FP8},
    {"e5m2", Precision::FP8},
    {"mxf4", Precision::FP4},
    {"nvf4", Precision::FP4},
    {"e2m1", Precision::FP4},
    {"fp4", Precision::FP4},
    {"half", Precision::FP16},
    {"fp16", Precision::FP16},
    {"single", Precision::FP32},
    {"fp32", Precision::FP32},
    {"sgemm", Precision::FP32},
    {"double", Precision::FP64},
    {"fp64", Precision::FP64},
    {"dgemm", Precision::FP64},
    {"int4", Precision::INT4},
    {"int8", Precision::INT8},
    {"char", Precision::INT8},
    {"8bit", Precision::INT8},
    {"8-bit", Precision::INT8},
    {"dp4a", Precision::INT8},
    {"int16", Precision::INT16},
    {"short", Precision::INT16},
    {"16bit", Precision::INT16},
    {"24bit", Precision::INT24},
    {"24-bit", Precision::INT24},
    {"mad24", Precision::INT24},
    {"int64", Precision::INT64},
    {"u64", Precision::INT64},
    {"int32", Precision::INT32},
}};
// Words that imply a default format when nothing more specific is said ("Integer compute", "float4").
constexpr std::array<std::pair<std::string_view, Precision>, 3> kGeneric{{
    {"integer", Precision::INT32},
    {"imad", Precision::INT32},
    {"float", Precision::FP32},
}};

template <std::size_t N>
Precision leftmost(const std::string& text, const std::array<std::pair<std::string_view, Precision>, N>& table) {
  std::size_t best_at = std::string::npos;
  Precision best = Precision::Unknown;
  for (const auto& [word, p] : table) {
    const std::size_t at = text.find(word);
    if (at < best_at) {
      best_at = at;
      best = p;
    }
  }
  return best;
}

Precision precision_of(const std::string& metric, const std::string& name) {
  for (const std::string* text : {&metric, &name}) {
    if (Precision p = leftmost(*text, kSpecific); p != Precision::Unknown) return p;
    if (Precision p = leftmost(*text, kGeneric); p != Precision::Unknown) return p;
  }
  return Precision::Unknown;
}

}  // namespace

MeasureClass classify_measurement(std::string_view metric_text, std::string_view name_text, std::string_view unit) {
  const std::string metric = lower(metric_text);
  const std::string name = lower(name_text);
  MeasureClass c;
  if (unit == "s" || has(metric, "latency")) {
    c.kind = MeasureKind::Latency;
    return c;
  }
  if (unit == "B/s" || has(metric, "bandwidth")) {
    if (has(metric, "transfer")) {
      c.kind = MeasureKind::TransferBandwidth;
    } else if (has_any(metric, std::array<std::string_view, 9>{"local", "shared", "l1", "l2", "l3", "cache", "image",
                                                               "string", "scan"})) {
      c.kind = MeasureKind::OnChipBandwidth;
    } else {
      c.kind = MeasureKind::MemoryBandwidth;  // global memory, DRAM, STREAM triad, a benchmark's bytes/s
    }
    return c;
  }
  // A FLOP rate is compute; an operation rate (1/s) only when the metric says so, since a benchmark's
  // items_per_second is a rate of something else.
  const bool says_compute = has(metric, "compute") || has(metric, "throughput") || has(metric, "ops");
  if (unit != "FLOP/s" && !says_compute) return c;
  if (has_any(metric, std::array<std::string_view, 11>{"matrix", "coopmat", "wmma", "mfma", "xmx", "dot-product",
                                                       "blas", "gemm", "tensor", "simdgroup", "smfmac"})) {
    c.kind = MeasureKind::MatrixCompute;
  } else if (has_any(metric, std::array<std::string_view, 8>{"divide", "sqrt", "atomic", "crypto", "aes", "sha", "crc",
                                                             "transcend"})) {
    c.kind = MeasureKind::OtherCompute;
  } else {
    c.kind = MeasureKind::VectorCompute;
  }
  c.precision = precision_of(metric, name);
  return c;
}

namespace {

// The words files, the CLI and the views name a precision by. The aliases come after the canonical word: word_of
// gives a value's first word, parse_word reads all of them.
constexpr EnumWord<Precision> kPrecisionWords[] = {
    {Precision::Unknown, "unknown"},     {Precision::FP64, "fp64"},   {Precision::FP32, "fp32"},
    {Precision::TF32, "tf32"},           {Precision::FP16, "fp16"},   {Precision::BF16, "bf16"},
    {Precision::MixedFP16FP32, "mixed"}, {Precision::FP8, "fp8"},     {Precision::FP4, "fp4"},
    {Precision::INT64, "int64"},         {Precision::INT32, "int32"}, {Precision::INT24, "int24"},
    {Precision::INT16, "int16"},         {Precision::INT8, "int8"},   {Precision::INT4, "int4"},
    {Precision::FP32, "single"},         {Precision::FP64, "double"}, {Precision::FP16, "half"}};
static_assert(names_every_value(kPrecisionWords, Precision::INT4));
// The labels of tables and charts.
constexpr EnumWord<Precision> kPrecisionLabels[] = {{Precision::Unknown, "unstated"},
                                                    {Precision::FP64, "FP64 (double)"},
                                                    {Precision::FP32, "FP32 (single)"},
                                                    {Precision::TF32, "TF32"},
                                                    {Precision::FP16, "FP16 (half)"},
                                                    {Precision::BF16, "BF16"},
                                                    {Precision::MixedFP16FP32, "FP16 x FP16 + FP32 (mixed)"},
                                                    {Precision::FP8, "FP8"},
                                                    {Precision::FP4, "FP4"},
                                                    {Precision::INT64, "INT64"},
                                                    {Precision::INT32, "INT32"},
                                                    {Precision::INT24, "INT24"},
                                                    {Precision::INT16, "INT16"},
                                                    {Precision::INT8, "INT8"},
                                                    {Precision::INT4, "INT4"}};
static_assert(names_every_value(kPrecisionLabels, Precision::INT4));
constexpr EnumWord<MeasureKind> kMeasureKindWords[] = {{MeasureKind::VectorCompute, "vector-compute"},
                                                       {MeasureKind::MatrixCompute, "matrix-compute"},
                                                       {MeasureKind::OtherCompute, "other-compute"},
                                                       {MeasureKind::MemoryBandwidth, "memory-bandwidth"},
                                                       {MeasureKind::OnChipBandwidth, "on-chip-bandwidth"},
                                                       {MeasureKind::TransferBandwidth, "transfer-bandwidth"},
                                                       {MeasureKind::Latency, "latency"},
                                                       {MeasureKind::Other, "other"}};
static_assert(names_every_value(kMeasureKindWords, MeasureKind::Other));

}  // namespace

std::string_view to_string(Precision p) { return word_of(kPrecisionWords, p, "unknown"); }

std::string_view precision_label(Precision p) { return word_of(kPrecisionLabels, p, ""); }

std::string_view to_string(MeasureKind k) { return word_of(kMeasureKindWords, k, "other"); }

std::optional<Precision> precision_from_string(std::string_view text) {
  return parse_word(kPrecisionWords, lower(text));
}

bool is_compute(MeasureKind k) {
  return k == MeasureKind::VectorCompute || k == MeasureKind::MatrixCompute || k == MeasureKind::OtherCompute;
}

}  // namespace bs
