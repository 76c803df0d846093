// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Which lens reprojects a stored frame, and how to name it (issue #32.1): the lens saved for the frame, else the
// one saved for its camera (store/lens_store.h), else the one recorded with the capture (sidecar), else the
// paper's lens. Every view that reprojects shows describe_lens_source() so the user knows which one it used.
#include <string>

#include "store/lens_store.h"
#include "store/workspace.h"
#include "vision/lens/lens.h"

namespace bs::vision {

struct ResolvedLens {
  enum class Source { SavedForFrame, SavedForCamera, Recorded, Paper };
  Lens lens;
  View view;
  Source source = Source::Paper;
  std::string camera;    // the frame's camera_key()
  std::string saved_at;  // for a saved lens
};

// `ws` may be null (no saved lenses). A saved lens that no longer parses or whose size is not the frame's is
// passed over (the next one in the order applies).
ResolvedLens resolve_frame_lens(const Workspace* ws, const StoredFrame& frame);
// The same order for a bare frame (no workspace): recorded, else the paper's.
ResolvedLens resolve_frame_lens(const Frame& frame);

// "saved for this frame", "saved for camera 1280x1024 BGGR", "recorded with the capture", "the paper's 195°
// equidistant lens (none recorded or saved)".
std::string describe_lens_source(const ResolvedLens& r);
// "equidistant, 195°, r_pp = 2.6589 mrad/px; obtained by checkerboard, 8 images, RMS 0.06 px"
std::string describe_lens(const Lens& lens);

}  // namespace bs::vision
