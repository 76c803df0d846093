// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <QJsonArray>
#include <QStringList>

#include "model/frame.h"
#include "util/cancel.h"

namespace bs::ui {

struct FigureOptions;

// The paper's figure 3: raw mosaic shown as grey | demosaiced | reprojected, side by side with captions, from the
// workspace's capture `frame` (pixels loaded) through its lens, or, without one, from a synthetic BGGR chart through
// the paper's lens (195 degree equidistant; 150 degree view) at half the paper's resolution. Writes
// stem.<format> for each format; returns the data sources. `height_mm` receives the figure's height (the width is
// the options').
QJsonArray render_triptych_figure(const QString& stem, const FigureOptions& options, QStringList& files,
                                  double& height_mm, const Frame* frame, const CancelToken& cancel);

}  // namespace bs::ui
