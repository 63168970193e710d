#include "k40t_driver/driver/settings_reader.h"

namespace k40t::driver {

SettingReports SettingsRead::reports() const {
  return SettingReports{settings.thermal ? &*settings.thermal : nullptr,
                        settings.visible ? &*settings.visible : nullptr,
                        camera ? &*camera : nullptr, gimbal ? &*gimbal : nullptr};
}

SettingsReader::SettingsReader(PodDriver& driver, std::chrono::milliseconds report_wait)
    : driver_(driver), report_wait_(report_wait) {
  driver.on<protocol::CameraSystemStatus>(
      [this](const protocol::CameraSystemStatus& report, StampNs) {
        std::lock_guard<std::mutex> lock(mutex_);
        camera_report_ = report;
        reports_arrived_.notify_all();
      });
  driver.on<protocol::GimbalStatus>([this](const protocol::GimbalStatus& report, StampNs) {
    std::lock_guard<std::mutex> lock(mutex_);
    gimbal_report_ = report;
    reports_arrived_.notify_all();
  });
}

SettingsRead SettingsReader::read() {
  std::lock_guard<std::mutex> one_read(read_mutex_);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    camera_report_.reset();  // wait for reports sent after the pod came online
    gimbal_report_.reset();
  }
  SettingsRead read;
  read.settings = read_settings(driver_);
  {
    std::unique_lock<std::mutex> lock(mutex_);
    reports_arrived_.wait_for(lock, report_wait_, [&] { return camera_report_ && gimbal_report_; });
    read.camera = camera_report_;
    read.gimbal = gimbal_report_;
  }
  read.message = read.ok() ? "read 0x000100 and 0x000200" : read.settings.error;
  if (!read.camera) read.message += "; no camera status report (0x000003) to read modes from";
  if (!read.gimbal) {
    read.message += "; no gimbal status report (0x000001) to read stabilisation from";
  }
  return read;
}

}  // namespace k40t::driver
