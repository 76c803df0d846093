// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Two draggable time cursors (A and B) on a QCustomPlot and the selection between them, for the Power tab.
// Mouse: Shift + drag on the plot draws a new selection (A at the press, B following the mouse); a press within a
// few pixels of a cursor drags that cursor; a plain drag still pans. Keys (plot focused): A / B put that cursor at
// the mouse, Esc clears both. Every move emits changed(false); the end of a drag or a key emits changed(true), when
// the costlier exact statistics (percentiles) are worth computing.
#include <QObject>
#include <QPointer>
#include <algorithm>
#include <optional>

class QCustomPlot;
class QCPItemRect;
class QCPItemStraightLine;
class QCPItemText;
class QMouseEvent;

namespace bs::ui {

class PowerCursors : public QObject {
  Q_OBJECT
 public:
  explicit PowerCursors(QCustomPlot* plot);
  // Positions on the plot's time axis (its own units: seconds, or seconds since 1970 with the wall-clock axis).
  std::optional<double> a() const { return a_; }
  std::optional<double> b() const { return b_; }
  bool has_selection() const { return a_ && b_ && *a_ != *b_; }
  // The value-axis position where the last selection was drawn (Shift + press): the trace nearest to it is the one
  // the user drew the selection on (a phase saved from it belongs to that log). nullopt: set by keys or set().
  std::optional<double> drawn_at() const { return drawn_at_; }
  double from() const { return std::min(a_.value_or(0), b_.value_or(0)); }
  double to() const { return std::max(a_.value_or(0), b_.value_or(0)); }
  void set(std::optional<double> a, std::optional<double> b);  // emits changed(true)
  void clear() { set(std::nullopt, std::nullopt); }
  // Shifts both cursors (the time axis moved under them: wall clock on or off, an overlay offset).
  void shift(double by);
  // QCustomPlot::clearItems() also removes the cursors' items: call this afterwards to bring them back.
  void rebuild_items();

 signals:
  void changed(bool final);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  enum class Drag { None, A, B };
  void press(QMouseEvent* e);
  void move(QMouseEvent* e);
  void release();
  void place();  // moves the items to a_/b_ and replots
  QCustomPlot* plot_;
  QPointer<QCPItemStraightLine> line_a_, line_b_;
  QPointer<QCPItemRect> band_;
  QPointer<QCPItemText> label_a_, label_b_;
  std::optional<double> a_, b_;
  std::optional<double> drawn_at_;
  Drag drag_ = Drag::None;
  double mouse_x_ = 0;  // last mouse position on the time axis, for the A / B keys
};

}  // namespace bs::ui
