// The panel's only way to the pod: the driver's public ROS interface under one namespace
// (docs/ros_interface.md). Topic callbacks arrive on the Qt GUI thread (rviz spins the global
// callback queue there) and are forwarded as signals; service calls run on a ServiceWorker and
// their outcome comes back as callFinished(), queued to the GUI thread.
#pragma once

#include <QObject>
#include <QString>
#include <QStringList>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <dynamic_reconfigure/Config.h>
#include <geometry_msgs/PointStamped.h>
#include <k40t_driver/CameraStatus.h>
#include <k40t_driver/PhotoStatus.h>
#include <k40t_driver/RecordStatus.h>
#include <k40t_driver/ThermalStats.h>
#include <k40t_driver/VisibleStatus.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <sensor_msgs/Range.h>

#include "service_worker.h"

namespace k40t::rviz_panel {

class PodLink : public QObject {
  Q_OBJECT
 public:
  explicit PodLink(QObject* parent = nullptr);
  ~PodLink() override;

  // Subscribes and advertises under `ns` (e.g. "/k40t"); false (and nothing connected) when it
  // is not a valid ROS name.
  bool setNamespace(const QString& ns);
  QString ns() const { return ns_; }
  // Joins the service thread (waits at most for the call in progress) and disconnects; the
  // commands below then do nothing.
  void shutdown();

  // gimbal/cmd_rate, rad/s (REP 103: pitch positive = down, yaw positive = left).
  void publishRate(double pitch_rate, double yaw_rate);
  // "Look at clicked point": the last point rviz's Publish Point tool sent (/clicked_point, in
  // rviz's fixed frame) since forgetClicked(), published again on gimbal/look_at_point; the
  // driver follows it while it keeps coming (its look_at_point_timeout dead-man).
  void publishLookAt();
  void forgetClicked() { clicked_.reset(); }
  // Service calls: each outcome arrives as callFinished(what, success, message).
  void trigger(const QString& relative_service);  // std_srvs/Trigger, e.g. "gimbal/center"
  void setAngle(double pitch, double yaw);
  void setZoom(double ratio);
  void zoom(uint8_t action);  // k40t_driver/Zoom ZOOM_IN, ZOOM_OUT, STOP, ...
  void setPalette(int palette);
  // An int parameter of the driver node's dynamic_reconfigure ("image_mode", "camera_mode").
  void setParameter(const QString& name, int value);
  void takePhoto();
  void record(bool start);
  void measureRange();

 Q_SIGNALS:
  void jointState(const sensor_msgs::JointState& msg);
  void visibleStatus(const k40t_driver::VisibleStatus& msg);
  void thermalStats(const k40t_driver::ThermalStats& msg);
  void laserRange(const sensor_msgs::Range& msg);
  void cameraStatus(const k40t_driver::CameraStatus& msg);
  void photoStatus(const k40t_driver::PhotoStatus& msg);
  void recordStatus(const k40t_driver::RecordStatus& msg);
  // Each int parameter of the driver's current configuration (parameter_updates).
  void settingChanged(const QString& name, int value);
  // From /diagnostics: the worst level (diagnostic_msgs/DiagnosticStatus) of the driver's
  // statuses, the level and message of its link status, and the statuses that are not OK.
  void health(int level, int link_level, const QString& link_message, const QString& others);
  void callFinished(const QString& what, bool success, const QString& message);
  void clickedPoint(const QString& where);  // a point came on /clicked_point

 private:
  template <class Srv>
  void call(const QString& what, const std::string& relative, Srv srv);
  void onDiagnostics(const diagnostic_msgs::DiagnosticArray& array);
  void onConfig(const dynamic_reconfigure::Config& config);

  QString ns_;
  std::string diagnostic_prefix_;  // "k40t/": the driver's statuses start with its node name
  std::map<std::string, diagnostic_msgs::DiagnosticStatus> statuses_;
  std::unique_ptr<ros::NodeHandle> nh_;
  std::vector<ros::Subscriber> subscribers_;
  ros::Publisher rate_pub_;
  ros::Publisher look_at_pub_;
  std::optional<geometry_msgs::PointStamped> clicked_;
  std::unique_ptr<ServiceWorker> worker_;
};

}  // namespace k40t::rviz_panel
