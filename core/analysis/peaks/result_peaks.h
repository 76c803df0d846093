// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A device's peak from result sets (clpeak, Google Benchmark), one precision at a time: the measurement with the
// highest mean over its repetitions among those of the asked precision and kind. Never the best across precisions:
// a GPU's half2 rate is not its single-precision peak. The paper compares FP32 vector compute, the default.
#include <optional>
#include <span>
#include <vector>

#include "analysis/stats/stats.h"
#include "model/flops_run.h"
#include "model/measure_class.h"

namespace bs {

struct ResultPeak {
  const ResultSet* set = nullptr;
  const Measurement* measurement = nullptr;
  MeasureClass cls;
  Summary summary;  // mean, SD and n of the chosen measurement's repetitions
};

struct ResultPeakQuery {
  // One precision (FP32 unless asked), or nullopt for every precision and compute kind: then one row per
  // (result set, kind, precision), each labelled, never two precisions in one row.
  std::optional<Precision> precision = Precision::FP32;
  MeasureKind kind = MeasureKind::VectorCompute;  // with a precision: which kind of compute counts
};

std::vector<ResultPeak> result_peaks(std::span<const ResultSet> sets, const ResultPeakQuery& query = {});

// Compute measurements (FLOP/s or operations/s) of the sets that the query leaves out, to say so beside a table.
std::size_t compute_measurements_left_out(std::span<const ResultSet> sets, const ResultPeakQuery& query);

}  // namespace bs
