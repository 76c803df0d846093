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
// phase keeps its line and band, only every n-th is named, so a 100-point sweep stays readable. The names are
// placed after every layout pass (on screen and in an exported figure alike), in up to three rows under the top of
// the axes: each takes the highest row where it prints over no other name; a name with no such row is left out
// (its band and line stay; the Phases table lists it).
void add_phase_markers(QCustomPlot* plot, const std::vector<TracePhase>& phases, const QColor& color,
                       int max_labels = 24);

// The phase names shown at the plot's last layout, and all of them (tests, and a figure's note).
int shown_phase_names(const QCustomPlot* plot);
int phase_name_count(const QCustomPlot* plot);

}  // namespace bs::ui
