// SPDX-License-Identifier: GPL-3.0-or-later
#include "power/phase_markers.h"

#include <qcustomplot.h>
#include <QPointer>

#include <algorithm>

#include "plot_labels.h"

namespace bs::ui {
namespace {

constexpr int kRows = 3;  // rows of names under the top of the axes

// Places a plot's phase names after every layout pass; one per plot, found by its name, kept across redraws (the
// names themselves are plot items and go with QCustomPlot::clearItems).
class PhaseNames : public QObject {
 public:
  explicit PhaseNames(QCustomPlot* plot) : QObject(plot), plot_(plot) {
    setObjectName(QStringLiteral("bs-phase-names"));
    connect(plot, &QCustomPlot::afterLayout, this, &PhaseNames::place);
  }
  static PhaseNames* of(QCustomPlot* plot) {
    // A plain QObject lookup by name (this class has no meta-object of its own): only a PhaseNames has this name.
    auto* names = plot->findChild<QObject*>(QStringLiteral("bs-phase-names"), Qt::FindDirectChildrenOnly);
    return names ? static_cast<PhaseNames*>(names) : new PhaseNames(plot);
  }
  void add(QCPItemText* name) { names_.emplace_back(name); }
  int shown() const {
    return static_cast<int>(
        std::count_if(names_.begin(), names_.end(), [](const auto& n) { return n && n->visible(); }));
  }
  int count() const {
    return static_cast<int>(std::count_if(names_.begin(), names_.end(), [](const auto& n) { return !n.isNull(); }));
  }

 private:
  void place() {
    names_.erase(std::remove_if(names_.begin(), names_.end(), [](const auto& n) { return n.isNull(); }), names_.end());
    const QRectF area = plot_->axisRect()->rect();
    if (names_.empty() || area.height() < 10) return;
    // Left to right, each name at the highest row where it overlaps no name placed before (a gap of 3 px).
    std::vector<QCPItemText*> order;
    for (const auto& n : names_) order.push_back(n);
    const auto x_of = [](QCPItemText* t) { return t->position->pixelPosition().x(); };
    std::stable_sort(order.begin(), order.end(), [&](QCPItemText* a, QCPItemText* b) { return x_of(a) < x_of(b); });
    std::vector<QRectF> taken;
    for (QCPItemText* name : order) {
      bool placed = false;
      for (int row = 0; row < kRows && !placed; ++row) {
        const double height = QFontMetricsF(name->font()).height() + 2;
        name->position->setCoords(name->position->coords().x(), (2 + row * height) / area.height());
        const QRectF box = text_item_rect(name).adjusted(-1.5, 0, 1.5, 0);
        if (std::any_of(taken.begin(), taken.end(), [&](const QRectF& t) { return t.intersects(box); })) continue;
        // Outside the range in view a name is clipped away anyway: it takes no room from the others.
        if (box.right() > area.left() && box.left() < area.right()) taken.push_back(box);
        placed = true;
      }
      name->setVisible(placed);
    }
  }
  QCustomPlot* plot_;
  std::vector<QPointer<QCPItemText>> names_;
};

}  // namespace

void add_phase_markers(QCustomPlot* plot, const std::vector<TracePhase>& phases, const QColor& color, int max_labels) {
  PhaseNames* names = PhaseNames::of(plot);
  const int n = static_cast<int>(phases.size());
  const int every = n > max_labels && max_labels > 0 ? (n + max_labels - 1) / max_labels : 1;
  QColor band = color;
  for (int i = 0; i < n; ++i) {
    const TracePhase& p = phases[static_cast<std::size_t>(i)];
    // Alternate the band's shade so neighbouring phases stay apart.
    band.setAlpha(i % 2 ? 18 : 36);
    auto* rect = new QCPItemRect(plot);
    rect->topLeft->setTypeX(QCPItemPosition::ptPlotCoords);
    rect->topLeft->setTypeY(QCPItemPosition::ptAxisRectRatio);
    rect->bottomRight->setTypeX(QCPItemPosition::ptPlotCoords);
    rect->bottomRight->setTypeY(QCPItemPosition::ptAxisRectRatio);
    rect->topLeft->setCoords(p.start_s, 0);
    rect->bottomRight->setCoords(p.end_s, 1);
    rect->setPen(Qt::NoPen);
    rect->setBrush(band);
    rect->setLayer("background");
    auto* line = new QCPItemStraightLine(plot);
    line->point1->setCoords(p.start_s, 0);
    line->point2->setCoords(p.start_s, 1);
    QColor edge = color;
    edge.setAlpha(140);
    line->setPen(QPen(edge, 1, Qt::DashLine));
    if (i % every != 0) continue;
    auto* label = new QCPItemText(plot);
    label->position->setTypeX(QCPItemPosition::ptPlotCoords);
    label->position->setTypeY(QCPItemPosition::ptAxisRectRatio);
    label->position->setCoords((p.start_s + p.end_s) / 2, 0.01);
    label->setPositionAlignment(Qt::AlignTop | Qt::AlignHCenter);
    label->setText(QString::fromStdString(p.name));
    label->setFont(QFont(plot->font().family(), 7));
    label->setColor(color.darker(140));
    label->setClipToAxisRect(true);
    names->add(label);
  }
}

int shown_phase_names(const QCustomPlot* plot) {
  const auto* names = plot->findChild<QObject*>(QStringLiteral("bs-phase-names"), Qt::FindDirectChildrenOnly);
  return names ? static_cast<const PhaseNames*>(names)->shown() : 0;
}

int phase_name_count(const QCustomPlot* plot) {
  const auto* names = plot->findChild<QObject*>(QStringLiteral("bs-phase-names"), Qt::FindDirectChildrenOnly);
  return names ? static_cast<const PhaseNames*>(names)->count() : 0;
}

}  // namespace bs::ui
