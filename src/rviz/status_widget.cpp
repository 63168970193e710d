#include "status_widget.h"

#include <QFormLayout>
#include <QLabel>
#include <QTime>
#include <cmath>

namespace k40t::rviz_panel {
namespace {

constexpr qint64 kSilentMs = 2000;

QString degrees(double rad) {
  return QString::fromUtf8("%1°").arg(rad * 180.0 / M_PI, 0, 'f', 1);
}
QString celsius(double c) {
  return QString::fromUtf8("%1 °C").arg(c, 0, 'f', 1);
}

const char* levelName(int level) {
  switch (level) {
    case diagnostic_msgs::DiagnosticStatus::OK:
      return "OK";
    case diagnostic_msgs::DiagnosticStatus::WARN:
      return "WARN";
    case diagnostic_msgs::DiagnosticStatus::ERROR:
      return "ERROR";
    default:
      return "STALE";
  }
}

QString levelColour(int level) {
  return level == diagnostic_msgs::DiagnosticStatus::OK     ? "#2e7d32"
         : level == diagnostic_msgs::DiagnosticStatus::WARN ? "#e69500"
                                                            : "#c62828";
}

QLabel* value(const char* name, QWidget* parent) {
  auto* label = new QLabel("–", parent);
  label->setObjectName(name);
  label->setTextInteractionFlags(Qt::TextSelectableByMouse);
  label->setWordWrap(true);
  return label;
}

}  // namespace

StatusWidget::StatusWidget(QWidget* parent) : QGroupBox("Status", parent) {
  auto* form = new QFormLayout(this);
  form->addRow("Joints", joints_ = value("status_joints", this));
  form->addRow("Zoom", zoom_ = value("status_zoom", this));
  form->addRow("Thermal", thermal_ = value("status_thermal", this));
  form->addRow("Alarms", alarms_ = value("status_alarms", this));
  form->addRow("Laser", range_ = value("status_range", this));
  form->addRow("SD card", sd_ = value("status_sd", this));
  form->addRow("Photo", photo_ = value("status_photo", this));
  form->addRow("Record", record_ = value("status_record", this));
  form->addRow("Link", link_ = value("status_link", this));
  form->addRow("Driver", health_ = value("status_health", this));
  silence_check_.setInterval(500);
  connect(&silence_check_, &QTimer::timeout, this, &StatusWidget::checkSilence);
  silence_check_.start();
}

void StatusWidget::clear() {
  for (QLabel* label :
       {joints_, zoom_, thermal_, alarms_, range_, sd_, photo_, record_, link_, health_}) {
    label->setText("–");
  }
  since_joints_.invalidate();
  since_diagnostics_.invalidate();
}

void StatusWidget::showJoints(const sensor_msgs::JointState& msg) {
  since_joints_.start();
  QStringList parts;
  for (const char* axis : {"yaw", "pitch", "roll"}) {
    const std::string suffix = std::string(axis) + "_joint";
    for (size_t i = 0; i < msg.name.size() && i < msg.position.size(); ++i) {
      const std::string& n = msg.name[i];
      if (n.size() >= suffix.size() &&
          n.compare(n.size() - suffix.size(), suffix.size(), suffix) == 0) {
        parts << QString("%1 %2").arg(axis, degrees(msg.position[i]));
      }
    }
  }
  joints_->setText(parts.join("   "));
}

void StatusWidget::showVisible(const k40t_driver::VisibleStatus& msg) {
  zoom_->setText(QString("%1x, focal length %2 mm%3")
                     .arg(msg.zoom_ratio, 0, 'f', 1)
                     .arg(msg.focal_length_mm, 0, 'f', 1)
                     .arg(msg.zooming ? ", zooming" : ""));
}

void StatusWidget::showThermal(const k40t_driver::ThermalStats& msg) {
  thermal_->setText(
      QString("max %1   min %2   centre %3")
          .arg(celsius(msg.max_degC), celsius(msg.min_degC), celsius(msg.centre_degC)));
  QStringList raised;
  if (msg.high_alarm) raised << "high";
  if (msg.low_alarm) raised << "low";
  if (msg.difference_alarm) raised << "difference";
  if (msg.threshold_alarm) raised << "threshold";
  alarms_->setText(raised.isEmpty()
                       ? "none"
                       : QString("<b style='color:#c62828'>%1</b>").arg(raised.join(", ")));
}

void StatusWidget::showRange(const sensor_msgs::Range& msg) {
  const QString when = QString::fromUtf8(" (at %1)").arg(QTime::currentTime().toString("HH:mm:ss"));
  range_->setText((std::isfinite(msg.range) ? QString("%1 m").arg(msg.range, 0, 'f', 1)
                                            : QString("no return")) +
                  when);
}

void StatusWidget::showCamera(const k40t_driver::CameraStatus& msg) {
  sd_->setText(QString("%1, %2 of %3 MB free")
                   .arg(QString::fromStdString(msg.sd_state_text))
                   .arg(msg.sd_free_mb, 0, 'f', 0)
                   .arg(msg.sd_total_mb, 0, 'f', 0));
}

void StatusWidget::showPhoto(const k40t_driver::PhotoStatus& msg) {
  QString text = QString::fromStdString(msg.state_text);
  if (msg.burst_count > 0) text += QString(", %1 taken").arg(msg.burst_count);
  photo_->setText(text);
}

void StatusWidget::showRecord(const k40t_driver::RecordStatus& msg) {
  record_->setText(QString("%1, %2:%3")
                       .arg(QString::fromStdString(msg.state_text))
                       .arg(msg.duration_s / 60)
                       .arg(msg.duration_s % 60, 2, 10, QChar('0')));
}

void StatusWidget::showHealth(int level, int link_level, const QString& link_message,
                              const QString& others) {
  since_diagnostics_.start();
  link_->setText(
      QString("<b style='color:%1'>%2</b> %3")
          .arg(levelColour(link_level), levelName(link_level), link_message.toHtmlEscaped()));
  health_->setText(QString("<b style='color:%1'>%2</b> %3")
                       .arg(levelColour(level), levelName(level), others.toHtmlEscaped()));
}

void StatusWidget::checkSilence() {
  if (!since_diagnostics_.isValid() || since_diagnostics_.elapsed() > kSilentMs) {
    link_->setText(QString("<b style='color:%1'>ERROR</b> no diagnostics from the driver")
                       .arg(levelColour(diagnostic_msgs::DiagnosticStatus::ERROR)));
  }
  if (since_joints_.isValid() && since_joints_.elapsed() > kSilentMs) {
    joints_->setText(QString("no joint_states for %1 s").arg(since_joints_.elapsed() / 1000));
  }
}

}  // namespace k40t::rviz_panel
