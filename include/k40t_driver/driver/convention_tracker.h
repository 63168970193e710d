// The driver's view of the document's open readings (docs/protocol/decisions.md#conventions)
// while it runs: the values in force, where each came from (default, parameter, detected from
// which frame), and what the pod's traffic says against them.
//   - `auto` readings lock onto the first frame that shows which reading the pod uses
//     (yaw_range: a yaw beyond +-180 deg or in -180..0 deg in 0x000002);
//   - a reading that is not `auto` is checked against the same evidence, and against the gimbal's
//     unambiguous commands: a move commanded with 0x000010's or 0x000012's direction bytes that
//     the 0x000002 report counts the other way contradicts yaw_sign / pitch_sign. Contradictions
//     are kept and shown by the `conventions` diagnostic (WARN);
//   - calibration_end: whether 0x000008 reports a calibration the pod acknowledged.
//   - ack_byte_order: ACKs whose bytes read sensibly one way only (protocol/
//     ack_byte_order_evidence.h: response codes, the thermal and SBUS read-backs) confirm the value
//     in force (shown with its source) or contradict it (the message names the value to set).
//     With `auto` the link's protocol::AckOrderSetting locks the order on the first such ACK; the
//     tracker shows it as "auto: detected little from ACK 0x010100 bytes ..." and checks the
//     ACKs after it like a value set by hand.
// ROS-free and thread-safe: observations come from the I/O thread, reports from any thread.
#pragma once

#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "k40t_driver/protocol/ack_order_setting.h"
#include "k40t_driver/protocol/convention_readings.h"
#include "k40t_driver/protocol/conventions.h"

namespace k40t::driver {

struct ConventionStatus {
  std::string name;
  std::string value;
  std::string source;         // "default", "parameter", "detected from 0x000002 (yaw 350.00 deg)"
  std::string contradiction;  // "" unless the pod's traffic says otherwise
};

class ConventionTracker {
 public:
  // `codec` and `crc_coverage` as configured; `from_parameters`: the names the user set.
  ConventionTracker(protocol::CrcCoverage crc_coverage, const protocol::CodecOptions& codec,
                    std::set<std::string> from_parameters);

  // Seconds of the steady clock, the time base of the observations in the driver.
  static double steady_now_s();

  // The readings in force (auto ones resolved once locked).
  protocol::Conventions conventions() const;
  protocol::YawRange yaw_range() const;  // kSigned until an auto range locks

  // --- what the driver sees (seconds of any monotonic clock) ------------------------------------
  // A 0x000002 report as the layout decoded it (before attitude_from_wire).
  void observe_attitude(const protocol::GimbalAttitude& as_decoded, double now_s);
  void observe_command(const protocol::GimbalControlRequest& command, double now_s);
  void observe_command(const protocol::GimbalAngleRequest& command, double now_s);
  // ACK 0x010100 as the layout decoded it (before the readings are applied).
  void observe_thermal_settings(const protocol::ThermalSettingsAck& as_decoded);
  void observe_crc_coverage(protocol::CrcCoverage locked);
  // Any ACK (0x01xxxx) as received, before decoding; `in_force`: the link's ACK byte order, which
  // has seen this ACK already (with ack_byte_order: auto, the detection is the setting's).
  void observe_ack(protocol::MessageId ack_id, const uint8_t* payload, size_t size,
                   const protocol::AckOrderSetting& in_force);
  // How a gimbal calibration ends: its OK ACK (0x010013, 0x01002E, 0x010031), then whether
  // 0x000008 says "repairing" within kCalibrationQuietS (status) or not (ack). Decided on the next
  // observation after that time.
  void observe_calibration_acked(double now_s);
  void observe_upgrade_status(const protocol::CameraUpgradeStatus& m, double now_s);
  static constexpr double kCalibrationQuietS = 2.5;

  // --- applying the readings --------------------------------------------------------------------
  // The true values of a decoded message (convention_readings.h's *_from_wire).
  protocol::GimbalAttitude applied(const protocol::GimbalAttitude& m) const;
  protocol::CameraSystemStatus applied(const protocol::CameraSystemStatus& m) const;
  protocol::ThermalSettingsAck applied(const protocol::ThermalSettingsAck& m) const;
  template <class Msg>
  static constexpr bool kApplies = std::is_same_v<Msg, protocol::GimbalAttitude> ||
                                   std::is_same_v<Msg, protocol::CameraSystemStatus> ||
                                   std::is_same_v<Msg, protocol::ThermalSettingsAck>;

  // Every reading of protocol::convention_table(), in its order.
  std::vector<ConventionStatus> report() const;
  bool contradicted() const;

 private:
  // One axis's check of the report's sign against a commanded move.
  struct AxisCheck {
    bool pending = false;
    bool by_angle = false;  // 0x000012 (a target) or 0x000010 (a direction)
    double expected = 0;    // target (deg, right/up positive), or +1/-1
    double baseline = 0;    // the axis's angle when the command went out
    double since_s = 0;
    std::string command_text;  // "0x000010 yaw right"
  };
  void start_check(AxisCheck& check, bool by_angle, double expected, double baseline, double now_s,
                   std::string text);
  void finish_check(AxisCheck& check, const char* name, double angle, double rate, double now_s);
  void contradict(const std::string& name, std::string why);
  void calibration_evidence(protocol::CalibrationEnd seen, const std::string& evidence);
  void check_calibration(double now_s);
  void detect(const std::string& name, std::string evidence);

  mutable std::mutex mutex_;
  protocol::CrcCoverage crc_coverage_;
  protocol::CodecOptions codec_;  // codec_.conventions: auto ones resolved as they lock
  std::set<std::string> from_parameters_;
  std::optional<protocol::CrcCoverage> locked_crc_;
  protocol::YawRange yaw_range_ = protocol::YawRange::kSigned;
  std::vector<std::pair<std::string, std::string>> detected_;        // name, source text
  std::vector<std::pair<std::string, std::string>> contradictions_;  // name, why
  std::vector<std::pair<std::string, std::string>> confirmed_;       // name, by which frame
  std::optional<protocol::GimbalAttitude> last_attitude_;            // true values
  std::optional<double> calibration_acked_s_;  // a calibration whose end is being watched
  AxisCheck yaw_check_;
  AxisCheck pitch_check_;
};

}  // namespace k40t::driver
