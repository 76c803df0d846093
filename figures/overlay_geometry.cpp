// SPDX-License-Identifier: GPL-3.0-or-later
#include "overlay_geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace bs::ui {
namespace {

// Length of segment a-b inside `rect` (Liang-Barsky clipping).
double clipped_length(const QRectF& rect, const QPointF& a, const QPointF& b) {
  // Cheap rejection first: nearly all segments of a sweep lie far from a given box.
  if (std::max(a.x(), b.x()) < rect.left() || std::min(a.x(), b.x()) > rect.right() ||
      std::max(a.y(), b.y()) < rect.top() || std::min(a.y(), b.y()) > rect.bottom())
    return 0;
  const double dx = b.x() - a.x(), dy = b.y() - a.y();
  double t0 = 0, t1 = 1;
  const std::array<double, 4> p = {-dx, dx, -dy, dy};
  const std::array<double, 4> q = {a.x() - rect.left(), rect.right() - a.x(), a.y() - rect.top(),
                                   rect.bottom() - a.y()};
  for (std::size_t i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return 0;  // parallel to this edge and outside it
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
  }
  return t1 > t0 ? (t1 - t0) * std::hypot(dx, dy) : 0;
}

}  // namespace

QPolygonF thin_polyline(const QPolygonF& points, double min_step) {
  QPolygonF out;
  for (const QPointF& p : points) {
    if (!std::isfinite(p.x()) || !std::isfinite(p.y())) continue;
    if (!out.isEmpty() && std::hypot(p.x() - out.back().x(), p.y() - out.back().y()) < min_step) continue;
    out << p;
  }
  // Keep the true end point so the last segment reaches where the curve ends.
  if (!points.isEmpty() && !out.isEmpty() && out.back() != points.back() && std::isfinite(points.back().x()) &&
      std::isfinite(points.back().y()))
    out << points.back();
  return out;
}

double covered_length(const QRectF& rect, const std::vector<QPolygonF>& curves) {
  double length = 0;
  for (const QPolygonF& c : curves)
    for (qsizetype i = 1; i < c.size(); ++i) length += clipped_length(rect, c[i - 1], c[i]);
  return length;
}

double coverage_cost(const QRectF& rect, const std::vector<QPolygonF>& curves, const std::vector<QRectF>& marks) {
  double cost = covered_length(rect, curves);
  for (const QRectF& m : marks)
    if (rect.intersects(m)) cost += kMarkCost;
  return cost;
}

Qt::Alignment least_covered_corner(const QRectF& area, const QSizeF& size, const std::vector<QPolygonF>& curves,
                                   const std::vector<QRectF>& marks, double margin) {
  const QRectF inner = area.adjusted(margin, margin, -margin, -margin);
  const std::array<Qt::Alignment, 4> corners = {Qt::AlignTop | Qt::AlignRight, Qt::AlignBottom | Qt::AlignRight,
                                                Qt::AlignTop | Qt::AlignLeft, Qt::AlignBottom | Qt::AlignLeft};
  Qt::Alignment best = corners[0];
  double best_cost = std::numeric_limits<double>::max();
  for (const Qt::Alignment a : corners) {
    const double x = (a & Qt::AlignRight) ? inner.right() - size.width() : inner.left();
    const double y = (a & Qt::AlignBottom) ? inner.bottom() - size.height() : inner.top();
    const double cost = coverage_cost(QRectF(QPointF(x, y), size), curves, marks);
    if (cost < best_cost) {
      best_cost = cost;
      best = a;
    }
  }
  return best;
}

double distance_to(const QRectF& rect, const QPolygonF& curve) {
  const auto point_to_rect = [&](const QPointF& p) {
    const double dx = std::max({rect.left() - p.x(), 0.0, p.x() - rect.right()});
    const double dy = std::max({rect.top() - p.y(), 0.0, p.y() - rect.bottom()});
    return std::hypot(dx, dy);
  };
  const auto point_to_segment = [](const QPointF& p, const QPointF& a, const QPointF& b) {
    const QPointF d = b - a;
    const double length2 = d.x() * d.x() + d.y() * d.y();
    const double t = length2 > 0 ? std::clamp(QPointF::dotProduct(p - a, d) / length2, 0.0, 1.0) : 0.0;
    const QPointF q = a + t * d;
    return std::hypot(p.x() - q.x(), p.y() - q.y());
  };
  double best = std::numeric_limits<double>::infinity();
  if (curve.size() == 1) return point_to_rect(curve.front());
  for (qsizetype i = 1; i < curve.size(); ++i) {
    const QPointF a = curve[i - 1], b = curve[i];
    if (clipped_length(rect, a, b) > 0 || rect.contains(a)) return 0;
    // Apart from the rectangle, the nearest pair is an end of the segment and the rectangle, or a corner and the
    // segment.
    best = std::min({best, point_to_rect(a), point_to_rect(b)});
    for (const QPointF& corner : {rect.topLeft(), rect.topRight(), rect.bottomLeft(), rect.bottomRight()})
      best = std::min(best, point_to_segment(corner, a, b));
  }
  return best;
}

bool nearer_another_curve(const QRectF& box, const std::vector<QPolygonF>& curves, int own) {
  if (own < 0 || own >= static_cast<int>(curves.size())) return false;
  const double mine = distance_to(box, curves[static_cast<std::size_t>(own)]);
  for (std::size_t c = 0; c < curves.size(); ++c)
    if (static_cast<int>(c) != own && distance_to(box, curves[c]) + 0.5 < mine) return true;
  return false;
}

std::vector<std::optional<QRectF>> place_labels_greedy(const QRectF& area, const std::vector<QPointF>& anchors,
                                                       const std::vector<QSizeF>& sizes,
                                                       const std::vector<QRectF>& obstacles,
                                                       const std::vector<QPolygonF>& curves, double gap,
                                                       const std::vector<int>& owners) {
  std::vector<std::optional<QRectF>> placed(anchors.size());
  std::vector<QRectF> taken = obstacles;
  for (std::size_t i = 0; i < anchors.size() && i < sizes.size(); ++i) {
    const QPointF p = anchors[i];
    const double w = sizes[i].width(), h = sizes[i].height();
    // Above-left first: peaks sit on plateaus that run to the right edge, and curves rise from the lower left.
    // Then straight above, right, left and below: on a crowded log axis the diagonals are often all taken.
    const std::array<QRectF, 8> candidates = {
        QRectF(p.x() - gap - w, p.y() - gap - h, w, h), QRectF(p.x() + gap, p.y() - gap - h, w, h),
        QRectF(p.x() - gap - w, p.y() + gap, w, h),     QRectF(p.x() + gap, p.y() + gap, w, h),
        QRectF(p.x() - w / 2, p.y() - gap - h, w, h),   QRectF(p.x() + gap, p.y() - h / 2, w, h),
        QRectF(p.x() - gap - w, p.y() - h / 2, w, h),   QRectF(p.x() - w / 2, p.y() + gap, w, h)};
    double best_cost = std::numeric_limits<double>::max();
    for (const QRectF& c : candidates) {
      if (!area.contains(c)) continue;
      bool free = true;
      for (const QRectF& t : taken) free = free && !t.intersects(c);
      if (!free || (i < owners.size() && nearer_another_curve(c, curves, owners[i]))) continue;
      const double cost = covered_length(c, curves);
      if (cost < best_cost) {
        best_cost = cost;
        placed[i] = c;
      }
    }
    if (placed[i]) taken.push_back(*placed[i]);
  }
  return placed;
}

}  // namespace bs::ui
