// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Lenses the user saved in the workspace (schema 8, table `lenses`): one for a single frame, or one for every frame
// of a camera. A frame's lens is, in this order: its own saved lens, its camera's saved lens, the lens recorded
// with the capture (sidecar), the paper's lens. The store keeps the lens as JSON (vision::lens_to_json: lens +
// view + how it was calibrated) so it builds without OpenCV; core/vision reads it.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "store/workspace.h"

namespace bs {

struct SavedLens {
  std::int64_t frame_id = 0;  // > 0: this frame's own lens
  std::string camera;         // non-empty: every frame of this camera (camera_key)
  std::string lens_json;      // vision::lens_to_json(lens, view).dump()
  std::string obtained;       // how it was obtained, one line (vision::describe of its calibration)
  std::string saved_at;       // ISO 8601 UTC, set by save_lens
  bool for_camera() const { return frame_id == 0; }
};

// The camera a frame came from, as far as a workspace can tell: its size and mosaic ("1280x1024 BGGR"). Frames of
// one camera share both; a lens calibrated on one of them fits the others.
std::string camera_key(const Frame& frame);

// Saves (replacing any lens of the same frame or camera). Throws WorkspaceError(Constraint) when neither or both of
// frame_id and camera are given, for an unknown frame, or for empty lens JSON.
void save_lens(Workspace& ws, SavedLens lens);
// Removes the frame's (frame_id > 0) or the camera's lens; no-op when there is none.
void remove_lens(Workspace& ws, std::int64_t frame_id, const std::string& camera);
std::optional<SavedLens> find_lens(const Workspace& ws, std::int64_t frame_id, const std::string& camera);
std::vector<SavedLens> saved_lenses(const Workspace& ws);  // frames' first (by frame id), then cameras' (by name)
// The saved lens that applies to `frame`: its own, else its camera's; nullopt when neither was saved.
std::optional<SavedLens> saved_lens_for(const Workspace& ws, const StoredFrame& frame);

}  // namespace bs
