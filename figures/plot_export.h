// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Saves a QCustomPlot as a publication figure: PDF and SVG with text kept as text, PNG at a dpi, at a journal width
// in mm, with the figure's font size and line widths in pt. Used by the paper figures and by File > Export figure
// for every plot view.
#include <QSizeF>
#include <QString>
#include <QStringList>

#include "util/cancel.h"

class QCustomPlot;

namespace bs::ui {

struct FigureOptions;

// Page size of a figure in points (1/72 inch): width_mm, and height_mm or 0.62 x width.
QSizeF figure_size_pt(const FigureOptions& options);

// Writes stem.<format> for every format of `options` (pdf, svg, png); appends the paths to `files`.
// Throws std::runtime_error naming the file when it cannot be written, Cancelled between formats.
void save_plot(QCustomPlot& plot, const QString& stem, const FigureOptions& options, const QString& title, QStringList& files,
               const CancelToken* cancel = nullptr);

// As save_plot, for a plot shown on screen: applies the figure's font size and line widths for the export, then
// restores the view's own look.
void export_plot(QCustomPlot& plot, const QString& stem, const FigureOptions& options, const QString& title, QStringList& files);

}  // namespace bs::ui
