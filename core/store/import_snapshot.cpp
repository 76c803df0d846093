// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/import_snapshot.h"

#include <string>

namespace bs {

ImportSnapshot snapshot_import(const Workspace& ws, std::int64_t import_id) {
  ImportSnapshot out;
  bool found = false;
  for (const ImportRecord& r : ws.imports())
    if (r.id == import_id) {
      out.record = r;
      found = true;
    }
  if (!found)
    throw WorkspaceError(WorkspaceError::Kind::Constraint, ws.path() + ": no import #" + std::to_string(import_id));
  ImportBatch& b = out.batch;
  b.source_path = out.record.path;
  b.format = out.record.format;
  for (const StoredRun& s : ws.runs())
    if (s.import_id == import_id) b.runs.push_back(s.run);
  for (const StoredResultSet& s : ws.result_sets())
    if (s.import_id == import_id) b.result_sets.push_back(s.set);
  for (const StoredPowerTrace& s : ws.power_traces())
    if (s.import_id == import_id) b.power_traces.push_back(s.trace);
  for (const StoredPipelineRun& s : ws.pipeline_runs())
    if (s.import_id == import_id) b.pipeline_runs.push_back(s.run);
  // Inference runs and headroom measurements too: without them, undoing a removal lost them.
  for (const StoredDnnRun& s : ws.dnn_runs())
    if (s.import_id == import_id) b.dnn_runs.push_back(s.run);
  for (const StoredHeadroom& s : ws.headroom_measurements())
    if (s.import_id == import_id) b.headroom.push_back(s.measurement);
  for (const StoredSustainRun& s : ws.sustain_runs())
    if (s.import_id == import_id) b.sustain_runs.push_back(s.run);
  for (const StoredFrame& s : ws.frames()) {
    if (s.import_id != import_id) continue;
    Frame f = s.frame;
    if (f.storage == FrameStorage::Copy) f.pixels = ws.frame_pixels(s.id);
    // The workspace records a frame's file as the import's absolute path: give it back the path it had, not the
    // record's path as typed at import time (relative to a working directory that may have changed).
    b.source_path = s.path;
    b.frames.push_back(std::move(f));
  }
  return out;
}

std::int64_t restore_import(Workspace& ws, const ImportSnapshot& snapshot) {
  return ws.add_import(snapshot.batch, snapshot.record.content_hash);
}

}  // namespace bs
