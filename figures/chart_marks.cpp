// SPDX-License-Identifier: GPL-3.0-or-later
#include "chart_marks.h"

#include <qcustomplot.h>
#include <QPainter>
#include <QPixmap>

namespace bs::ui {

void mark_flagged_bars(QCPBars* bars, const QColor& color) {
  // Hatching as a texture (a pale fill crossed by bold diagonals): Qt's pattern brushes are one device pixel thin,
  // which vanishes in a 300 dpi PNG.
  QPixmap tile(12, 12);
  tile.fill(QColor::fromHsvF(color.hsvHueF(), color.hsvSaturationF() * 0.25, 1.0));
  {
    QPainter p(&tile);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(QPen(color.darker(115), 2.2));
    p.drawLine(QPointF(-2, 14), QPointF(14, -2));
    p.drawLine(QPointF(-8, 8), QPointF(8, -8));
    p.drawLine(QPointF(4, 20), QPointF(20, 4));
  }
  bars->setBrush(QBrush(tile));
  QPen pen = bars->pen();
  pen.setColor(color.darker(150));
  bars->setPen(pen);
}

bool is_flagged_bars(const QCPBars* bars) { return bars->brush().style() == Qt::TexturePattern; }

void mark_flagged_points(QCPGraph* graph, const QColor& color) {
  QCPScatterStyle s = graph->scatterStyle();
  if (s.shape() == QCPScatterStyle::ssNone) s.setShape(QCPScatterStyle::ssCircle);
  s.setPen(QPen(color.darker(130), 1.2));
  s.setBrush(Qt::white);
  s.setSize(s.size() + 2);
  graph->setScatterStyle(s);
}

bool is_flagged_points(const QCPGraph* graph) {
  const QCPScatterStyle s = graph->scatterStyle();
  return s.shape() != QCPScatterStyle::ssNone && s.brush().color() == Qt::white && s.brush().style() != Qt::NoBrush;
}

QString flag_label(const QString& value, const QString& marker) { return value + QStringLiteral(" \u26A0") + marker; }

}  // namespace bs::ui
