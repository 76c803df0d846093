// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A label of text to read and copy (a record's source, a command line, a robot's status or job, a ceiling, a
// decision): it wraps instead of widening the window, and the mouse selects it for pasting elsewhere. The views set
// up such labels alike in a dozen places.
#include <QString>

class QLabel;
class QWidget;

namespace bs::ui {

QLabel* reading_label(QWidget* parent, const QString& text = {});

}  // namespace bs::ui
