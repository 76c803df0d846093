// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The report's page-one chart: each platform's best peak compute as a bar (GFLOPS, log axis) in the platform's
// colour. A flagged peak is drawn at its value, hatched, and labelled "⚠ [n]" with the footnote number of the
// platforms table; a platform that fails a constraint is drawn pale; the recommended one is named under its bar.
#include <map>
#include <string>
#include <vector>

#include "analysis/platform/platform_comparison.h"

class QCustomPlot;

namespace bs::ui {

struct FigureOptions;

// Fills `plot` (which should be empty). `colors`: platform -> colour index (device_color()). Returns one line saying
// which runs the bars come from, for the report's sources appendix. Throws std::runtime_error when no platform
// has a FLOPS peak.
std::string comparison_chart(QCustomPlot& plot, const std::vector<PlatformRow>& rows,
                             const std::vector<PlatformVerdict>& verdicts, const std::map<std::string, int>& colors,
                             const FigureOptions& options);

// The caption that goes with it.
std::string comparison_chart_caption();

}  // namespace bs::ui
