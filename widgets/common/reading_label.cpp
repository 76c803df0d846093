// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/reading_label.h"

#include <QLabel>

namespace bs::ui {

QLabel* reading_label(QWidget* parent, const QString& text) {
  auto* label = new QLabel(text, parent);
  label->setWordWrap(true);
  label->setTextInteractionFlags(Qt::TextSelectableByMouse);
  return label;
}

}  // namespace bs::ui
