// A dead-man joystick: the knob follows the mouse while the left button is held and springs back
// to the centre when it is released; the arrow keys do the same while held (the widget has to
// have the keyboard focus). Losing the focus or the mouse grab releases it too.
#pragma once

#include <QPointF>
#include <QWidget>

namespace k40t::rviz_panel {

class JoystickWidget : public QWidget {
  Q_OBJECT
 public:
  explicit JoystickWidget(QWidget* parent = nullptr);
  QSize sizeHint() const override { return {140, 140}; }
  QSize minimumSizeHint() const override { return {90, 90}; }
  QPointF deflection() const { return deflection_; }

 Q_SIGNALS:
  // right, up in -1..1 (inside the unit circle); (0, 0) when released.
  void deflected(double right, double up);

 protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  void keyReleaseEvent(QKeyEvent* event) override;
  void focusOutEvent(QFocusEvent* event) override;

 private:
  void followMouse(const QPoint& pos);
  void set(QPointF deflection);
  double radius() const;

  QPointF deflection_;
  QPointF keys_;  // the held arrow keys' part: -1, 0 or 1 per axis
  bool dragging_ = false;
};

}  // namespace k40t::rviz_panel
