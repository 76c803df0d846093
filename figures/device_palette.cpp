// SPDX-License-Identifier: GPL-3.0-or-later
#include "device_palette.h"

#include <algorithm>
#include <array>
#include <map>
#include <set>

#include <qcustomplot.h>

namespace bs::ui {

QColor device_color(int color_index) {
  // Okabe & Ito (2008) without black (kept for text); then those of Tol's muted scheme that no Okabe-Ito colour
  // resembles (his cyan, teal and rose read as Okabe-Ito's sky blue, bluish green and reddish purple on screen),
  // a brown, a sand and a grey; Okabe-Ito's yellow last: it is too light on white for thin lines and bands.
  static const std::array<QColor, 15> colors = {
      QColor(0, 114, 178),  QColor(230, 159, 0),   QColor(0, 158, 115),   QColor(213, 94, 0),   QColor(204, 121, 167),
      QColor(86, 180, 233), QColor(51, 34, 136),   QColor(153, 153, 51),  QColor(136, 34, 85),  QColor(17, 119, 51),
      QColor(102, 61, 20),  QColor(221, 204, 119), QColor(110, 110, 110), QColor(170, 68, 153), QColor(240, 228, 66)};
  const int n = static_cast<int>(colors.size());
  return colors[static_cast<std::size_t>(((color_index % n) + n) % n)];
}

std::vector<std::pair<std::string, int>> platform_color_indices(
    const std::vector<std::pair<std::string, int>>& device_platform_colors, std::vector<std::string> platforms) {
  std::map<std::string, int> chosen;
  std::set<int> used;
  for (const auto& [platform, index] : device_platform_colors) {
    used.insert(index);
    const auto it = chosen.find(platform);
    if (it == chosen.end() || index < it->second) chosen[platform] = index;
  }
  std::sort(platforms.begin(), platforms.end());
  for (const std::string& p : platforms) {
    if (chosen.count(p)) continue;
    int free = 0;
    while (used.count(free)) ++free;
    chosen[p] = free;
    used.insert(free);
  }
  return {chosen.begin(), chosen.end()};
}

Qt::PenStyle dims_pen_style(int dims) {
  switch (dims) {
    case 1:
      return Qt::DotLine;
    case 2:
      return Qt::DashLine;
    case 4:
      return Qt::SolidLine;
    default:
      return Qt::DashDotLine;
  }
}

int backend_marker_shape(const QString& backend) {
  const QString b = backend.toLower();
  if (b.contains("cuda")) return QCPScatterStyle::ssTriangle;
  if (b.contains("opencl")) return QCPScatterStyle::ssDiamond;
  if (b.contains("cpu")) return QCPScatterStyle::ssSquare;
  return QCPScatterStyle::ssCircle;
}

int run_marker_shape(const QString& backend, int repeat) {
  if (repeat <= 0) return backend_marker_shape(backend);
  static const std::array<int, 8> shapes = {QCPScatterStyle::ssCross,       QCPScatterStyle::ssPlus,
                                            QCPScatterStyle::ssStar,        QCPScatterStyle::ssTriangleInverted,
                                            QCPScatterStyle::ssCrossSquare, QCPScatterStyle::ssPlusSquare,
                                            QCPScatterStyle::ssCrossCircle, QCPScatterStyle::ssPlusCircle};
  return shapes[static_cast<std::size_t>(repeat - 1) % shapes.size()];
}

}  // namespace bs::ui
