// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The bar over the views while a workspace holds damaged items (store/workspace.h, WorkspaceDamage): which items
// are left out and why, that the workspace is read-only until they are removed, and the button that removes them
// (the user's word; nothing is written to a damaged workspace otherwise). docs/workspace-check.md.
#include <QFrame>
#include <vector>

#include "store/workspace.h"

class QLabel;
class QPushButton;

namespace bs::ui {

class DamageBanner : public QFrame {
  Q_OBJECT
 public:
  explicit DamageBanner(QWidget* parent = nullptr);
  // Says what is damaged (at most kShown items, then how many more). Whoever holds the banner shows or hides it
  // (in a QToolBar only the bar's visibility works).
  void set_damage(const std::vector<WorkspaceDamage>& damage);
  QString text() const;  // what the banner says, for tests and screen readers

  static constexpr int kShown = 6;

 signals:
  void remove_requested();

 private:
  QLabel* label_;
  QPushButton* remove_;
};

// The confirmation text that lists every damaged item before they are removed.
QString damage_list(const std::vector<WorkspaceDamage>& damage);

}  // namespace bs::ui
