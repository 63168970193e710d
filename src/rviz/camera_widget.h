// Camera controls: zoom (a slider for the ratio, and in/out buttons that zoom while held),
// thermal palette, image mode and photo/video mode (the choices of cfg/K40t.cfg), photo,
// recording, laser ranging.
#pragma once

#include <QGroupBox>

class QComboBox;
class QLabel;
class QSlider;

namespace k40t::rviz_panel {

class PodLink;

class CameraWidget : public QGroupBox {
  Q_OBJECT
 public:
  CameraWidget(PodLink* link, QWidget* parent = nullptr);

  // Follow the driver: the combos show its current settings, the slider its zoom (unless the
  // user is moving it).
  void showSetting(const QString& name, int value);
  void showZoom(double ratio);

 private:
  void applySliderZoom();

  PodLink* link_;
  QSlider* zoom_;  // tenths of the ratio: set_zoom's 0.1 steps
  QLabel* zoom_label_;
  QComboBox* palette_;
  QComboBox* image_mode_;
  QComboBox* camera_mode_;  // photo or video: the pod records only in video mode
};

}  // namespace k40t::rviz_panel
