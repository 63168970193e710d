#include "joystick_widget.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <algorithm>
#include <cmath>

namespace k40t::rviz_panel {

JoystickWidget::JoystickWidget(QWidget* parent) : QWidget(parent) {
  setFocusPolicy(Qt::StrongFocus);
  setToolTip("Hold the left button and drag, or hold the arrow keys: the gimbal turns while held");
}

double JoystickWidget::radius() const {
  return std::max(1.0, std::min(width(), height()) / 2.0 - 8.0);
}

void JoystickWidget::set(QPointF deflection) {
  const double length = std::hypot(deflection.x(), deflection.y());
  if (length > 1.0) deflection /= length;
  if (deflection == deflection_) return;
  deflection_ = deflection;
  update();
  Q_EMIT deflected(deflection_.x(), deflection_.y());
}

void JoystickWidget::followMouse(const QPoint& pos) {
  const QPointF centre(width() / 2.0, height() / 2.0);
  const QPointF offset = (QPointF(pos) - centre) / radius();
  set(QPointF(offset.x(), -offset.y()));
}

void JoystickWidget::mousePressEvent(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton) return;
  dragging_ = true;
  followMouse(event->pos());
}

void JoystickWidget::mouseMoveEvent(QMouseEvent* event) {
  if (dragging_) followMouse(event->pos());
}

void JoystickWidget::mouseReleaseEvent(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton) return;
  dragging_ = false;
  set(keys_);
}

void JoystickWidget::keyPressEvent(QKeyEvent* event) {
  QPointF keys = keys_;
  switch (event->key()) {
    case Qt::Key_Left:
      keys.setX(-1);
      break;
    case Qt::Key_Right:
      keys.setX(1);
      break;
    case Qt::Key_Up:
      keys.setY(1);
      break;
    case Qt::Key_Down:
      keys.setY(-1);
      break;
    default:
      QWidget::keyPressEvent(event);
      return;
  }
  keys_ = keys;
  if (!dragging_) set(keys_);
}

void JoystickWidget::keyReleaseEvent(QKeyEvent* event) {
  if (event->isAutoRepeat()) return;  // a held key repeats press/release pairs: not a release
  switch (event->key()) {
    case Qt::Key_Left:
    case Qt::Key_Right:
      keys_.setX(0);
      break;
    case Qt::Key_Up:
    case Qt::Key_Down:
      keys_.setY(0);
      break;
    default:
      QWidget::keyReleaseEvent(event);
      return;
  }
  if (!dragging_) set(keys_);
}

void JoystickWidget::focusOutEvent(QFocusEvent* event) {
  keys_ = QPointF();
  dragging_ = false;
  set(QPointF());
  QWidget::focusOutEvent(event);
}

void JoystickWidget::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.setRenderHint(QPainter::Antialiasing);
  const QPointF centre(width() / 2.0, height() / 2.0);
  const double r = radius();
  painter.setPen(QPen(palette().color(QPalette::Mid), 2));
  painter.setBrush(palette().color(QPalette::Base));
  painter.drawEllipse(centre, r, r);
  painter.drawLine(centre - QPointF(r, 0), centre + QPointF(r, 0));
  painter.drawLine(centre - QPointF(0, r), centre + QPointF(0, r));
  const QPointF knob = centre + QPointF(deflection_.x(), -deflection_.y()) * r;
  painter.setBrush(deflection_.isNull() ? palette().color(QPalette::Button)
                                        : palette().color(QPalette::Highlight));
  painter.drawEllipse(knob, 12, 12);
  if (hasFocus()) {
    painter.setPen(QPen(palette().color(QPalette::Highlight), 1, Qt::DashLine));
    painter.setBrush(Qt::NoBrush);
    painter.drawRect(rect().adjusted(1, 1, -2, -2));
  }
}

}  // namespace k40t::rviz_panel
