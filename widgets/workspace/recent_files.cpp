// SPDX-License-Identifier: GPL-3.0-or-later
#include "workspace/recent_files.h"

#include <QFileInfo>
#include <QMenu>
#include <QSettings>

namespace bs::ui {
namespace {
constexpr int kMaxRecent = 8;
const char* kKey = "recentWorkspaces";
}  // namespace

RecentFiles::RecentFiles(QMenu* menu, QObject* parent) : QObject(parent), menu_(menu) { rebuild_menu(); }

QStringList RecentFiles::paths() const {
  QStringList list = QSettings().value(kKey).toStringList();
  list.erase(std::remove_if(list.begin(), list.end(), [](const QString& p) { return !QFileInfo::exists(p); }),
             list.end());
  return list;
}

void RecentFiles::add(const QString& path) {
  QStringList list = paths();
  const QString abs = QFileInfo(path).absoluteFilePath();
  list.removeAll(abs);
  list.prepend(abs);
  while (list.size() > kMaxRecent) list.removeLast();
  QSettings().setValue(kKey, list);
  rebuild_menu();
}

void RecentFiles::rebuild_menu() {
  menu_->clear();
  const QStringList list = paths();
  for (int i = 0; i < list.size(); ++i) {
    QAction* a = menu_->addAction(QStringLiteral("&%1 %2").arg(i + 1).arg(QFileInfo(list[i]).fileName()));
    a->setToolTip(list[i]);
    const QString p = list[i];
    connect(a, &QAction::triggered, this, [this, p] { emit open_requested(p); });
  }
  menu_->setEnabled(!list.isEmpty());
}

}  // namespace bs::ui
