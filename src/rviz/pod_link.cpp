#include "pod_link.h"

#include <algorithm>
#include <utility>

#include <dynamic_reconfigure/Reconfigure.h>
#include <geometry_msgs/Twist.h>
#include <k40t_driver/MeasureRange.h>
#include <k40t_driver/Record.h>
#include <k40t_driver/SetAngle.h>
#include <k40t_driver/SetPalette.h>
#include <k40t_driver/SetZoom.h>
#include <k40t_driver/TakePhoto.h>
#include <k40t_driver/Zoom.h>
#include <std_srvs/Trigger.h>

namespace k40t::rviz_panel {
namespace {

// The driver node's name in its namespace (launch/k40t.launch): where dynamic_reconfigure lives.
constexpr char kDriverNode[] = "driver";

QString text(const std::string& s) {
  return QString::fromStdString(s);
}

QString noAnswer(ros::ServiceClient client) {  // getService() is not const
  return text("no answer from " + client.getService() + " (is the driver running?)");
}

// Subscribes `topic` and forwards each message to `signal` of `link` (on the thread that spins
// the global queue: rviz's GUI thread).
template <class Msg>
ros::Subscriber forward(ros::NodeHandle& nh, const std::string& topic, PodLink* link,
                        void (PodLink::*signal)(const Msg&)) {
  return nh.subscribe<Msg>(
      topic, 10, [link, signal](const typename Msg::ConstPtr& msg) { (link->*signal)(*msg); });
}

}  // namespace

PodLink::PodLink(QObject* parent) : QObject(parent), worker_(std::make_unique<ServiceWorker>()) {}

PodLink::~PodLink() {
  shutdown();
}

void PodLink::shutdown() {
  worker_.reset();  // no call may report to a half-destroyed link or panel
  subscribers_.clear();
  rate_pub_ = ros::Publisher();
  look_at_pub_ = ros::Publisher();
  nh_.reset();
}

bool PodLink::setNamespace(const QString& ns) {
  if (!worker_) return false;
  subscribers_.clear();
  rate_pub_ = ros::Publisher();
  look_at_pub_ = ros::Publisher();
  nh_.reset();
  statuses_.clear();
  ns_ = ns;
  std::string error;
  if (ns.trimmed().isEmpty() || !ros::names::validate(ns.toStdString(), error)) return false;
  try {
    nh_ = std::make_unique<ros::NodeHandle>(ns.toStdString());
  } catch (const ros::Exception&) {
    return false;
  }
  diagnostic_prefix_ = nh_->getNamespace().substr(1) + "/";  // "/k40t" -> "k40t/"
  ros::NodeHandle& nh = *nh_;
  subscribers_.push_back(forward(nh, "joint_states", this, &PodLink::jointState));
  subscribers_.push_back(forward(nh, "visible/status", this, &PodLink::visibleStatus));
  subscribers_.push_back(forward(nh, "thermal/stats", this, &PodLink::thermalStats));
  subscribers_.push_back(forward(nh, "laser/range", this, &PodLink::laserRange));
  subscribers_.push_back(forward(nh, "camera/status", this, &PodLink::cameraStatus));
  subscribers_.push_back(forward(nh, "photo/status", this, &PodLink::photoStatus));
  subscribers_.push_back(forward(nh, "record/status", this, &PodLink::recordStatus));
  subscribers_.push_back(nh.subscribe<dynamic_reconfigure::Config>(
      std::string(kDriverNode) + "/parameter_updates", 1,
      [this](const dynamic_reconfigure::Config::ConstPtr& msg) { onConfig(*msg); }));
  subscribers_.push_back(nh.subscribe<diagnostic_msgs::DiagnosticArray>(
      "/diagnostics", 20,
      [this](const diagnostic_msgs::DiagnosticArray::ConstPtr& msg) { onDiagnostics(*msg); }));
  rate_pub_ = nh.advertise<geometry_msgs::Twist>("gimbal/cmd_rate", 1);
  look_at_pub_ = nh.advertise<geometry_msgs::PointStamped>("gimbal/look_at_point", 1);
  subscribers_.push_back(nh.subscribe<geometry_msgs::PointStamped>(
      "/clicked_point", 1, [this](const geometry_msgs::PointStamped::ConstPtr& msg) {
        clicked_ = *msg;
        Q_EMIT clickedPoint(QString("%1 %2 %3 in %4")
                                .arg(msg->point.x, 0, 'f', 1)
                                .arg(msg->point.y, 0, 'f', 1)
                                .arg(msg->point.z, 0, 'f', 1)
                                .arg(QString::fromStdString(msg->header.frame_id)));
      }));
  return true;
}

void PodLink::publishLookAt() {
  if (!look_at_pub_ || !clicked_) return;
  geometry_msgs::PointStamped point = *clicked_;
  point.header.stamp = ros::Time::now();
  look_at_pub_.publish(point);
}

void PodLink::publishRate(double pitch_rate, double yaw_rate) {
  if (!rate_pub_) return;
  geometry_msgs::Twist twist;
  twist.angular.y = pitch_rate;
  twist.angular.z = yaw_rate;
  rate_pub_.publish(twist);
}

template <class Srv>
void PodLink::call(const QString& what, const std::string& relative, Srv srv) {
  if (!nh_) {
    Q_EMIT callFinished(what, false, "no valid driver namespace set");
    return;
  }
  ros::ServiceClient client = nh_->serviceClient<Srv>(relative);
  worker_->post([this, what, client, srv]() mutable {
    if (!client.call(srv)) {
      Q_EMIT callFinished(what, false, noAnswer(client));
      return;
    }
    Q_EMIT callFinished(what, srv.response.success, text(srv.response.message));
  });
}

void PodLink::trigger(const QString& relative_service) {
  call(relative_service, relative_service.toStdString(), std_srvs::Trigger());
}

void PodLink::setAngle(double pitch, double yaw) {
  k40t_driver::SetAngle srv;
  srv.request.pitch = pitch;
  srv.request.yaw = yaw;
  call("gimbal/set_angle", "gimbal/set_angle", srv);
}

void PodLink::setZoom(double ratio) {
  k40t_driver::SetZoom srv;
  srv.request.ratio = ratio;
  call("set_zoom", "set_zoom", srv);
}

void PodLink::zoom(uint8_t action) {
  k40t_driver::Zoom srv;
  srv.request.action = action;
  call("zoom", "zoom", srv);
}

void PodLink::setPalette(int palette) {
  k40t_driver::SetPalette srv;
  srv.request.palette = static_cast<uint8_t>(std::clamp(palette, 0, 255));
  call("set_palette", "set_palette", srv);
}

void PodLink::takePhoto() {
  call("take_photo", "take_photo", k40t_driver::TakePhoto());
}

void PodLink::record(bool start) {
  k40t_driver::Record srv;
  srv.request.start = start;
  call(start ? "record start" : "record stop", "record", srv);
}

void PodLink::measureRange() {
  call("laser/measure", "laser/measure", k40t_driver::MeasureRange());
}

// dynamic_reconfigure has no success/message: the driver reverts a refused change, so the reply's
// configuration tells whether the pod took it (its log and diagnostics say why not).
void PodLink::setParameter(const QString& name, int value) {
  if (!nh_) {
    Q_EMIT callFinished(name, false, "no valid driver namespace set");
    return;
  }
  dynamic_reconfigure::Reconfigure srv;
  dynamic_reconfigure::IntParameter param;
  param.name = name.toStdString();
  param.value = value;
  srv.request.config.ints.push_back(param);
  ros::ServiceClient client = nh_->serviceClient<dynamic_reconfigure::Reconfigure>(
      std::string(kDriverNode) + "/set_parameters");
  worker_->post([this, name, client, srv, param]() mutable {
    if (!client.call(srv)) {
      Q_EMIT callFinished(name, false, noAnswer(client));
      return;
    }
    for (const auto& p : srv.response.config.ints) {
      if (p.name != param.name) continue;
      if (p.value == param.value) {
        Q_EMIT callFinished(name, true, "ok");
      } else {
        Q_EMIT callFinished(name, false,
                            QString("refused: the pod kept %1 (the driver's log and diagnostics "
                                    "say why)")
                                .arg(p.value));
      }
      return;
    }
    Q_EMIT callFinished(name, false, "the driver's reply has no " + name);
  });
}

void PodLink::onConfig(const dynamic_reconfigure::Config& config) {
  for (const auto& p : config.ints) Q_EMIT settingChanged(text(p.name), p.value);
}

void PodLink::onDiagnostics(const diagnostic_msgs::DiagnosticArray& array) {
  bool mine = false;
  for (const auto& status : array.status) {
    if (status.name.compare(0, diagnostic_prefix_.size(), diagnostic_prefix_) != 0) continue;
    statuses_[status.name] = status;
    mine = true;
  }
  if (!mine) return;
  int worst = diagnostic_msgs::DiagnosticStatus::OK;
  int link_level = diagnostic_msgs::DiagnosticStatus::STALE;
  QString link_message = "no link status";
  QStringList others;
  for (const auto& [name, status] : statuses_) {
    const std::string task =
        name.substr(name.find(": ") == std::string::npos ? 0 : name.find(": ") + 2);
    worst = std::max<int>(worst, status.level);
    if (task == "link") {
      link_level = status.level;
      link_message = text(status.message);
    } else if (status.level != diagnostic_msgs::DiagnosticStatus::OK) {
      others << text(task + ": " + status.message);
    }
  }
  Q_EMIT health(worst, link_level, link_message, others.join("; "));
}

}  // namespace k40t::rviz_panel
