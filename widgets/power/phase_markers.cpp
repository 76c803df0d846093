// SPDX-License-Identifier: GPL-3.0-or-later
#include "power/phase_markers.h"

#include <qcustomplot.h>

namespace bs::ui {

void add_phase_markers(QCustomPlot* plot, const std::vector<TracePhase>& phases, const QColor& color, int max_labels) {
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
    label->position->setCoords((p.start_s + p.end_s) / 2, 0.01 + 0.045 * (i / every % 3));
    label->setPositionAlignment(Qt::AlignTop | Qt::AlignHCenter);
    label->setText(QString::fromStdString(p.name));
    label->setFont(QFont(plot->font().family(), 7));
    label->setColor(color.darker(140));
    label->setClipToAxisRect(true);
  }
}

}  // namespace bs::ui
