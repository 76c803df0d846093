// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Saves a QCustomPlot as a publication figure: PDF and SVG with text kept as text, PNG at a dpi, at a journal width
// in mm, with the figure's font size and line widths in pt. Used by the paper figures and by File > Export figure
// for every plot view.
#include <QImage>
#include <QSizeF>
#include <QString>
#include <QStringList>

#include "util/cancel.h"

class QCustomPlot;

namespace bs::ui {

struct FigureOptions;

// Page size of a figure in points (1/72 inch): width_mm, and height_mm or 0.62 x width.
QSizeF figure_size_pt(const FigureOptions& options);

// Puts the legend below the axes, unframed, so that it can never cover data (the paper figures' layout).
void place_legend_below(QCustomPlot& plot, double font_pt);
// As many legend columns as fit `width_pt`, measured by the legend's own layout (fonts included); a smaller legend
// font (down to 5 pt) when even one column is too wide.
void wrap_legend(QCustomPlot& plot, double font_pt, double width_pt);

// Writes stem.<format> for every format of `options` (pdf, svg, png); appends the paths to `files`.
// Throws std::runtime_error naming the file when it cannot be written, Cancelled between formats.
void save_plot(QCustomPlot& plot, const QString& stem, const FigureOptions& options, const QString& title,
               QStringList& files, const CancelToken* cancel = nullptr);

// As save_plot, for a plot shown on screen: applies the figure's font size and line widths for the export, moves a
// visible legend from over the axes to below them in as many columns as fit (an automatic height grows by the
// legend's height, so the axes keep 0.62 x the width), then restores the view's own look and legend.
// The look and size export_plot gives `plot` (also what the export dialog's preview shows); the caller restores the
// view afterwards. Returns the options with the automatic height resolved.
FigureOptions prepare_export(QCustomPlot& plot, const FigureOptions& options);

// The figure export_plot would write, as an image `width_px` wide (the export dialog's preview).
QImage render_export_preview(QCustomPlot& plot, const FigureOptions& options, int width_px);

void export_plot(QCustomPlot& plot, const QString& stem, const FigureOptions& options, const QString& title,
                 QStringList& files);

}  // namespace bs::ui
