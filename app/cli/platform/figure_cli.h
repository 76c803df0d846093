// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What `figures` and `report` share: the figure size/font options, the data handed to the renderer, and an
// offscreen QApplication. Only in builds with Qt (BENCHSCOPE_WITH_FIGURES).
#ifdef BENCHSCOPE_WITH_FIGURES
#include <memory>
#include <set>
#include <string>

#include <QApplication>

#include "common/args.h"
#include "paper_figures.h"
#include "workspace/inputs.h"

namespace bs::cli {

// --preset, --width-mm, --height-mm, --dpi, --font-pt, --format, --template
const std::set<std::string>& figure_value_options();
// Throws UsageError for a bad value.
ui::FigureOptions parse_figure_options(const ParsedArgs& args);
std::vector<FigureTemplate> figure_templates(const ParsedArgs& args);
// Colours by first appearance, as the workspace assigns them, so figures match the GUI; pipeline timings; the
// first capture (of the files, or read from the workspace) for fig3.
ui::FigureData figure_data(const std::vector<std::string>& paths, const LoadedData& data, const CancelToken& cancel);
// Renders without a display (QT_QPA_PLATFORM=offscreen unless the user set a platform).
std::unique_ptr<QApplication> offscreen_application();

}  // namespace bs::cli
#endif
