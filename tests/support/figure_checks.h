// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a figure fit for a paper must not have, checked on the plot's items after it was drawn at the figure's size
// (as save_plot draws it): labels that overlap each other, labels outside the axes, a legend over the axes, a
// curve or bar cut off by the axis range. Returns one line per problem (empty: fit).
#include <qcustomplot.h>
#include <QStringList>

#include <cmath>

#include "paper_figures.h"
#include "plot_export.h"
#include "plot_labels.h"

namespace bs::test {

// Draws `plot` at the options' size, which runs its layout and the label placement at that size.
inline void draw_at_figure_size(QCustomPlot& plot, const bs::ui::FigureOptions& sized) {
  const QSizeF size = bs::ui::figure_size_pt(sized);
  plot.toPixmap(static_cast<int>(std::lround(size.width())), static_cast<int>(std::lround(size.height())));
}

inline QStringList figure_problems(QCustomPlot& plot, const bs::ui::FigureOptions& sized) {
  draw_at_figure_size(plot, sized);
  QStringList problems;
  const QRectF axes = plot.axisRect()->rect();
  std::vector<std::pair<QString, QRectF>> labels;
  for (int i = 0; i < plot.itemCount(); ++i) {
    auto* t = qobject_cast<QCPItemText*>(plot.item(i));
    if (!t || !t->visible() || t->text().isEmpty()) continue;
    const QRectF r = bs::ui::text_item_rect(t);
    if (t->clipToAxisRect() && !axes.adjusted(-1, -1, 1, 1).contains(r))
      problems << QStringLiteral("label '%1' is clipped by the axes").arg(t->text());
    labels.emplace_back(t->text(), r);
  }
  for (std::size_t a = 0; a < labels.size(); ++a)
    for (std::size_t b = a + 1; b < labels.size(); ++b)
      if (labels[a].second.intersects(labels[b].second))
        problems << QStringLiteral("labels '%1' and '%2' overlap").arg(labels[a].first, labels[b].first);
  // An axis label is centred on its axis: one longer than the figure leaves room for is cut at the figure's edge
  // ("ck voltage under load").
  const QSizeF figure = bs::ui::figure_size_pt(sized);
  for (QCPAxis* axis : plot.axisRect()->axes()) {
    if (!axis->visible() || axis->label().isEmpty()) continue;
    const bool vertical = axis->orientation() == Qt::Vertical;
    const double centre = vertical ? axes.center().y() : axes.center().x();
    const double room = 2 * std::min(centre, (vertical ? figure.height() : figure.width()) - centre);
    if (QFontMetricsF(axis->labelFont()).horizontalAdvance(axis->label()) > room + 1)
      problems << QStringLiteral("axis label '%1' is cut at the figure's edge").arg(axis->label());
  }
  if (plot.legend->visible() && plot.legend->itemCount() > 0) {
    if (QRectF(plot.legend->outerRect()).intersects(axes.adjusted(1, 1, -1, -1)))
      problems << QStringLiteral("the legend covers the axes");
    if (plot.legend->rowCount() > bs::ui::kMaxLegendRows)
      problems << QStringLiteral("the legend has %1 rows").arg(plot.legend->rowCount());
    if (plot.legend->outerRect().width() > bs::ui::figure_size_pt(sized).width() + 1)
      problems << QStringLiteral("the legend is wider than the figure");
    // An entry narrower than its text needs is cut ("4.69 GFLO").
    for (int i = 0; i < plot.legend->itemCount(); ++i)
      if (auto* item = qobject_cast<QCPPlottableLegendItem*>(plot.legend->item(i));
          item && item->outerRect().width() + 1 < static_cast<QCPLayoutElement*>(item)->minimumOuterSizeHint().width())
        problems << QStringLiteral("the legend entry '%1' is cut").arg(item->plottable()->name());
  }
  // Every visible plottable's values within the shown key range lie inside the value range.
  for (int i = 0; i < plot.plottableCount(); ++i) {
    QCPAbstractPlottable* p = plot.plottable(i);
    if (!p->visible()) continue;
    bool found = false;
    const QCPRange values = p->getValueRange(found, QCP::sdBoth, p->keyAxis()->range());
    if (!found) continue;
    const QCPRange shown = p->valueAxis()->range();
    const double tolerance = 1e-9 * std::max(1.0, std::abs(shown.upper));
    if (values.upper > shown.upper + tolerance ||
        (values.lower < shown.lower - tolerance && p->valueAxis()->scaleType() == QCPAxis::stLinear))
      problems << QStringLiteral("'%1' is clipped: values %2..%3, axis %4..%5")
                      .arg(p->name())
                      .arg(values.lower)
                      .arg(values.upper)
                      .arg(shown.lower)
                      .arg(shown.upper);
  }
  return problems;
}

}  // namespace bs::test
