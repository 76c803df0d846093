// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <QObject>
#include <QStringList>

class QMenu;

namespace bs::ui {

// The "Recent workspaces" list, kept in QSettings (at most 8, newest first, missing files dropped).
class RecentFiles : public QObject {
  Q_OBJECT
 public:
  RecentFiles(QMenu* menu, QObject* parent);
  void add(const QString& path);
  QStringList paths() const;

 signals:
  void open_requested(const QString& path);

 private:
  void rebuild_menu();
  QMenu* menu_;
};

}  // namespace bs::ui
