// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The candidates figure: inferences per second (log axis) against power (W) for every candidate with both, one
// colour per class (network, scenario, precision: the legend names each, so unlike classes are never mixed
// silently) and one marker per origin (filled circle measured, open square reconstructed, diamond published: the
// legend names each), every point labelled with its platform where the name fits apart from the others (flagged
// points first; the table beside the figure lists every row). Rows without a power figure are listed in the
// returned note, not drawn. Needs a QApplication (offscreen works).
#include <QImage>
#include <QString>
#include <span>

#include "analysis/library/candidates.h"

class QCustomPlot;

namespace bs::ui {

// Draws into `plot` (cleared first). Returns a note naming the rows left out for lack of power or rate.
QString draw_candidates(QCustomPlot& plot, std::span<const CandidateClass> classes);
// The same rendered off screen to a PNG-ready image of `width` x `height` pixels.
QImage render_candidates(std::span<const CandidateClass> classes, int width, int height, QString* note = nullptr);

}  // namespace bs::ui
