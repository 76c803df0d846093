// SPDX-License-Identifier: GPL-3.0-or-later
#include "power/power_cursors.h"

#include <qcustomplot.h>
#include <QKeyEvent>
#include <QMouseEvent>
#include <cmath>

namespace bs::ui {
namespace {

constexpr double kGrabPx = 6;  // how close to a cursor line a press grabs it
const QColor kColorA(0xd6, 0x27, 0x28), kColorB(0x1f, 0x77, 0xb4);

}  // namespace

PowerCursors::PowerCursors(QCustomPlot* plot) : QObject(plot), plot_(plot) {
  plot_->installEventFilter(this);
  plot_->setFocusPolicy(Qt::StrongFocus);  // A / B / Esc reach the plot
  plot_->setMouseTracking(true);
  rebuild_items();
}

void PowerCursors::rebuild_items() {
  // Items removed by clearItems() are deleted; QPointer notices, so only missing ones are made again.
  if (!band_) {
    band_ = new QCPItemRect(plot_);
    band_->topLeft->setTypeY(QCPItemPosition::ptAxisRectRatio);
    band_->bottomRight->setTypeY(QCPItemPosition::ptAxisRectRatio);
    band_->setPen(Qt::NoPen);
    band_->setBrush(QColor(0x80, 0x80, 0x80, 40));
    band_->setSelectable(false);
  }
  const auto make_line = [&](QPointer<QCPItemStraightLine>& line, QPointer<QCPItemText>& label, const QColor& c,
                             const char* name) {
    if (!line) {
      line = new QCPItemStraightLine(plot_);
      line->setPen(QPen(c, 1.5));
      line->setSelectable(false);
    }
    if (!label) {
      label = new QCPItemText(plot_);
      label->position->setTypeY(QCPItemPosition::ptAxisRectRatio);
      label->setPositionAlignment(Qt::AlignBottom | Qt::AlignHCenter);
      label->setText(QString::fromLatin1(name));
      label->setColor(Qt::white);
      label->setBrush(c);
      label->setPadding(QMargins(3, 1, 3, 1));
      label->setClipToAxisRect(false);
      label->setSelectable(false);
    }
  };
  make_line(line_a_, label_a_, kColorA, "A");
  make_line(line_b_, label_b_, kColorB, "B");
  place();
}

void PowerCursors::place() {
  const auto put = [](QCPItemStraightLine* line, QCPItemText* label, std::optional<double> x) {
    line->setVisible(x.has_value());
    label->setVisible(x.has_value());
    if (!x) return;
    line->point1->setCoords(*x, 0);
    line->point2->setCoords(*x, 1);
    label->position->setCoords(*x, 0);
  };
  put(line_a_, label_a_, a_);
  put(line_b_, label_b_, b_);
  band_->setVisible(has_selection());
  if (has_selection()) {
    band_->topLeft->setCoords(from(), 0);
    band_->bottomRight->setCoords(to(), 1);
  }
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

void PowerCursors::set(std::optional<double> a, std::optional<double> b) {
  a_ = a;
  b_ = b;
  drawn_at_.reset();
  place();
  emit changed(true);
}

void PowerCursors::shift(double by) {
  if (a_) *a_ += by;
  if (b_) *b_ += by;
  place();
  emit changed(true);
}

bool PowerCursors::eventFilter(QObject* watched, QEvent* event) {
  if (watched != plot_) return false;
  switch (event->type()) {
    case QEvent::MouseButtonPress: {
      auto* e = static_cast<QMouseEvent*>(event);
      if (e->button() != Qt::LeftButton) return false;
      press(e);
      return drag_ != Drag::None;  // swallowed: the plot must not pan while a cursor moves
    }
    case QEvent::MouseMove: {
      auto* e = static_cast<QMouseEvent*>(event);
      mouse_x_ = plot_->xAxis->pixelToCoord(e->position().x());
      if (drag_ == Drag::None) {
        const bool near_a = a_ && std::abs(plot_->xAxis->coordToPixel(*a_) - e->position().x()) <= kGrabPx;
        const bool near_b = b_ && std::abs(plot_->xAxis->coordToPixel(*b_) - e->position().x()) <= kGrabPx;
        plot_->setCursor(near_a || near_b ? Qt::SizeHorCursor : Qt::ArrowCursor);
        return false;
      }
      move(e);
      return true;
    }
    case QEvent::MouseButtonRelease:
      if (drag_ == Drag::None) return false;
      release();
      return true;
    case QEvent::KeyPress: {
      const int key = static_cast<QKeyEvent*>(event)->key();
      if (key == Qt::Key_A)
        set(mouse_x_, b_);
      else if (key == Qt::Key_B)
        set(a_, mouse_x_);
      else if (key == Qt::Key_Escape)
        clear();
      else
        return false;
      return true;
    }
    default:
      return false;
  }
}

void PowerCursors::press(QMouseEvent* e) {
  const double px = e->position().x();
  const double x = plot_->xAxis->pixelToCoord(px);
  mouse_x_ = x;
  if (!plot_->axisRect()->rect().contains(e->position().toPoint())) return;
  plot_->setFocus();
  if (e->modifiers() & Qt::ShiftModifier) {  // a new selection from here
    a_ = x;
    b_ = x;
    drawn_at_ = plot_->yAxis->pixelToCoord(e->position().y());
    drag_ = Drag::B;
  } else if (b_ && std::abs(plot_->xAxis->coordToPixel(*b_) - px) <= kGrabPx) {
    drag_ = Drag::B;
  } else if (a_ && std::abs(plot_->xAxis->coordToPixel(*a_) - px) <= kGrabPx) {
    drag_ = Drag::A;
  } else {
    return;
  }
  place();
  emit changed(false);
}

void PowerCursors::move(QMouseEvent* e) {
  const double x = plot_->xAxis->pixelToCoord(e->position().x());
  (drag_ == Drag::A ? a_ : b_) = x;
  place();
  emit changed(false);
}

void PowerCursors::release() {
  drag_ = Drag::None;
  emit changed(true);
}

}  // namespace bs::ui
