// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Value labels anchored to points of a plot (peak labels), placed after every layout pass so that they stay
// readable at any size: on screen, in an export at a journal width, in the report. In priority order (the first
// added is the highest peak), each label takes the free spot around its anchor that covers the least curve; with
// no spot free of curves it sits beside its anchor, unless it would cover a label placed before it or the legend:
// then it is dropped, the lesser of two that would collide. Labels never overlap each other.
#include <QObject>
#include <QPointer>
#include <QRectF>
#include <vector>

class QCustomPlot;
class QCPGraph;
class QCPItemText;

namespace bs::ui {

class AnchoredLabels : public QObject {
  Q_OBJECT
 public:
  // `auto_place`: re-place after every layout pass of `plot`; false when an owner calls place() itself (after it
  // has moved the legend).
  explicit AnchoredLabels(QCustomPlot* plot, bool auto_place = true);

  // Forget every curve and label. Call before QCustomPlot::clearGraphs()/clearItems() delete them.
  void clear();
  // A data series the labels should avoid covering.
  void add_curve(QCPGraph* graph);
  // A label for the point (key, value) in plot coordinates. Add in priority order, highest first. With `owner` (the
  // curve the point lies on, added with add_curve) the label is never put nearer another curve than that one, where
  // it would read as the other curve's value; with no such spot it is not drawn.
  QCPItemText* add(double key, double value, const QString& text, const QColor& color, QCPGraph* owner = nullptr);
  // Re-places the labels for the plot's current layout (done after every layout pass).
  void place();

  int shown_count() const;
  std::vector<QCPItemText*> labels() const;
  std::vector<QRectF> marker_boxes() const;  // the anchors' markers in pixels, for other overlays to avoid

 private:
  struct Label {
    QPointer<QCPItemText> item;
    double key, value;
    QPointer<QCPGraph> owner;
  };
  QCustomPlot* plot_;
  std::vector<QPointer<QCPGraph>> curves_;
  std::vector<Label> labels_;
};

// The box a text item covers in pixels at the plot's current layout (text, padding and alignment included).
QRectF text_item_rect(const QCPItemText* item);
// Each visible graph's points in pixels (thinned), for placement costs.
std::vector<QPolygonF> graphs_in_pixels(const std::vector<QPointer<QCPGraph>>& graphs);

}  // namespace bs::ui
