// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/workspace_lens.h"

#include <cstdio>
#include <nlohmann/json.hpp>

#include "vision/frames/frame_image.h"

namespace bs::vision {
namespace {

bool fits(const SavedLens& s, const Frame& f, ResolvedLens& out) {
  try {
    auto [lens, view] = lens_from_json(nlohmann::json::parse(s.lens_json));
    if (lens.width != f.width || lens.height != f.height) return false;
    out.lens = lens;
    out.view = view;
    out.saved_at = s.saved_at;
    return true;
  } catch (const std::exception&) {
    return false;  // damaged JSON: the next lens in the order applies, as for a damaged sidecar
  }
}

}  // namespace

ResolvedLens resolve_frame_lens(const Frame& frame) {
  ResolvedLens out;
  const FrameLens fl = lens_for_frame(frame);
  out.lens = fl.lens;
  out.view = fl.view;
  out.source = fl.from_frame ? ResolvedLens::Source::Recorded : ResolvedLens::Source::Paper;
  out.camera = camera_key(frame);
  return out;
}

ResolvedLens resolve_frame_lens(const Workspace* ws, const StoredFrame& frame) {
  ResolvedLens out;
  out.camera = camera_key(frame.frame);
  if (ws) {
    if (const auto own = find_lens(*ws, frame.id, {}); own && fits(*own, frame.frame, out)) {
      out.source = ResolvedLens::Source::SavedForFrame;
      return out;
    }
    if (const auto cam = find_lens(*ws, 0, out.camera); cam && fits(*cam, frame.frame, out)) {
      out.source = ResolvedLens::Source::SavedForCamera;
      return out;
    }
  }
  return resolve_frame_lens(frame.frame);
}

std::string describe_lens_source(const ResolvedLens& r) {
  switch (r.source) {
    case ResolvedLens::Source::SavedForFrame:
      return "saved for this frame";
    case ResolvedLens::Source::SavedForCamera:
      return "saved for camera " + r.camera;
    case ResolvedLens::Source::Recorded:
      return "recorded with the capture";
    case ResolvedLens::Source::Paper:
      break;
  }
  return "the paper's 195° equidistant lens (none recorded or saved)";
}

std::string describe_lens(const Lens& lens) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "%s, %.4g°, r_pp = %.4f mrad/px; obtained by ",
                std::string(to_string(lens.type)).c_str(), lens.fov_deg, lens.r_pp * 1000);
  return buf + describe(lens.calibration);
}

}  // namespace bs::vision
