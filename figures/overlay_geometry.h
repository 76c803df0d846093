// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Pixel-space geometry for putting overlays (the legend, peak labels) inside a plot where they hide the least
// data. Pure functions over rectangles and polylines, so the placement rules are unit-testable without a plot.
#include <QPolygonF>
#include <QRectF>
#include <optional>
#include <vector>

namespace bs::ui {

// A curve as drawn: its points in pixels, thinned so consecutive points are at least `min_step` pixels apart
// (a 4000-point sweep becomes a few hundred segments; lengths inside a box change by under a pixel per crossing).
QPolygonF thin_polyline(const QPolygonF& points, double min_step = 2.0);

// Pixel length of the curves inside `rect`.
double covered_length(const QRectF& rect, const std::vector<QPolygonF>& curves);

// What covering `rect` hides: the curve length inside it plus kMarkCost per mark (a peak marker's box) it touches,
// so a box would rather sit on a few pixels of line than on a peak.
inline constexpr double kMarkCost = 200;
double coverage_cost(const QRectF& rect, const std::vector<QPolygonF>& curves, const std::vector<QRectF>& marks);

// The corner of `area` (inset by `margin`) where a box of `size` has the lowest coverage_cost. Ties keep the
// first in the order top-right, bottom-right, top-left, bottom-left (top-right is where readers look for a legend).
Qt::Alignment least_covered_corner(const QRectF& area, const QSizeF& size, const std::vector<QPolygonF>& curves,
                                   const std::vector<QRectF>& marks, double margin);

// Distance in pixels from `rect` to the polyline `curve` (0 where the curve enters the rectangle).
double distance_to(const QRectF& rect, const QPolygonF& curve);

// A label box that lies nearer another curve than its own reads as that curve's value ("2.71" under the 5.25 curve):
// true when some curve other than `curves[own]` is nearer `box` than `curves[own]` by more than half a pixel.
// Always false without an owner (own < 0).
bool nearer_another_curve(const QRectF& box, const std::vector<QPolygonF>& curves, int own);

// Greedy label placement in priority order: each label tries the four positions diagonal to its anchor (`gap`
// pixels away), then straight above, right, left and below it, and takes the free one that covers the least curve
// length. Free = inside `area`, overlapping no obstacle and no label placed before, and (when `owners` gives the
// label's curve, an index into `curves`) no nearer another curve than its own. A label with no free position gets
// nullopt and is not drawn.
std::vector<std::optional<QRectF>> place_labels_greedy(const QRectF& area, const std::vector<QPointF>& anchors,
                                                       const std::vector<QSizeF>& sizes,
                                                       const std::vector<QRectF>& obstacles,
                                                       const std::vector<QPolygonF>& curves, double gap,
                                                       const std::vector<int>& owners = {});

}  // namespace bs::ui
