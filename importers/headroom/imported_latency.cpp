// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/imported_latency.h"

#include "common/import_error.h"

namespace bs::headroom_import {

headroom::ThreadLatency summary_only_thread(int index, std::optional<std::uint64_t> cycles,
                                            std::optional<std::int64_t> min_ns, std::optional<std::int64_t> max_ns,
                                            std::optional<double> mean_ns, std::optional<double> sd_ns) {
  headroom::ThreadLatency t;
  t.index = index;
  t.histogram.bins.clear();
  t.histogram.cycles = cycles.value_or(0);
  t.histogram.overflows = t.histogram.cycles;
  t.histogram.min_ns = min_ns;
  t.histogram.max_ns = max_ns;
  t.mean_ns = mean_ns;
  t.sd_ns = sd_ns;
  return t;
}

bool summary_only(const headroom::ThreadLatency& thread) { return thread.histogram.bins.empty(); }

headroom::HeadroomMeasurement imported_measurement(headroom::LatencyKind kind, std::string tool,
                                                   const std::string& file) {
  headroom::HeadroomMeasurement m;
  m.kind = kind;
  m.tool = std::move(tool);
  m.provenance.origin = DataOrigin::Measured;
  m.provenance.tool = m.tool;
  m.provenance.source_file = file;
  headroom::Phase phase;
  phase.name = std::string(kImportedPhase);
  phase.load = headroom::LoadKind::Unknown;
  m.phases.push_back(std::move(phase));
  return m;
}

ImportBatch batch_of(headroom::HeadroomMeasurement m, const std::string& file) {
  if (const std::string e = m.bookkeeping_error(); !e.empty())
    throw ImportError(ImportErrorCategory::InvalidValue, {file, 0, 0, {}}, "inconsistent latency counts: " + e);
  ImportBatch batch;
  batch.headroom.push_back(std::move(m));
  return batch;
}

}  // namespace bs::headroom_import
