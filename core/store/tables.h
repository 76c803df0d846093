// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The stored entities, one description each (store/row_map.h): the workspace writes and reads every row through
// these, so a new entity is one description here plus its place in store/workspace.cpp's import and read.
#include <cstdint>
#include <vector>

#include "store/row_map.h"
#include "store/workspace.h"

namespace bs::store {

// One timing of a FLOPS run: its worker count, repetition index and seconds.
struct RunSampleRow {
  std::int64_t workers = 0;
  std::int64_t repetition = 0;
  double seconds = 0;
};

// Largest colour index, worker count, iteration count and dims the readers accept (the importers' own bounds).
inline constexpr std::int64_t kMaxColorIndex = 1 << 20;
inline constexpr std::int64_t kMaxWorkers = std::int64_t{1} << 40;
inline constexpr std::int64_t kMaxIterations = std::int64_t{1} << 40;
inline constexpr std::int64_t kMaxDims = 64;
inline constexpr std::int64_t kMaxFrames = std::int64_t{1} << 40;
inline constexpr std::int64_t kMaxFlops = std::int64_t{1} << 62;

const Table<ImportRecord>& imports_table();
const Table<DeviceRecord>& devices_table();      // read only: a device is inserted with its colour by SQL of its own
const Table<FlopsRun>& runs_table();             // keys: import_id, device_id
const Table<RunSampleRow>& run_samples_table();  // key: run_id
const Table<ResultSet>& result_sets_table();     // keys: import_id, device_id
const Table<Measurement>& measurements_table();  // key: result_set_id
const Table<StoredPowerTrace>& power_traces_table();  // key: import_id; metadata and summary, never samples
const Table<ChannelSummary>& power_channels_table();  // key: trace_id; name, quantity and cached summary
const Table<TracePhase>& power_phases_table();        // key: trace_id
const Table<StoredFrame>& frames_table();             // key: import_id; pixels written (copies), never read here
const Table<PipelineRun>& pipeline_runs_table();      // key: import_id
const Table<StageStats>& pipeline_stages_table();     // key: run_id
const Table<DnnRun>& dnn_runs_table();                // key: import_id
const Table<headroom::HeadroomMeasurement>& headroom_table();  // key: import_id; phases and threads as JSON
const Table<SustainRun>& sustain_table();  // key: import_id; intervals, clocks and temperatures as JSON

// A trace without its samples (what the power_traces row and its children describe).
PowerTrace trace_metadata(const PowerTrace& t);

}  // namespace bs::store
