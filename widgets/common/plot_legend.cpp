// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/plot_legend.h"

#include <qcustomplot.h>

namespace bs::ui {

bool legend_is_below(QCustomPlot* plot) {
  QCPLayoutGrid* grid = plot->plotLayout();  // QCustomPlot's grid has no const element()
  return grid->rowCount() > 1 && grid->hasElement(1, 0) && grid->element(1, 0) == plot->legend;
}

void put_legend_below(QCustomPlot* plot, int columns) {
  QCPLegend* legend = plot->legend;
  legend->setFillOrder(QCPLayoutGrid::foColumnsFirst, false);
  legend->setWrap(columns > 0 ? columns : 1);
  legend->setFillOrder(QCPLayoutGrid::foColumnsFirst, true);  // re-flow the items into the new wrap
  if (legend_is_below(plot)) return;
  if (QCPLayout* from = legend->layout()) from->take(legend);
  QCPLayoutGrid* grid = plot->plotLayout();
  if (grid->hasElement(1, 0)) grid->remove(grid->element(1, 0));
  grid->addElement(1, 0, legend);
  grid->setRowStretchFactor(1, 0.001);  // as tall as its entries, the plot keeps the rest
  legend->setMargins(QMargins(5, 3, 5, 3));
  // Its columns must not set the plot's (and so the window's) minimum width: a narrower window clips the entries'
  // ends instead of refusing to shrink (issue #32.7). Height 0: as tall as the entries need.
  legend->setMinimumSize(QSize(50, 0));
}

void put_legend_beside(QCustomPlot* plot) {
  QCPLegend* legend = plot->legend;
  QCPLayoutGrid* grid = plot->plotLayout();
  if (grid->columnCount() > 1 && grid->hasElement(0, 1) && grid->element(0, 1) == legend) return;
  if (QCPLayout* from = legend->layout()) from->take(legend);
  grid->simplify();
  legend->setFillOrder(QCPLayoutGrid::foRowsFirst, false);
  legend->setWrap(0);
  legend->setFillOrder(QCPLayoutGrid::foRowsFirst, true);
  legend->setMinimumSize(QSize(0, 0));
  legend->setMargins(QMargins(3, 3, 3, 3));
  grid->addElement(0, 1, legend);
  grid->setColumnStretchFactor(1, 0.001);  // as wide as its entries, the axes keep the rest
}

void put_legend_inside(QCustomPlot* plot) {
  QCPLegend* legend = plot->legend;
  if (legend->layout() != plot->plotLayout()) return;  // inside already
  plot->plotLayout()->take(legend);
  plot->plotLayout()->simplify();  // the emptied row goes
  legend->setFillOrder(QCPLayoutGrid::foRowsFirst, false);
  legend->setWrap(0);
  legend->setFillOrder(QCPLayoutGrid::foRowsFirst, true);
  legend->setMinimumSize(QSize(0, 0));  // its own size again
  plot->axisRect()->insetLayout()->addElement(legend, Qt::AlignTop | Qt::AlignRight);
}

}  // namespace bs::ui
