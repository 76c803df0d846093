// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The pixels of a frame stored in a workspace: a copy comes out of the workspace file; a reference is read again
// from its file, which must still have the content hash recorded at import (a changed or moved file is an error
// that names the path, never a silently different image).
#include "common/importer.h"
#include "store/workspace.h"

namespace bs {

// Returns `stored.frame` with its pixels. Throws ImportError (file missing, changed, unreadable) or
// WorkspaceError (damaged BLOB).
Frame load_frame(const Workspace& ws, const StoredFrame& stored, const CancelToken& cancel = CancelToken{},
                 const ImportLimits& limits = {});

}  // namespace bs
