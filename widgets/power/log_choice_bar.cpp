// SPDX-License-Identifier: GPL-3.0-or-later
#include "power/log_choice_bar.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <algorithm>

#include "common/wrapping_tool_bar.h"

namespace bs::ui {

LogChoiceBar::LogChoiceBar(QWidget* parent) : QWidget(parent), flow_(new FlowLayout(this, 8)) {
  setObjectName(QStringLiteral("logChoice"));
  flow_->setContentsMargins(0, 0, 0, 0);
  setToolTip(
      tr("The power log each platform's numbers come from. A platform with several logs uses the one chosen here "
         "(kept in the workspace, Ctrl+Z undoes); the report and benchscope-cli use the same one."));
}

void LogChoiceBar::set_logs(const std::vector<PowerTrace>& traces, const std::vector<std::int64_t>& ids) {
  // Later, not now: this may run inside a choice's own signal (the choice is stored, the views reload).
  while (QLayoutItem* item = flow_->takeAt(0)) {
    if (QWidget* w = item->widget()) {
      w->hide();
      w->deleteLater();
    }
    delete item;
  }
  // Platforms in first-seen order, each with its logs in the order given (the one in use first).
  std::vector<std::pair<std::string, std::vector<std::size_t>>> platforms;
  for (std::size_t i = 0; i < traces.size(); ++i) {
    auto it =
        std::find_if(platforms.begin(), platforms.end(), [&](const auto& p) { return p.first == traces[i].platform; });
    if (it == platforms.end()) it = platforms.insert(platforms.end(), {traces[i].platform, {}});
    it->second.push_back(i);
  }
  QStringList said;
  if (!platforms.empty()) flow_->addWidget(new QLabel(tr("Power logs:"), this));
  for (const auto& [platform, logs] : platforms) {
    const QString name = QString::fromStdString(platform);
    const QString used = QString::fromStdString(traces[logs.front()].label);
    if (logs.size() == 1) {
      auto* label = new QLabel(tr("%1: %2").arg(name, used), this);
      label->setToolTip(tr("%1 has one power log").arg(name));
      flow_->addWidget(label);
      said << tr("%1: %2").arg(name, used);
      continue;
    }
    auto* item = new QWidget(this);
    auto* row = new QHBoxLayout(item);
    row->setContentsMargins(0, 0, 0, 0);
    auto* label = new QLabel(tr("Power log of %1:").arg(name), item);
    auto* box = new QComboBox(item);
    box->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    label->setBuddy(box);
    for (std::size_t i : logs) {
      const std::int64_t id = i < ids.size() ? ids[i] : 0;
      box->addItem(QString::fromStdString(traces[i].label), QVariant::fromValue<qint64>(id));
      box->setItemData(
          box->count() - 1,
          tr("%1, from %2")
              .arg(QString::fromStdString(traces[i].label), QString::fromStdString(traces[i].provenance.source_file)),
          Qt::ToolTipRole);
    }
    box->setToolTip(tr("%1 has %2 power logs; its numbers come from the one shown").arg(name).arg(logs.size()));
    connect(box, &QComboBox::activated, this, [this, box, name](int index) {
      const qint64 id = box->itemData(index).value<qint64>();
      if (index > 0 && id > 0) emit log_chosen(name, id);  // index 0 is the log in use
    });
    row->addWidget(label);
    row->addWidget(box);
    flow_->addWidget(item);
    said << tr("%1: %2 (1 of %3 logs)").arg(name, used).arg(logs.size());
  }
  text_ = said.join("; ");
  setVisible(!platforms.empty());
  updateGeometry();
}

QString LogChoiceBar::text() const { return text_; }

}  // namespace bs::ui
