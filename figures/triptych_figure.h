// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <QJsonArray>
#include <QStringList>

namespace bs::ui {

struct FigureOptions;

// The paper's figure 3: raw mosaic shown as grey | demosaiced | reprojected, side by side with captions, from a
// synthetic BGGR capture through the paper's lens (195 degree equidistant; 150 degree rectilinear view), rendered
// at half the paper's resolution. Writes stem.<format> for each format; returns the data sources.
// `height_mm` receives the figure's height (the width is the options').
QJsonArray render_triptych_figure(const QString& stem, const FigureOptions& options, QStringList& files,
                                  double& height_mm);

}  // namespace bs::ui
