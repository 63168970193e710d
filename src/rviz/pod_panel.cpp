#include "pod_panel.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QTime>
#include <QVBoxLayout>

#include <pluginlib/class_list_macros.hpp>

#include "camera_widget.h"
#include "gimbal_widget.h"
#include "panel_test_hook.h"
#include "pod_link.h"
#include "status_widget.h"

namespace k40t::rviz_panel {
namespace {

constexpr char kDefaultNamespace[] = "/k40t";  // launch/k40t.launch's default
constexpr char kNamespaceKey[] = "Namespace";

}  // namespace

PodPanel::PodPanel(QWidget* parent) : rviz::Panel(parent), link_(new PodLink(this)) {
  setObjectName("PodPanel");
  namespace_ = new QLineEdit(kDefaultNamespace, this);
  namespace_->setObjectName("namespace");
  namespace_->setToolTip("The driver's namespace (its topics and services); Enter applies it");
  status_ = new StatusWidget(this);
  gimbal_ = new GimbalWidget(link_, this);
  camera_ = new CameraWidget(link_, this);
  message_ = new QLabel(this);
  message_->setObjectName("message");
  message_->setWordWrap(true);
  message_->setTextInteractionFlags(Qt::TextSelectableByMouse);

  auto* top = new QHBoxLayout;
  top->addWidget(new QLabel("Driver namespace", this));
  top->addWidget(namespace_, 1);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(top);
  layout->addWidget(status_);
  layout->addWidget(gimbal_);
  layout->addWidget(camera_);
  layout->addWidget(message_);
  layout->addStretch(1);

  connect(namespace_, &QLineEdit::editingFinished, this, &PodPanel::applyNamespace);
  connect(link_, &PodLink::jointState, status_, &StatusWidget::showJoints);
  connect(link_, &PodLink::visibleStatus, status_, &StatusWidget::showVisible);
  connect(link_, &PodLink::visibleStatus, camera_,
          [this](const k40t_driver::VisibleStatus& msg) { camera_->showZoom(msg.zoom_ratio); });
  connect(link_, &PodLink::thermalStats, status_, &StatusWidget::showThermal);
  connect(link_, &PodLink::laserRange, status_, &StatusWidget::showRange);
  connect(link_, &PodLink::cameraStatus, status_, &StatusWidget::showCamera);
  connect(link_, &PodLink::photoStatus, status_, &StatusWidget::showPhoto);
  connect(link_, &PodLink::recordStatus, status_, &StatusWidget::showRecord);
  connect(link_, &PodLink::health, status_, &StatusWidget::showHealth);
  connect(link_, &PodLink::settingChanged, camera_, &CameraWidget::showSetting);
  connect(link_, &PodLink::callFinished, this, &PodPanel::showCallResult);
  applyNamespace();
  test_hook_ = PanelTestHook::fromEnvironment(this);
}

PodPanel::~PodPanel() {
  test_hook_.reset();
  link_->shutdown();  // joins its service thread before the widgets it reports to go
}

void PodPanel::applyNamespace() {
  const QString ns = namespace_->text().trimmed();
  if (ns == link_->ns() && !ns.isEmpty()) return;
  status_->clear();
  if (link_->setNamespace(ns)) {
    message_->setText(QString("Connected to the driver's interface under %1").arg(ns));
  } else {
    message_->setText(QString("<b style='color:#c62828'>'%1' is not a valid ROS namespace</b>")
                          .arg(ns.toHtmlEscaped()));
  }
  Q_EMIT configChanged();
}

void PodPanel::showCallResult(const QString& what, bool success, const QString& message) {
  const QString time = QTime::currentTime().toString("HH:mm:ss");
  if (success) {
    message_->setText(QString("%1 %2: %3").arg(time, what, message.toHtmlEscaped()));
  } else {
    message_->setText(QString("%1 <b style='color:#c62828'>%2 failed:</b> %3")
                          .arg(time, what, message.toHtmlEscaped()));
  }
}

void PodPanel::load(const rviz::Config& config) {
  rviz::Panel::load(config);
  QString ns;
  if (config.mapGetString(kNamespaceKey, &ns)) {
    namespace_->setText(ns);
    applyNamespace();
  }
}

void PodPanel::save(rviz::Config config) const {
  rviz::Panel::save(config);
  config.mapSetValue(kNamespaceKey, namespace_->text().trimmed());
}

}  // namespace k40t::rviz_panel

PLUGINLIB_EXPORT_CLASS(k40t::rviz_panel::PodPanel, rviz::Panel)
