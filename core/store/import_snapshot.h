// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Everything one import brought, read back from the workspace, so that removing it can be undone: restoring adds
// the same content under the same content hash (new ids; the items, their labels and their pixels are the same).
#include <cstdint>

#include "store/import_batch.h"
#include "store/workspace.h"

namespace bs {

struct ImportSnapshot {
  ImportRecord record;
  ImportBatch batch;  // frames stored as copies carry their pixels; frames kept by reference their path
};

// Throws WorkspaceError(Constraint) for an unknown import id.
ImportSnapshot snapshot_import(const Workspace& ws, std::int64_t import_id);
// Adds the snapshot back as one import (one transaction) and returns its new id.
std::int64_t restore_import(Workspace& ws, const ImportSnapshot& snapshot);

}  // namespace bs
