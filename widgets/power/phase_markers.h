// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A trace's phases (warm-up, each sweep point, a pipeline's window) drawn on a time plot: a dashed line where
// each starts, a shaded band over it and its name at the top, in the trace's colour.
#include <QColor>
#include <vector>

#include "model/power_trace.h"

class QCustomPlot;

namespace bs::ui {

// Adds the markers as plot items (QCustomPlot::clearItems removes them). More than `max_labels` phases: every
// phase keeps its line and band, only every n-th is named, so a 100-point sweep stays readable.
void add_phase_markers(QCustomPlot* plot, const std::vector<TracePhase>& phases, const QColor& color,
                       int max_labels = 24);

}  // namespace bs::ui
