// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/import_snapshot.h"

#include <string>

#include "store/record_kinds.h"

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
  // Every kind's records of the import (frames below: their pixels and file need more than the record).
  for_each_record_kind([&](const auto& kind) {
    if (kind.id == RecordKindId::Frame) return;
    for (auto& stored : (ws.*kind.read)())
      if (stored.import_id == import_id) (b.*kind.in_batch).push_back(std::move(stored.*kind.item));
  });
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
