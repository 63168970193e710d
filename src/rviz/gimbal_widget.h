// Gimbal controls: the dead-man joystick (gimbal/cmd_rate while held, a zero rate on release),
// centre, look down, and move to the angles typed in.
#pragma once

#include <QGroupBox>
#include <QTimer>

class QDoubleSpinBox;

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

  PodLink* link_;
  JoystickWidget* joystick_;
  QDoubleSpinBox* max_rate_;  // deg/s at full deflection
  QDoubleSpinBox* pitch_;     // deg, positive down (REP 103)
  QDoubleSpinBox* yaw_;       // deg, positive left
  // Repeats the rate while the joystick is held: the driver stops the gimbal when no command
  // came for cmd_rate_timeout (0.5 s), so a panel that dies mid-turn stops it too.
  QTimer repeat_;
};

}  // namespace k40t::rviz_panel
