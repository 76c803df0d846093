// SPDX-License-Identifier: GPL-3.0-or-later
// Placement of the legend and peak labels inside a plot.
#include <QTest>

#include "overlay_geometry.h"

class TestOverlayGeometry : public QObject {
  Q_OBJECT
 private slots:
  void covered_length_clips_segments() {
    const QRectF box(0, 0, 10, 10);
    QCOMPARE(bs::ui::covered_length(box, {QPolygonF({{-5, 5}, {15, 5}})}), 10.0);                // crosses the box
    QCOMPARE(bs::ui::covered_length(box, {QPolygonF({{2, 2}, {5, 6}})}), 5.0);                   // 3-4-5, inside
    QCOMPARE(bs::ui::covered_length(box, {QPolygonF({{20, 0}, {30, 10}})}), 0.0);                // outside
    QCOMPARE(bs::ui::covered_length(box, {QPolygonF({{-5, -5}, {15, 15}})}), std::sqrt(200.0));  // the diagonal
  }

  void thinning_keeps_ends_and_drops_subpixel_steps() {
    QPolygonF dense;
    for (int i = 0; i <= 1000; ++i) dense << QPointF(i * 0.1, 0);
    const QPolygonF thin = bs::ui::thin_polyline(dense, 2.0);
    QVERIFY(thin.size() < 60);
    QCOMPARE(thin.front(), dense.front());
    QCOMPARE(thin.back(), dense.back());
  }

  void legend_goes_to_the_empty_corner() {
    const QRectF area(0, 0, 400, 300);
    const QSizeF legend(100, 60);
    // A rising curve from the bottom left to the top right leaves top-left and bottom-right free; with a second
    // curve along the bottom only the top-left is free.
    const QPolygonF rising({{0, 300}, {400, 0}});
    QCOMPARE(bs::ui::least_covered_corner(area, legend, {rising}, {}, 0), Qt::AlignBottom | Qt::AlignRight);
    const QPolygonF floor({{0, 290}, {400, 290}});
    QCOMPARE(bs::ui::least_covered_corner(area, legend, {rising, floor}, {}, 0), Qt::AlignTop | Qt::AlignLeft);
    // A peak marker counts more than a few pixels of line: every corner holds something, and the one with only a
    // marker (no line at all) loses to the one with the shortest piece of line.
    const std::vector<QPolygonF> pieces = {QPolygonF({{350, 30}, {380, 30}}), QPolygonF({{20, 30}, {70, 30}}),
                                           QPolygonF({{20, 270}, {60, 270}})};
    const QRectF marker_bottom_right(350, 270, 10, 10);
    QCOMPARE(bs::ui::least_covered_corner(area, legend, pieces, {}, 0), Qt::AlignBottom | Qt::AlignRight);
    QCOMPARE(bs::ui::least_covered_corner(area, legend, pieces, {marker_bottom_right}, 0),
             Qt::AlignTop | Qt::AlignRight);
  }

  void labels_never_overlap_each_other_or_obstacles() {
    const QRectF area(0, 0, 300, 200);
    // Three peaks at the same spot: only positions around it that do not collide are used; the fifth cannot fit.
    const std::vector<QPointF> anchors(5, QPointF(150, 100));
    const std::vector<QSizeF> sizes(5, QSizeF(60, 14));
    const QRectF obstacle(150 + 6, 100 + 6, 60, 14);  // e.g. the legend, below-right of the anchor
    const auto placed = bs::ui::place_labels_greedy(area, anchors, sizes, {obstacle}, {}, 6);
    QCOMPARE(placed.size(), std::size_t{5});
    int shown = 0;
    for (std::size_t i = 0; i < placed.size(); ++i) {
      if (!placed[i]) continue;
      ++shown;
      QVERIFY(area.contains(*placed[i]));
      QVERIFY(!placed[i]->intersects(obstacle));
      for (std::size_t j = 0; j < i; ++j) QVERIFY(!placed[j] || !placed[i]->intersects(*placed[j]));
    }
    QCOMPARE(shown, 3);
    QVERIFY(placed[0] && placed[1] && placed[2]);  // priority order: the first labels win
    // A label at the right edge flips to the left of its anchor instead of leaving the plot.
    const auto edge = bs::ui::place_labels_greedy(area, {QPointF(295, 100)}, {QSizeF(60, 14)}, {}, {}, 6);
    QVERIFY(edge[0] && edge[0]->right() <= 295);
    // Among free positions the one covering less curve wins: a line above the anchor pushes the label below.
    const QPolygonF line_above({{0, 90}, {300, 90}});
    const auto below = bs::ui::place_labels_greedy(area, {QPointF(150, 100)}, {QSizeF(60, 14)}, {}, {line_above}, 6);
    QVERIFY(below[0] && below[0]->top() > 100);
  }
};

QTEST_MAIN(TestOverlayGeometry)
#include "test_overlay_geometry.moc"
