// rviz panel k40t_driver/PodPanel: the pod's status and controls, through the driver's public
// ROS interface under the namespace set in the panel (saved in the .rviz configuration).
#pragma once

#include <memory>

#include <rviz/panel.h>

class QLabel;
class QLineEdit;

namespace k40t::rviz_panel {

class CameraWidget;
class GimbalWidget;
class PanelTestHook;
class PodLink;
class StatusWidget;

class PodPanel : public rviz::Panel {
  Q_OBJECT
 public:
  explicit PodPanel(QWidget* parent = nullptr);
  ~PodPanel() override;

  void load(const rviz::Config& config) override;
  void save(rviz::Config config) const override;

 private:
  void applyNamespace();
  void showCallResult(const QString& what, bool success, const QString& message);

  PodLink* link_;
  QLineEdit* namespace_;
  StatusWidget* status_;
  GimbalWidget* gimbal_;
  CameraWidget* camera_;
  QLabel* message_;  // the last call's outcome: "ok" or the driver's refusal
  std::unique_ptr<PanelTestHook> test_hook_;
};

}  // namespace k40t::rviz_panel
