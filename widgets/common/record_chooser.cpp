// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/record_chooser.h"

#include <QComboBox>
#include <QSignalBlocker>
#include <algorithm>

namespace bs::ui {

void shape_record_chooser(QComboBox* chooser, const QString& tip) {
  chooser->setToolTip(tip);
  chooser->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  chooser->setMinimumContentsLength(28);
}

void refill_record_chooser(QComboBox* chooser, const std::vector<RecordEntry>& entries, std::int64_t& newest_seen) {
  const std::int64_t shown = chooser->currentIndex() >= 0 ? chooser->currentData().toLongLong() : -1;
  const QSignalBlocker block(chooser);
  chooser->clear();
  std::int64_t newest = -1;
  for (const RecordEntry& e : entries) {
    chooser->addItem(e.text, QVariant::fromValue<qint64>(e.id));
    newest = std::max(newest, e.id);
  }
  const bool arrived = newest > newest_seen;
  newest_seen = std::max(newest_seen, newest);
  const int again = chooser->findData(QVariant::fromValue<qint64>(shown));
  chooser->setCurrentIndex(again >= 0 && !arrived ? again : chooser->findData(QVariant::fromValue<qint64>(newest)));
}

}  // namespace bs::ui
