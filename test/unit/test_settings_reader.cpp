// SettingsReader (driver/settings_reader.h) against a scripted pod over a pty, no ROS: the two
// settings ACKs and the status reports sent after the read began make a complete read; reports
// that came before it are not used; whatever is missing is named in the message.
#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "fake_pod.h"
#include "k40t_driver/driver/settings_reader.h"
#include "k40t_driver/protocol/messages/thermal.h"
#include "k40t_driver/protocol/messages/visible.h"
#include "pod_driver_test_support.h"

namespace k40t::driver {
namespace {

using std::chrono::milliseconds;
using namespace testing;  // k40t::driver::testing: FakePod and the helpers

constexpr milliseconds kShortWait{300};

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(SettingsReader, AcksAndTheNextReportsMakeACompleteRead) {
  const std::string pty = unique_pty("settings_read");
  FakePod pod(pty);
  pod.set_auto_ack(false);  // the settings ACKs are answered below, with their payloads
  std::unique_ptr<PodDriver> driver = make_driver(options_for(pty));
  SettingsReader reader(*driver, milliseconds(3000));
  ASSERT_TRUE(driver->start().is_ok());
  wait_until_linked(pod, *driver);

  std::thread answers([&pod] {
    pod.wait_for(FakePod::count_of(protocol::ThermalReadSettingsRequest::kId, 1),
                 milliseconds(3000));
    pod.send(protocol::ThermalSettingsAck{});
    pod.wait_for(FakePod::count_of(protocol::VisibleReadSettingsRequest::kId, 1),
                 milliseconds(3000));
    pod.send(protocol::VisibleSettingsAck{});
    protocol::GimbalStatus gimbal;
    gimbal.stabilisation = protocol::GimbalStabilisationState::kStabilising;
    pod.send(gimbal);
    pod.send(protocol::CameraSystemStatus{});
  });
  const SettingsRead read = reader.read();
  answers.join();
  EXPECT_TRUE(read.ok()) << read.settings.error;
  EXPECT_EQ(read.message, "read 0x000100 and 0x000200");
  ASSERT_TRUE(read.gimbal);
  EXPECT_EQ(read.gimbal->stabilisation, protocol::GimbalStabilisationState::kStabilising);
  EXPECT_TRUE(read.camera);
  const SettingReports reports = read.reports();
  EXPECT_NE(std::get<const protocol::ThermalSettingsAck*>(reports), nullptr);
  EXPECT_NE(std::get<const protocol::VisibleSettingsAck*>(reports), nullptr);
  EXPECT_NE(std::get<const protocol::CameraSystemStatus*>(reports), nullptr);
  EXPECT_NE(std::get<const protocol::GimbalStatus*>(reports), nullptr);
}

TEST(SettingsReader, WhatIsMissingIsNamed) {
  const std::string pty = unique_pty("settings_missing");
  FakePod pod(pty);  // answers every request with a bare OK code: no settings to decode
  std::unique_ptr<PodDriver> driver = make_driver(options_for(pty));
  SettingsReader reader(*driver, kShortWait);
  ASSERT_TRUE(driver->start().is_ok());
  wait_until_linked(pod, *driver);

  const SettingsRead read = reader.read();
  EXPECT_FALSE(read.ok());
  EXPECT_FALSE(read.settings.thermal);
  EXPECT_FALSE(read.camera);
  EXPECT_FALSE(read.gimbal);
  EXPECT_EQ(read.message.rfind(read.settings.error, 0), 0u) << read.message;
  EXPECT_TRUE(contains(read.settings.error, "thermal settings (0x000100)")) << read.message;
  EXPECT_TRUE(contains(read.message, "; no camera status report (0x000003) to read modes from"))
      << read.message;
  EXPECT_TRUE(
      contains(read.message, "; no gimbal status report (0x000001) to read stabilisation from"))
      << read.message;
  EXPECT_EQ(std::get<const protocol::GimbalStatus*>(read.reports()), nullptr);
}

TEST(SettingsReader, ReportsFromBeforeTheReadAreNotUsed) {
  const std::string pty = unique_pty("settings_stale");
  FakePod pod(pty);
  std::unique_ptr<PodDriver> driver = make_driver(options_for(pty));
  SettingsReader reader(*driver, kShortWait);
  std::atomic<int> status_reports{0};
  driver->on<protocol::GimbalStatus>(
      [&](const protocol::GimbalStatus&, StampNs) { ++status_reports; });
  driver->on<protocol::CameraSystemStatus>(
      [&](const protocol::CameraSystemStatus&, StampNs) { ++status_reports; });
  ASSERT_TRUE(driver->start().is_ok());
  wait_until_linked(pod, *driver);
  pod.send(protocol::GimbalStatus{});
  pod.send(protocol::CameraSystemStatus{});
  for (int i = 0; i < 100 && status_reports < 2; ++i) std::this_thread::sleep_for(milliseconds(20));
  ASSERT_EQ(status_reports.load(), 2) << "the driver did not receive the reports";

  const SettingsRead read = reader.read();
  EXPECT_FALSE(read.camera);
  EXPECT_FALSE(read.gimbal);
}

}  // namespace
}  // namespace k40t::driver
