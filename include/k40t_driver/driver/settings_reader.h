// The read side of the settings read-back, ROS-free: 0x000100 and 0x000200 asked for, and the next
// camera (0x000003) and gimbal (0x000001) status reports waited for, since they carry the modes
// and the stabilisation. Reports received before the read are not used: after a reconnect they
// may predate the pod's reboot. The settings sync (ros/settings_sync.h) turns the result into the
// published configuration.
#pragma once

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <string>

#include "k40t_driver/driver/pod_driver.h"
#include "k40t_driver/driver/pod_queries.h"
#include "k40t_driver/driver/setting_binding.h"
#include "k40t_driver/protocol/messages/camera_reports.h"
#include "k40t_driver/protocol/messages/gimbal.h"

namespace k40t::driver {

struct SettingsRead {
  PodSettings settings;  // 0x000100 and 0x000200, and why one is missing
  std::optional<protocol::CameraSystemStatus> camera;
  std::optional<protocol::GimbalStatus> gimbal;
  // "read 0x000100 and 0x000200", or what failed; then each report that did not come.
  std::string message;

  bool ok() const { return settings.error.empty(); }  // both settings ACKs read
  // Pointers into this read, for the settings table's read-back.
  SettingReports reports() const;
};

class SettingsReader {
 public:
  // How long read() waits for the periodic camera (1 Hz) and gimbal (2 Hz) reports.
  static constexpr std::chrono::milliseconds kReportWait{2500};

  // Registers the report handlers: construct before PodDriver::start().
  explicit SettingsReader(PodDriver& driver, std::chrono::milliseconds report_wait = kReportWait);

  // Blocking (requests, then up to report_wait); one read at a time.
  SettingsRead read();

 private:
  PodDriver& driver_;
  const std::chrono::milliseconds report_wait_;
  std::mutex read_mutex_;  // one read() at a time

  // The reports are kept by the I/O thread, which must never wait for anything else.
  std::mutex mutex_;
  std::condition_variable reports_arrived_;
  std::optional<protocol::CameraSystemStatus> camera_report_;
  std::optional<protocol::GimbalStatus> gimbal_report_;
};

}  // namespace k40t::driver
