// What the pod reports, as text: joint angles, zoom, thermal statistics and alarms, laser range,
// SD card, photo and recording state, and the link's health from /diagnostics.
#pragma once

#include <QElapsedTimer>
#include <QGroupBox>
#include <QTimer>

#include "pod_link.h"

class QLabel;

namespace k40t::rviz_panel {

class StatusWidget : public QGroupBox {
  Q_OBJECT
 public:
  explicit StatusWidget(QWidget* parent = nullptr);

  void showJoints(const sensor_msgs::JointState& msg);
  void showVisible(const k40t_driver::VisibleStatus& msg);
  void showThermal(const k40t_driver::ThermalStats& msg);
  void showRange(const sensor_msgs::Range& msg);
  void showCamera(const k40t_driver::CameraStatus& msg);
  void showPhoto(const k40t_driver::PhotoStatus& msg);
  void showRecord(const k40t_driver::RecordStatus& msg);
  void showHealth(int level, int link_level, const QString& link_message, const QString& others);
  // Forget everything (a new namespace).
  void clear();

 private:
  void checkSilence();

  QLabel* joints_;
  QLabel* zoom_;
  QLabel* thermal_;
  QLabel* alarms_;
  QLabel* range_;
  QLabel* sd_;
  QLabel* photo_;
  QLabel* record_;
  QLabel* link_;
  QLabel* health_;
  QElapsedTimer since_joints_;       // the driver publishes joint_states at 10 Hz while linked
  QElapsedTimer since_diagnostics_;  // and diagnostics every 0.25 s
  QTimer silence_check_;
};

}  // namespace k40t::rviz_panel
