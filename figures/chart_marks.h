// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One look for a flagged value in every chart (report, paper figures, Efficiency tab, FLOPS tab): the value is
// drawn where it is, never replaced or capped, and marked: a bar hatched instead of filled, a point as a hollow
// marker, a label with "⚠" and the footnote number of the table that gives the reason.
#include <QColor>
#include <QString>

class QCPBars;
class QCPGraph;

namespace bs::ui {

inline const QColor kFlagColor{0x8a, 0x4b, 0x00};  // the tables' flag colour

// Diagonal hatching in `color` over white, outline in the darker colour.
void mark_flagged_bars(QCPBars* bars, const QColor& color);
bool is_flagged_bars(const QCPBars* bars);
// The graph's scatter markers drawn hollow (white fill) and one size larger.
void mark_flagged_points(QCPGraph* graph, const QColor& color);
bool is_flagged_points(const QCPGraph* graph);
// "5.25 TFLOPS ⚠[1]"; "5.25 TFLOPS ⚠" without a footnote number.
QString flag_label(const QString& value, const QString& marker = {});

}  // namespace bs::ui
