// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Line proposals for straight-line ("plumb-line") lens refinement: long edges of a fisheye frame that are
// candidates for lines straight in the world, as point lists of the same form as the Lens tab's clicks
// (line_fit.h's PickedLine, source pixels), so that fit_lens_to_lines can take them instead of clicks.
//
// How (all in source pixels, then in the current lens's rays):
//  1. gray, normalised between the dark surround and the bright level; the lit disc (convex hull of the lit
//     region) shrunk by a margin, so the image circle's own rim is never an edge;
//  2. Canny on a Gaussian-blurred copy, each edge pixel moved sub-pixel along its gradient (parabola through the
//     gradient magnitude), edge pixels chained end to end (straightest continuation at junctions);
//  3. chains split where they turn sharply (corners, crossings of dark lines);
//  4. each piece, as rays of the current lens, gets a robust fit (RANSAC over 3-point planes, then least squares
//     on the inliers) of a plane n.v = d: d = 0 is a line straight in the world (a great circle of rays); a small
//     d is allowed, so a line still bends a little where the current lens is off. The longest run of inliers is
//     kept, the rest tried again; pieces on one plane are merged across gaps (a line cut by crossing lines);
//  5. a second pass refits every merged line and drops its outlier points (iteratively, 3 robust sigmas, at least
//     `inlier_px`), so one stray edge does not bend a line; lines too short, too bent (`max_bend_px` from the
//     best great circle: not straight in the world, even allowing for the lens's error) or too rough are dropped.
// No Qt.
#include <vector>

#include <opencv2/core.hpp>

#include "vision/lens/lens.h"
#include "vision/lens/line_fit.h"

namespace bs::vision {

struct LineProposalOptions {
  double blur_sigma = 1.0;      // Gaussian blur before the gradient, px (larger for noisy frames)
  double canny_low = 0.015;     // hysteresis thresholds on the gradient magnitude, fraction of the range per px
  double canny_high = 0.04;     //   (the range: dark surround to bright level)
  double rim_margin_px = 8;     // edges closer than this to the lit disc's rim are ignored
  double corner_deg = 30;       // a chain turning more than this over +-5 px is split there
  double inlier_px = 0.8;       // distance from a line's curve within which a point counts as on it
  double max_rms_px = 0.5;      // RMS about the curve allowed (edge noise, not shape)
  double max_bend_px = 6;       // largest distance from the best world-straight line under the lens
  double min_length_px = 80;    // shortest proposal, arc length in the fisheye image
  double max_gap_px = 80;       // pieces on one line are merged across gaps up to this
  double point_spacing_px = 8;  // spacing of the returned points along a line (each an average of +-3 edge pixels)
  int max_lines = 80;           // the longest; <= 0: all
};

struct ProposedLine {
  PickedLine points;     // sub-pixel edge points, source pixels, in order along the line
  double length_px = 0;  // arc length in the fisheye image
  double rms_px = 0;     // RMS distance of the line's edge pixels from its fitted curve (a small circle of rays)
  double bend_px = 0;    // largest distance of its edge pixels from the best great circle (world-straight) curve
  double kink_px = 0;    // how much better two curves fit than one (RMS px): a kink, not a line of the world
  int edge_pixels = 0;   // edge pixels kept
  int outliers = 0;      // edge pixels the second pass dropped
};

struct LineProposals {
  std::vector<ProposedLine> lines;  // longest first
  int edge_pixels = 0;              // Canny edge pixels inside the disc
  int chains = 0;                   // chains before splitting
  int pieces = 0;                   // straight pieces before merging
  int rejected_bent = 0;            // merged lines dropped as too bent (curved in the world)
  int rejected_short = 0;           // merged lines dropped as too short or too rough
};

// Proposals in `image` (8/16-bit, 1 or 3 channels) with `lens` as the current estimate (its size should match
// the image's). Throws std::invalid_argument for an empty image or bad options.
LineProposals propose_lines(const cv::Mat& image, const Lens& lens, const LineProposalOptions& options = {});

// The points alone, as fit_lens_to_lines and the lines file take them.
std::vector<PickedLine> proposal_points(const LineProposals& proposals);

// The second pass on its own: `points` (source pixels along one line, in order) refitted robustly under `lens`;
// points further than max(inlier_px, 3 robust sigmas) from the refitted curve are dropped, repeatedly. Returns
// the kept points (order kept); `dropped` (optional) receives how many went. Fewer than 3 points: returned as is.
PickedLine drop_line_outliers(const Lens& lens, const PickedLine& points, double inlier_px = 0.8,
                              int* dropped = nullptr);

// The lines of `proposals` that do not repeat one of `existing` (most of their points within `tol_px` of an
// existing line's polyline), e.g. for pressing "Propose lines" twice.
std::vector<PickedLine> lines_not_in(const std::vector<PickedLine>& proposals, const std::vector<PickedLine>& existing,
                                     double tol_px = 3);

}  // namespace bs::vision
