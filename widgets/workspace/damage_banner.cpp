// SPDX-License-Identifier: GPL-3.0-or-later
#include "workspace/damage_banner.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

#include "common/reading_label.h"

namespace bs::ui {

DamageBanner::DamageBanner(QWidget* parent)
    : QFrame(parent), label_(reading_label(this)), remove_(new QPushButton(this)) {
  setObjectName(QStringLiteral("damageBanner"));
  setFrameShape(QFrame::StyledPanel);
  // A warning colour that reads on light and dark themes alike (text stays the palette's).
  setStyleSheet(QStringLiteral("#damageBanner { background: rgba(230, 160, 0, 60); border: 1px solid #c08000; }"));
  remove_->setText(tr("Remove damaged items…"));
  remove_->setToolTip(
      tr("Delete the damaged items listed here (after a confirmation); the workspace becomes "
         "writable again. Removing their imports from the workspace tree does the same."));
  auto* row = new QHBoxLayout(this);
  row->setContentsMargins(8, 4, 8, 4);
  row->addWidget(label_, 1);
  row->addWidget(remove_);
  connect(remove_, &QPushButton::clicked, this, &DamageBanner::remove_requested);
}

void DamageBanner::set_damage(const std::vector<WorkspaceDamage>& damage) {
  if (damage.empty()) {
    label_->clear();
    return;
  }
  QStringList lines;
  for (std::size_t i = 0; i < damage.size() && i < static_cast<std::size_t>(kShown); ++i)
    lines << QString::fromStdString(describe(damage[i])).toHtmlEscaped();
  if (damage.size() > static_cast<std::size_t>(kShown))
    lines << tr("… and %n more", nullptr, static_cast<int>(damage.size()) - kShown);
  label_->setText(tr("<b>Read-only: this workspace holds %n damaged item(s)</b>, left out of every view. Nothing "
                     "is written to it until they are removed.",
                     nullptr, static_cast<int>(damage.size())) +
                  "<br>" + lines.join("<br>"));
}

QString DamageBanner::text() const { return label_->text(); }

QString damage_list(const std::vector<WorkspaceDamage>& damage) {
  QStringList lines;
  for (const WorkspaceDamage& d : damage) lines << QString::fromStdString(describe(d));
  return lines.join('\n');
}

}  // namespace bs::ui
