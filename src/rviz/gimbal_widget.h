// Gimbal controls: the dead-man joystick (gimbal/cmd_rate while held, a zero rate on release),
// centre, look down, move to the angles typed in, and "Look at clicked point" (gimbal/look_at_point
// with the point clicked with rviz's Publish Point tool, repeated while the button is down).
#pragma once

#include <QGroupBox>
#include <QTimer>

class QDoubleSpinBox;
class QPushButton;

namespace k40t::rviz_panel {

class JoystickWidget;
class PodLink;

class GimbalWidget : public QGroupBox {
  Q_OBJECT
 public:
  GimbalWidget(PodLink* link, QWidget* parent = nullptr);

 private:
  void onDeflected(double right, double up);
  void publishRate();
  void lookAtClicked(bool on);

  PodLink* link_;
  JoystickWidget* joystick_;
  QDoubleSpinBox* max_rate_;  // deg/s at full deflection
  QDoubleSpinBox* pitch_;     // deg, positive down (REP 103)
  QDoubleSpinBox* yaw_;       // deg, positive left
  // Repeats the rate while the joystick is held: the driver stops the gimbal when no command
  // came for cmd_rate_timeout (0.5 s), so a panel that dies mid-turn stops it too.
  QTimer repeat_;
  QPushButton* look_at_;
  // Repeats the clicked point while "Look at clicked point" is down: the driver stops following
  // when none came for look_at_point_timeout (1 s).
  QTimer look_at_repeat_;
};

}  // namespace k40t::rviz_panel
