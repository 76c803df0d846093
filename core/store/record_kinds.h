// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The record kinds a workspace holds, each described ONCE (#52): its place in an import batch, how it is written
// and read back, its words, its section of the workspace tree and what becomes of it when a robot's job comes home.
// Code that handles "every kind" (storing an import, undoing a removal, a robot job's import, counting what an
// import brought, checking a workspace on opening) loops over for_each_record_kind() instead of naming the kinds, so
// a new kind is one descriptor here plus its own files: its model struct, its table (store/tables.h) and its
// write function (store/record_writes.h). Views that show a kind's own columns (a Sustained tab) stay per kind.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "store/import_batch.h"
#include "store/record_writes.h"
#include "store/workspace.h"

namespace bs {

// In the order an import's kinds are written, counted and listed.
enum class RecordKindId { Run, ResultSet, PowerLog, Frame, PipelineRun, InferenceRun, Headroom, SustainedRun };
inline constexpr std::size_t kRecordKindCount = 8;

// What happens to a kind's records when a robot's job comes home (core/remote/job_import.cpp): stamped with the
// robot's provenance and put under the platform name the user confirmed, or left on the robot with a warning (a
// frame's file stays where it was captured).
enum class FromRobot { Stamped, StaysOnRobot };

// The words and tree section of a kind, without its types (for code that only counts or names).
struct RecordKindWords {
  const char* one;      // "run", "power log": counts read "1 run, 2 power logs"
  const char* many;     // "runs", "power logs"
  const char* section;  // its section of the workspace tree, "Power logs"
};

template <class Item, class Stored, FromRobot Rule = FromRobot::Stamped>
struct RecordKind {
  static constexpr FromRobot from_robot = Rule;  // a type's property: the rule's code is compiled per kind
  RecordKindId id;
  RecordKindWords words;
  std::vector<Item> ImportBatch::*in_batch;        // its place in an import batch
  std::vector<Stored> (Workspace::*read)() const;  // every stored item, whole (a power log with its samples)
  std::vector<Stored> (Workspace::*list)() const;  // every stored item for listing (a power log's summary only)
  Item Stored::*item;                              // the record inside its stored row
  // Writes a batch's items of this kind inside the import's transaction (store/record_writes.h).
  void (*write)(store::ImportWrite&, const std::vector<Item>&);
};

// The kinds, a line each: id, words, batch vector, whole reader, listing reader, record in its row, writer.
// clang-format off
inline constexpr RecordKind<FlopsRun, StoredRun> kRunKind{RecordKindId::Run, {"run", "runs", "Runs"}, &ImportBatch::runs, &Workspace::runs, &Workspace::runs, &StoredRun::run, &store::write_runs};
inline constexpr RecordKind<ResultSet, StoredResultSet> kResultSetKind{RecordKindId::ResultSet, {"result set", "result sets", "Throughput results"}, &ImportBatch::result_sets, &Workspace::result_sets, &Workspace::result_sets, &StoredResultSet::set, &store::write_result_sets};
inline constexpr RecordKind<PowerTrace, StoredPowerTrace> kPowerLogKind{RecordKindId::PowerLog, {"power log", "power logs", "Power logs"}, &ImportBatch::power_traces, &Workspace::power_traces, &Workspace::power_trace_summaries, &StoredPowerTrace::trace, &store::write_power_logs};
inline constexpr RecordKind<Frame, StoredFrame, FromRobot::StaysOnRobot> kFrameKind{RecordKindId::Frame, {"frame", "frames", "Frames"}, &ImportBatch::frames, &Workspace::frames, &Workspace::frames, &StoredFrame::frame, &store::write_frames};
inline constexpr RecordKind<PipelineRun, StoredPipelineRun> kPipelineRunKind{RecordKindId::PipelineRun, {"pipeline run", "pipeline runs", "Pipeline runs"}, &ImportBatch::pipeline_runs, &Workspace::pipeline_runs, &Workspace::pipeline_runs, &StoredPipelineRun::run, &store::write_pipeline_runs};
inline constexpr RecordKind<DnnRun, StoredDnnRun> kInferenceRunKind{RecordKindId::InferenceRun, {"inference run", "inference runs", "Inference runs"}, &ImportBatch::dnn_runs, &Workspace::dnn_runs, &Workspace::dnn_runs, &StoredDnnRun::run, &store::write_inference_runs};
inline constexpr RecordKind<headroom::HeadroomMeasurement, StoredHeadroom> kHeadroomKind{RecordKindId::Headroom, {"headroom measurement", "headroom measurements", "Headroom measurements"}, &ImportBatch::headroom, &Workspace::headroom_measurements, &Workspace::headroom_measurements, &StoredHeadroom::measurement, &store::write_headroom};
inline constexpr RecordKind<SustainRun, StoredSustainRun> kSustainedRunKind{RecordKindId::SustainedRun, {"sustained run", "sustained runs", "Sustained runs"}, &ImportBatch::sustain_runs, &Workspace::sustain_runs, &Workspace::sustain_runs, &StoredSustainRun::run, &store::write_sustained_runs};
// clang-format on

// A kind's rule for robot jobs, for `if constexpr` in generic code.
template <class Kind>
inline constexpr FromRobot from_robot_v = std::remove_cvref_t<Kind>::from_robot;

template <class F>
void for_each_record_kind(F&& f) {
  f(kRunKind);
  f(kResultSetKind);
  f(kPowerLogKind);
  f(kFrameKind);
  f(kPipelineRunKind);
  f(kInferenceRunKind);
  f(kHeadroomKind);
  f(kSustainedRunKind);
}

const RecordKindWords& words_of(RecordKindId kind);

// How many records of each kind (what an import or a robot job brought).
struct RecordCounts {
  std::array<std::size_t, kRecordKindCount> n{};
  void add(const ImportBatch& batch);
  std::size_t operator[](RecordKindId kind) const { return n[static_cast<std::size_t>(kind)]; }
  std::size_t total() const;
  // "3 runs, 1 power log" in RecordKindId order; "nothing" when all are zero.
  std::string summary() const;
};

}  // namespace bs
