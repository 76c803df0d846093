// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <QColor>
#include <QPen>
#include <QString>

#include "model/flops_run.h"

namespace bs::ui {

// Colour of a device from its workspace colour index: Okabe-Ito's colour-blind-safe set first, then Paul Tol's
// muted set, so the same device has the same colour in every view and every session.
QColor device_color(int color_index);

// D is shown by line style (1 dotted, 2 dashed, 4 solid, others dash-dot) so curves stay apart in greyscale.
Qt::PenStyle dims_pen_style(int dims);

// A stable scatter marker per backend family (OpenCL, CUDA, CPU ...) for greyscale-safe peak markers.
int backend_marker_shape(const QString& backend);  // a QCPScatterStyle::ScatterShape value

}  // namespace bs::ui
