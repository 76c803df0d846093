// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The latency histogram as the real-time community draws it (cyclictest plots, OSADL's latency plots): cycles per
// 1 us bin on a logarithmic count axis, one step line per thread and phase (idle and each load overlaid), the
// maximum of each in the legend ("idle · T0, max 37 us"), and a vertical deadline line with the count and
// percentage of cycles beyond it per curve. The Headroom tab draws it, Ctrl+E exports it like every figure.
// Needs a QApplication (QT_QPA_PLATFORM=offscreen works).
#include <QJsonArray>
#include <QString>
#include <cstdint>
#include <optional>
#include <vector>

#include "headroom/headroom_measurement.h"
#include "report/figure_template.h"

class QCustomPlot;

namespace bs::ui {

struct HeadroomCurve {
  QString label;  // "idle · T0"
  const headroom::LatencyHistogram* histogram = nullptr;
  int color_index = 0;  // device_color() palette: one colour per phase
  int thread = 0;       // line style per thread, so threads stay apart in greyscale
};

// One curve per phase and thread of each measurement, in order; colours follow the phases.
std::vector<HeadroomCurve> headroom_curves(const headroom::HeadroomMeasurement& m, const QString& prefix = {});

// What the deadline line says about one curve.
struct BeyondDeadline {
  QString label;
  std::uint64_t count = 0;
  double percent = 0;
  bool exact = true;  // false when the deadline cuts an occupied bin (that bin is not counted)
};

// Draws the curves into `plot` (cleared first). `deadline_ns`: the vertical line and the counts beyond it (latency
// strictly above it); empty: no line. `title`: the source, drawn above the plot so an export says where it came
// from. Returns the per-curve counts beyond the deadline (empty without one).
std::vector<BeyondDeadline> headroom_histogram_figure(QCustomPlot& plot, const std::vector<HeadroomCurve>& curves,
                                                      std::optional<std::int64_t> deadline_ns, const QString& title);

// The figure template kind "headroom" (`benchscope-cli figures`, the report's figures): the newest measurement of
// the template's platforms (every platform when it names none), all its phases overlaid, the deadline line at its
// first thread's deadline; the template's x label replaces the default. Every other measurement goes into
// `left_out` ({"platform", "what", "reason"}). Returns the measurement drawn as figures.json sources. Throws
// NoFigureData when there is none.
QJsonArray headroom_template_figure(QCustomPlot& plot, const FigureTemplate& t,
                                    const std::vector<headroom::HeadroomMeasurement>& measurements,
                                    QJsonArray& left_out);

}  // namespace bs::ui
