#include "camera_widget.h"

#include <QComboBox>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <cmath>

#include <k40t_driver/Zoom.h>

#include "cfg_choices.h"
#include "pod_link.h"

namespace k40t::rviz_panel {
namespace {

constexpr int kZoomMin = 10;    // 1.0x (set_zoom's range, docs/ros_interface.md)
constexpr int kZoomMax = 1600;  // 160.0x

QComboBox* choicesBox(const char* name, const char* parameter, QWidget* parent) {
  auto* box = new QComboBox(parent);
  box->setObjectName(name);
  for (const Choice& c : cfgChoices(parameter)) box->addItem(c.label, c.value);
  return box;
}

QPushButton* button(const char* name, const QString& text, QWidget* parent) {
  auto* b = new QPushButton(text, parent);
  b->setObjectName(name);
  return b;
}

void selectValue(QComboBox* box, int value) {
  const int index = box->findData(value);
  if (index >= 0) box->setCurrentIndex(index);
}

}  // namespace

CameraWidget::CameraWidget(PodLink* link, QWidget* parent)
    : QGroupBox("Camera", parent), link_(link) {
  zoom_ = new QSlider(Qt::Horizontal, this);
  zoom_->setObjectName("zoom_slider");
  zoom_->setRange(kZoomMin, kZoomMax);
  zoom_->setSingleStep(10);
  zoom_->setPageStep(50);
  zoom_label_ = new QLabel("1.0x", this);
  zoom_label_->setObjectName("zoom_value");
  zoom_label_->setMinimumWidth(50);
  auto* zoom_in = button("zoom_in", "Zoom +", this);
  auto* zoom_out = button("zoom_out", QString::fromUtf8("Zoom −"), this);
  zoom_in->setToolTip("Zooms in while held");
  zoom_out->setToolTip("Zooms out while held");
  palette_ = choicesBox("palette", "palette", this);
  image_mode_ = choicesBox("image_mode", "image_mode", this);
  camera_mode_ = choicesBox("camera_mode", "camera_mode", this);
  auto* photo = button("take_photo", "Photo", this);
  auto* record_start = button("record_start", "Record", this);
  auto* record_stop = button("record_stop", "Stop recording", this);
  auto* measure = button("laser_measure", "Measure range", this);

  auto* layout = new QGridLayout(this);
  layout->addWidget(new QLabel("Zoom", this), 0, 0);
  layout->addWidget(zoom_, 0, 1, 1, 2);
  layout->addWidget(zoom_label_, 0, 3);
  layout->addWidget(zoom_out, 1, 1);
  layout->addWidget(zoom_in, 1, 2);
  layout->addWidget(new QLabel("Palette", this), 2, 0);
  layout->addWidget(palette_, 2, 1, 1, 3);
  layout->addWidget(new QLabel("Image", this), 3, 0);
  layout->addWidget(image_mode_, 3, 1, 1, 3);
  layout->addWidget(new QLabel("Mode", this), 4, 0);
  layout->addWidget(camera_mode_, 4, 1, 1, 3);
  layout->addWidget(photo, 5, 0);
  layout->addWidget(record_start, 5, 1);
  layout->addWidget(record_stop, 5, 2, 1, 2);
  layout->addWidget(measure, 6, 0, 1, 4);

  // The slider sets the zoom when let go, or at once when moved by keys or page clicks.
  connect(zoom_, &QSlider::sliderReleased, this, &CameraWidget::applySliderZoom);
  connect(zoom_, &QSlider::valueChanged, this, [this](int value) {
    zoom_label_->setText(QString("%1x").arg(value / 10.0, 0, 'f', 1));
    if (!zoom_->isSliderDown()) applySliderZoom();
  });
  connect(zoom_in, &QPushButton::pressed, this,
          [this] { link_->zoom(k40t_driver::Zoom::Request::ZOOM_IN); });
  connect(zoom_out, &QPushButton::pressed, this,
          [this] { link_->zoom(k40t_driver::Zoom::Request::ZOOM_OUT); });
  connect(zoom_in, &QPushButton::released, this,
          [this] { link_->zoom(k40t_driver::Zoom::Request::STOP); });
  connect(zoom_out, &QPushButton::released, this,
          [this] { link_->zoom(k40t_driver::Zoom::Request::STOP); });
  // activated: only the user's choices, not showSetting() following the driver.
  connect(palette_, QOverload<int>::of(&QComboBox::activated), this,
          [this](int index) { link_->setPalette(palette_->itemData(index).toInt()); });
  for (QComboBox* box : {image_mode_, camera_mode_}) {
    connect(box, QOverload<int>::of(&QComboBox::activated), this, [this, box](int index) {
      link_->setParameter(box->objectName(), box->itemData(index).toInt());
    });
  }
  connect(photo, &QPushButton::clicked, this, [this] { link_->takePhoto(); });
  connect(record_start, &QPushButton::clicked, this, [this] { link_->record(true); });
  connect(record_stop, &QPushButton::clicked, this, [this] { link_->record(false); });
  connect(measure, &QPushButton::clicked, this, [this] { link_->measureRange(); });
}

void CameraWidget::applySliderZoom() {
  link_->setZoom(zoom_->value() / 10.0);
}

void CameraWidget::showSetting(const QString& name, int value) {
  for (QComboBox* box : {palette_, image_mode_, camera_mode_}) {
    if (box->objectName() == name) selectValue(box, value);
  }
}

void CameraWidget::showZoom(double ratio) {
  if (zoom_->isSliderDown() || zoom_->hasFocus() || !std::isfinite(ratio)) return;
  const QSignalBlocker quiet(zoom_);  // following the pod is not a command
  zoom_->setValue(static_cast<int>(std::lround(ratio * 10)));
  zoom_label_->setText(QString("%1x").arg(ratio, 0, 'f', 1));
}

}  // namespace k40t::rviz_panel
