// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The reprojection tuner's parameter set (lens + view + occluder masks) with an undo/redo history, and the files
// it reads and writes: the lens JSON (lens_to_json plus "masks") and the exported lookup table (docs/lut-format.md).
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "vision/lens/lens.h"

namespace bs::vision {

// One occluder (e.g. the robot's nose) as a closed polygon in fisheye source pixel coordinates.
using MaskPolygon = std::vector<cv::Point2f>;

struct TunerParams {
  Lens lens = Lens::paper();
  View view;
  std::vector<MaskPolygon> masks;
  bool operator==(const TunerParams& o) const;
};

// CV_8UC1 image of `size` with 255 inside every polygon (polygons with fewer than 3 points are ignored).
cv::Mat mask_image(const std::vector<MaskPolygon>& masks, cv::Size size);

nlohmann::json tuner_to_json(const TunerParams& p);
TunerParams tuner_from_json(const nlohmann::json& j);  // throws std::invalid_argument naming the field
void save_tuner_json(const TunerParams& p, const std::filesystem::path& path);
TunerParams load_tuner_json(const std::filesystem::path& path);  // throws std::runtime_error naming the file

// Undo/redo over TunerParams and the straight-line tool's picked lines (source pixels; kept beside the parameters,
// not in them: they are no part of the lens file, and Reset, rebase and loading a lens keep them). Every change
// names the field it edits; consecutive changes of the same field merge into one undo step (a slider drag is one
// step) until end_merge() is called (slider released, editing finished) or another field changes.
class TunerState {
 public:
  using Lines = std::vector<std::vector<cv::Point2d>>;  // line_fit.h's PickedLine
  explicit TunerState(TunerParams initial = {});
  const TunerParams& params() const { return current_.params; }
  const TunerParams& initial() const { return initial_; }
  const Lines& lines() const { return current_.lines; }

  // Returns false (and records nothing) when `p` equals the current parameters.
  bool set(const TunerParams& p, const std::string& field);
  // The same for the picked lines (the parameters stay).
  bool set_lines(const Lines& lines, const std::string& field);
  void end_merge() { merge_field_.clear(); }
  bool can_undo() const { return !undo_.empty(); }
  bool can_redo() const { return !redo_.empty(); }
  bool undo();
  bool redo();
  // Back to the initial parameters, as one undoable step.
  bool reset() { return set(initial_, "reset") && (end_merge(), true); }
  // A new baseline (e.g. a loaded file becomes what Reset returns to): clears the history; the lines stay.
  void rebase(const TunerParams& p);
  std::size_t undo_depth() const { return undo_.size(); }

 private:
  struct Snapshot {
    TunerParams params;
    Lines lines;
  };
  bool push(Snapshot next, const std::string& field);
  TunerParams initial_;
  Snapshot current_;
  std::vector<Snapshot> undo_, redo_;
  std::string merge_field_;
};

// Lookup-table export: a binary file with a JSON header, then the CV_32FC2 map (docs/lut-format.md).
void export_lut(const cv::Mat& map, const TunerParams& p, const std::filesystem::path& path);
// Reads it back, checking magic, header and sizes against the file size before allocating; `header` (optional)
// receives the JSON header. Throws std::runtime_error naming the file and the reason.
cv::Mat read_lut(const std::filesystem::path& path, nlohmann::json* header = nullptr);

}  // namespace bs::vision
