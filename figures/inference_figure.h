// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The inference-time figure (figure template kind "inference"): one horizontal bar per `bench dnn` run, its mean
// time per image with the SD as an error bar and the value and n beside it, grouped by platform and network down
// the axis and coloured by cv::dnn target (cpu, opencl, cuda). Runs of a built-in architecture with random
// weights are hatched and named "architecture timing: no detections" in the legend, so they are never read as a
// trained detector's timing. Needs a QApplication (QT_QPA_PLATFORM=offscreen works).
#include <QJsonArray>
#include <string>
#include <vector>

#include "model/dnn_run.h"
#include "report/figure_template.h"

class QCustomPlot;

namespace bs::ui {

struct FigureOptions;

// The runs the figure shows, in axis order (platform, network, input, batch, then cpu, opencl, cuda, others):
// the newest of each platform, network file (hash), input, batch and target; the template's platforms only when
// it names some. Every other run goes into `left_out` ({"platform", "what", "reason"}).
std::vector<DnnRun> inference_figure_runs(const FigureTemplate& t, const std::vector<DnnRun>& runs,
                                          QJsonArray& left_out);

// The axis label of a run's group: "vm\nmobilenet-ssd 300x300" (with ", batch B" when B > 1).
std::string inference_bar_label(const DnnRun& r);

// Fills `plot` (axes already styled from the template: x_label names the time axis) with the bars: the x axis
// is the time per image / t.y_scale (1e-3: ms), the y axis the runs, first at the top. Returns the runs drawn as
// figures.json sources. Throws NoFigureData when no run is left to draw.
QJsonArray inference_figure(QCustomPlot& plot, const FigureTemplate& t, const std::vector<DnnRun>& runs,
                            const FigureOptions& o, QJsonArray& left_out);

}  // namespace bs::ui
