// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Saves a QCustomPlot as a publication figure: PDF and SVG with text kept as text, PNG at a dpi, at a journal width
// in mm, with the figure's font size and line widths in pt. One layout (layout_figure) for every figure that leaves
// the program: File > Export figure (Ctrl+E) of every tab, the paper figures and the report's figures.
#include <QImage>
#include <QSizeF>
#include <QString>
#include <QStringList>

#include "util/cancel.h"

class QCustomPlot;
class QCPAbstractPlottable;

namespace bs::ui {

struct FigureOptions;

// Page size of a figure in points (1/72 inch): width_mm, and height_mm or 0.62 x width.
QSizeF figure_size_pt(const FigureOptions& options);

// At most this many legend rows: entries beyond them are named in a note under the legend instead.
inline constexpr int kMaxLegendRows = 8;

// Lays `plot` out as a figure at the options' width: the figure's fonts (axes, legend, labels) and line widths;
// the legend below the axes, unframed, in as many columns as fit, entries that read and look the same merged into
// one ("… (2 runs)"), at most kMaxLegendRows rows with the rest named in a note under it; the value axis widened
// where a visible curve or bar would be clipped. Returns the options with an automatic height (0) resolved: the
// axes keep 0.62 x the width (0.8 below 80 mm, so the axis label fits) and the legend and note add theirs.
// The plot is left in the figure's look: export_plot puts a view back afterwards.
FigureOptions layout_figure(QCustomPlot& plot, const FigureOptions& options);

// The name a plottable has in an exported figure when it differs from the view's legend (the FLOPS tab's series
// carry their peak there: a figure's peak labels give way where they crowd, the legend names every peak).
void set_figure_name(QCPAbstractPlottable* plottable, const QString& name);
// The name `plottable` has in an exported figure: its figure name where set_figure_name gave one, else its name.
QString figure_name(const QCPAbstractPlottable* plottable);

// A line for the figure's note under the legend (a flag's footnote, "⚠[1] above_spec_peak: …"): layout_figure
// sets the note's lines at the figure's width. Kept with the plot; a view that adds none exports without a note.
void add_figure_note(QCustomPlot& plot, const QString& line);
void clear_figure_notes(QCustomPlot& plot);

// The note layout_figure put under the legend (the figure's notes, then "Also drawn: …" for entries beyond
// kMaxLegendRows rows), empty when there is none.
QString legend_note(const QCustomPlot& plot);

// Writes stem.<format> for every format of `options` (pdf, svg, png); appends the paths to `files`.
// Throws std::runtime_error naming the file when it cannot be written, Cancelled between formats.
void save_plot(QCustomPlot& plot, const QString& stem, const FigureOptions& options, const QString& title,
               QStringList& files, const CancelToken* cancel = nullptr);

// layout_figure, save_plot, then the view's own look, legend, names and ranges restored.
void export_plot(QCustomPlot& plot, const QString& stem, const FigureOptions& options, const QString& title,
                 QStringList& files);

// The figure export_plot would write, as an image `width_px` wide (the export dialog's preview).
QImage render_export_preview(QCustomPlot& plot, const FigureOptions& options, int width_px);

}  // namespace bs::ui
