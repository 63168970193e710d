#include "gimbal_widget.h"

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>
#include <cmath>

#include "joystick_widget.h"
#include "pod_link.h"

namespace k40t::rviz_panel {
namespace {

constexpr double kRepeatPeriodMs = 100;  // well inside the driver's 0.5 s dead-man timeout
constexpr double kLookAtPeriodMs = 200;  // well inside look_at_point_timeout (1 s)

double radians(double degrees) {
  return degrees * M_PI / 180.0;
}

QDoubleSpinBox* degreesBox(const char* name, double min, double max, double value,
                           QWidget* parent) {
  auto* box = new QDoubleSpinBox(parent);
  box->setObjectName(name);
  box->setRange(min, max);
  box->setDecimals(1);
  box->setValue(value);
  box->setSuffix(QString::fromUtf8(" °"));
  return box;
}

}  // namespace

GimbalWidget::GimbalWidget(PodLink* link, QWidget* parent)
    : QGroupBox("Gimbal", parent), link_(link) {
  joystick_ = new JoystickWidget(this);
  joystick_->setObjectName("gimbal_joystick");
  max_rate_ = new QDoubleSpinBox(this);
  max_rate_->setObjectName("gimbal_max_rate");
  max_rate_->setRange(1, 30);  // the pod's dial speeds (0x000017)
  max_rate_->setValue(20);
  max_rate_->setSuffix(QString::fromUtf8(" °/s"));
  auto* centre = new QPushButton("Centre", this);
  centre->setObjectName("gimbal_center");
  auto* look_down = new QPushButton("Look down", this);
  look_down->setObjectName("gimbal_look_down");
  // The ranges of gimbal/set_angle (docs/ros_interface.md), in degrees.
  pitch_ = degreesBox("gimbal_pitch", -30, 90, 0, this);
  yaw_ = degreesBox("gimbal_yaw", -180, 180, 0, this);
  pitch_->setToolTip("Pitch, positive looks down");
  yaw_->setToolTip("Yaw, positive turns left");
  auto* move = new QPushButton("Move", this);
  move->setObjectName("gimbal_move");
  look_at_ = new QPushButton("Look at clicked point", this);
  look_at_->setObjectName("gimbal_look_at_clicked");
  look_at_->setCheckable(true);
  look_at_->setToolTip(
      "While down, the gimbal follows the point clicked with rviz's Publish Point tool");

  auto* side = new QGridLayout;
  side->addWidget(new QLabel("Max rate", this), 0, 0);
  side->addWidget(max_rate_, 0, 1);
  side->addWidget(centre, 1, 0);
  side->addWidget(look_down, 1, 1);
  side->addWidget(new QLabel("Pitch", this), 2, 0);
  side->addWidget(pitch_, 2, 1);
  side->addWidget(new QLabel("Yaw", this), 3, 0);
  side->addWidget(yaw_, 3, 1);
  side->addWidget(move, 4, 0, 1, 2);
  side->addWidget(look_at_, 5, 0, 1, 2);
  side->setRowStretch(6, 1);
  auto* layout = new QHBoxLayout(this);
  layout->addWidget(joystick_, 1);
  layout->addLayout(side);

  repeat_.setInterval(kRepeatPeriodMs);
  connect(&repeat_, &QTimer::timeout, this, &GimbalWidget::publishRate);
  connect(joystick_, &JoystickWidget::deflected, this, &GimbalWidget::onDeflected);
  connect(centre, &QPushButton::clicked, this, [this] { link_->trigger("gimbal/center"); });
  connect(look_down, &QPushButton::clicked, this, [this] { link_->trigger("gimbal/look_down"); });
  connect(move, &QPushButton::clicked, this,
          [this] { link_->setAngle(radians(pitch_->value()), radians(yaw_->value())); });
  look_at_repeat_.setInterval(kLookAtPeriodMs);
  connect(&look_at_repeat_, &QTimer::timeout, this, [this] { link_->publishLookAt(); });
  connect(look_at_, &QPushButton::toggled, this, &GimbalWidget::lookAtClicked);
  connect(link_, &PodLink::clickedPoint, this, [this](const QString& where) {
    if (look_at_->isChecked()) look_at_->setToolTip("Looking at " + where);
  });
}

// Down: only points clicked from now on are followed; up: the points stop, and with them the
// following (the driver's dead-man).
void GimbalWidget::lookAtClicked(bool on) {
  if (on) {
    link_->forgetClicked();
    look_at_repeat_.start();
  } else {
    look_at_repeat_.stop();
  }
}

void GimbalWidget::onDeflected(double right, double up) {
  publishRate();
  if (right == 0 && up == 0) {
    repeat_.stop();  // released: the zero rate just published stops the gimbal
  } else if (!repeat_.isActive()) {
    repeat_.start();
  }
}

// Joystick up = the camera looks up = negative pitch rate; right = negative yaw rate (REP 103).
void GimbalWidget::publishRate() {
  const QPointF d = joystick_->deflection();
  const double max = radians(max_rate_->value());
  link_->publishRate(-d.y() * max, -d.x() * max);
}

}  // namespace k40t::rviz_panel
