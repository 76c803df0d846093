// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A sustained run on one time axis, as s-tui and jtop put it side by side, in panels one over the other whose time
// axes move together: the load's rate per interval (with the sustained level and the stable threshold of the best
// interval), the clocks (as % of their maximum with the throttle threshold where every clock states one, else in
// MHz), the temperatures (with each zone's trip point) and the power where one was recorded. Throttled spans are
// shaded in every panel and the onset is marked. A record without a rate (an imported tegrastats, jtop or
// nvidia-smi log) has no rate panel. The Sustained tab draws it; Ctrl+E exports it like every figure. Needs a
// QApplication (QT_QPA_PLATFORM=offscreen works).
#include <QString>

#include "model/sustain_run.h"
#include "sustain/sustain_analysis.h"

class QCustomPlot;

namespace bs::ui {

// Draws into `plot` (cleared first, panels rebuilt). `title`: where the record came from, drawn above the panels so
// an export says it. Returns the number of panels drawn (0: nothing to draw, the plot shows why).
int sustain_figure(QCustomPlot& plot, const SustainRun& run, const sustain::SustainAnalysis& analysis,
                   const QString& title);

// A CPU's clock by name ("cpu3", "CPU3"): these are drawn as the lowest and the mean of them, not one line each.
bool is_cpu_clock(const std::string& name);

}  // namespace bs::ui
