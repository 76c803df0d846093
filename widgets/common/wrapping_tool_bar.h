// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A tool bar whose buttons wrap onto more rows when the window is narrow, instead of hiding behind QToolBar's "»"
// (issue #32.7: at 1280x800 the Lens tab hid "Calibrate from checkerboard…" there). It shows the actions of a
// QToolBar (kept hidden, so code that adds actions to the tool bar keeps working), one button per action, a thin
// line per separator, in a flow layout whose height follows its width.
#include <QLayout>
#include <QWidget>

class QToolBar;

namespace bs::ui {

// Lays out its items left to right and starts a new row where the width runs out (Qt's flow layout example).
class FlowLayout : public QLayout {
 public:
  explicit FlowLayout(QWidget* parent = nullptr, int spacing = 4);
  ~FlowLayout() override;
  void addItem(QLayoutItem* item) override;
  int count() const override { return static_cast<int>(items_.size()); }
  QLayoutItem* itemAt(int index) const override;
  QLayoutItem* takeAt(int index) override;
  Qt::Orientations expandingDirections() const override { return {}; }
  bool hasHeightForWidth() const override { return true; }
  int heightForWidth(int width) const override { return arrange(QRect(0, 0, width, 0), false); }
  QSize minimumSize() const override;
  QSize sizeHint() const override { return minimumSize(); }
  void setGeometry(const QRect& rect) override;

 private:
  int arrange(const QRect& rect, bool apply) const;
  QList<QLayoutItem*> items_;
  int spacing_;
};

class WrappingToolBar : public QWidget {
  Q_OBJECT
 public:
  // Mirrors `bar`'s actions, now and as they are added; hides `bar`.
  explicit WrappingToolBar(QToolBar* bar, QWidget* parent = nullptr);
  bool eventFilter(QObject* watched, QEvent* event) override;
  int button_count() const;  // buttons shown (tests)

 private:
  void rebuild();
  QToolBar* bar_;
  FlowLayout* flow_;
};

}  // namespace bs::ui
