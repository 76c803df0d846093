// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Renders a figure template set (resources/figures/paper-2018.json) from a workspace's data into PDF, SVG and PNG
// files at journal sizes, plus the paper's Tables 1 and 2 (LaTeX, CSV) and figures.json listing every file with
// its data sources and their provenance. Needs a QApplication (QT_QPA_PLATFORM=offscreen works).
#include <QFont>
#include <QJsonArray>
#include <QString>
#include <QStringList>
#include <map>
#include <optional>
#include <vector>

#include <functional>
#include <stdexcept>

#include "analysis/platform/platform_comparison.h"
#include "headroom/headroom_measurement.h"
#include "model/dnn_run.h"
#include "model/flops_run.h"
#include "model/frame.h"
#include "model/power_trace.h"
#include "model/sustain_run.h"
#include "report/figure_template.h"
#include "util/cancel.h"

class QCPAxis;
class QCustomPlot;

namespace bs::ui {

struct FigureOptions {
  double width_mm = 122;  // LNCS text width
  double height_mm = 0;   // 0: 0.62 x width
  double font_pt = 8;
  double line_width_pt = 1.0;
  int dpi = 300;               // PNG
  QStringList formats{"pdf"};  // any of pdf, svg, png
};

struct FigureData {
  std::vector<FlopsRun> runs;
  std::vector<std::string> run_labels;  // the user's names of `runs`, same order (may be shorter; "": none)
  std::vector<PowerTrace> traces;
  std::vector<PipelineTimings> pipelines;
  std::vector<DnnRun> inference_runs;                   // bench dnn runs: the report's inference table
  std::vector<headroom::HeadroomMeasurement> headroom;  // the report's control-loop headroom section
  std::vector<SustainRun> sustain_runs;                 // what the report's sustained requirement judges
  std::optional<Frame> frame;  // the capture for fig3 (pixels loaded); none: a synthetic chart stands in
  std::map<std::pair<std::string, std::string>, int> colors;  // (platform, device) -> colour index
  // Which data this is, said to the user and recorded in figures.json ("data"): e.g. "paper data only".
  std::string selection = "all data given";
};

// What the figures may show: everything given (the CLI's default, the runs ticked in the GUI), or only the data
// reconstructed from the paper, so that a run measured on this machine never slips into a paper figure unasked.
enum class FigureDataChoice { All, PaperOnly };
// Keeps the runs, power logs and pipeline runs the choice allows and sets `selection`.
FigureData select_figure_data(FigureData data, FigureDataChoice choice);

// A figure whose template selects no data (no FLOPS runs match, no power log, no inference run): an error naming
// the figure, unless the template is optional, when the figure is skipped and the contents line says why.
struct NoFigureData : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct FigureOutput {
  QStringList files;     // every file written, figures.json last
  QStringList contents;  // a line per figure: what it shows, and what it left out and why (or why it is skipped)
};

// Throws std::runtime_error (naming the file) when a file cannot be written, Cancelled when `cancel` fires
// (checked between figures); either way the files it wrote are removed again.
FigureOutput render_figures(const std::vector<FigureTemplate>& templates, const FigureData& data,
                            const QString& out_dir, const FigureOptions& options, const CancelToken& cancel,
                            const std::function<void(int done, int total, const QString& what)>& progress = {});

// A plot template's figure (kind flops, current or inference) drawn into `plot` and laid out at the options' size by
// the one figure layout (plot_export.h): what render_figures saves. `sized` has the automatic height resolved.
// Throws NoFigureData when the template selects nothing; `left_out` gets what was left out and why.
struct PlotFigure {
  QJsonArray sources;
  FigureOptions sized;
};
PlotFigure figure_plot(QCustomPlot& plot, const FigureTemplate& t, const FigureData& data, const FigureOptions& options,
                       QJsonArray& left_out);

// The bundled template of the paper's figures.
QString paper_template_path();

// The figures' font (DejaVu Sans) at `scale` times the options' size: tick and bar labels take 0.9 of it.
QFont figure_font(const FigureOptions& o, double scale = 1.0);

// An axis in the figures' look: its label in the figure font, tick labels at 0.9 of it, black axis line and ticks
// as thick as the options say (sub-ticks thinner). The paper's figures and the report's comparison chart share it, so
// that the report's chart sits beside them alike; the grid stays each figure's.
void style_figure_axis(QCPAxis* axis, const FigureOptions& o);

}  // namespace bs::ui
