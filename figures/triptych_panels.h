// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The paper's Figure 3 for a publication: three panels side by side with (a) (b) (c) captions under them, at
// double-column width (7.16 in, IEEE). PNG at 300 dpi, or vector PDF (QPdfWriter) with the images embedded.
#include <QImage>
#include <QString>
#include <array>

class QPainter;

namespace bs::ui {

// Paints the figure into `area` (device units of `painter`): equal panel widths, a gap between them, each caption
// centred under its panel in `font_pt` points (`dpi` converts points to device units).
void paint_triptych_figure(QPainter& painter, const QRectF& area, const std::array<QImage, 3>& panels,
                           const std::array<QString, 3>& captions, double dpi, double font_pt = 8);

// The figure's height in inches for a given width, from the panels' aspect ratio and the caption line.
double triptych_figure_height_in(const std::array<QImage, 3>& panels, double width_in, double font_pt = 8);

// Writes `path` as PDF (".pdf") or PNG (anything else, 300 dpi). Returns false and sets `error` on failure.
bool export_triptych_figure(const QString& path, const std::array<QImage, 3>& panels,
                            const std::array<QString, 3>& captions, QString* error, double width_in = 7.16);

}  // namespace bs::ui
