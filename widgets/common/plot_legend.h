// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where a QCustomPlot's legend lives (issue #32.7): inside the axis rect when it fits without hiding data, else in a
// row of its own under the plot, its entries in columns, so on a small window the legend never covers a curve.
class QCustomPlot;

namespace bs::ui {

// Moves the legend out of the axis rect into a row under it (entries filled row by row, `columns` per row).
void put_legend_below(QCustomPlot* plot, int columns);
// Moves it to a column right of the axes, one entry per line: for a short plot whose many entries would leave the
// axes no height below them (the Platforms tab's candidates at 1280x800).
void put_legend_beside(QCustomPlot* plot);
// Moves it back into the axis rect's inset layout (no-op when it is there).
void put_legend_inside(QCustomPlot* plot);
bool legend_is_below(QCustomPlot* plot);

}  // namespace bs::ui
