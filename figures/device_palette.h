// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <QColor>
#include <QPen>
#include <QString>
#include <string>
#include <utility>
#include <vector>

#include "model/flops_run.h"

namespace bs::ui {

// Colour of a device from its workspace colour index: Okabe-Ito's colour-blind-safe set first, then Paul Tol's
// muted set, so the same device has the same colour in every view and every session.
QColor device_color(int color_index);

// One colour index per platform, for the views of platform data (power, battery, platforms): the colour of the
// platform's first device (lowest index); a platform that has no device (only a power log) takes, in name order,
// the smallest index that neither a device nor an earlier such platform has. Every view that colours by platform
// uses this, so a platform has one colour everywhere.
std::vector<std::pair<std::string, int>> platform_color_indices(
    const std::vector<std::pair<std::string, int>>& device_platform_colors, std::vector<std::string> platforms);

// D is shown by line style (1 dotted, 2 dashed, 4 solid, others dash-dot) so curves stay apart in greyscale.
Qt::PenStyle dims_pen_style(int dims);

// A stable scatter marker per backend family (OpenCL, CUDA, CPU ...) for greyscale-safe peak markers.
int backend_marker_shape(const QString& backend);  // a QCPScatterStyle::ScatterShape value

// Runs of one series (same device, backend and D) in one chart: the first keeps its backend's marker, the
// `repeat`-th (1, 2, ...) takes a marker no backend uses, so repeated sweeps stay apart while colour stays the
// device's and line style the D.
int run_marker_shape(const QString& backend, int repeat);

}  // namespace bs::ui
