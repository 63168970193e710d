// The simulated adapter's scripted exchanges: what DJI Pilot would send, with every ACK checked.
#include <chrono>
#include <cmath>
#include <string>
#include <thread>

#include "k40t_driver/psdk/sim/adapter_simulator.h"
#include "k40t_driver/psdk/sim/payload_reading.h"

namespace k40t::psdk::sim {
namespace {

// Sends `command`, checks the ACK is OK and, when given, that `expect` holds for it.
template <class Cmd, class Expect>
typename Cmd::Ack exchange(Session& session, CheckReport& report, const Cmd& command,
                           const std::string& what, Expect expect) {
  const Result<typename Cmd::Ack> ack = session.request(command);
  if (!ack) {
    report.add(Cmd::kName, false, what + ": " + ack.error());
    return {};
  }
  if (ack->code != AckCode::kOk) {
    report.add(Cmd::kName, false,
               what + ": payload answered " + ack_code_text(static_cast<uint8_t>(ack->code)));
    return ack.value();
  }
  std::string detail = what + ": OK";
  const bool passed = expect(ack.value(), detail);
  report.add(Cmd::kName, passed, detail);
  return ack.value();
}

template <class Cmd>
typename Cmd::Ack exchange(Session& session, CheckReport& report, const Cmd& command,
                           const std::string& what) {
  return exchange(session, report, command, what,
                  [](const typename Cmd::Ack&, std::string&) { return true; });
}

// Polls with `command` until `done` holds for its ACK or a generous deadline passes, as DJI Pilot
// does: the gimbal and the lens move at a finite speed, the camera takes time to store a photo.
// `last` keeps the last OK answer; a refusal ends the polling (asking again will not help) and
// `why` says what went wrong.
template <class Cmd, class Done>
bool poll_until(Session& session, const Cmd& command, Done done, typename Cmd::Ack* last,
                std::string* why) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  *why = "no answer";
  while (std::chrono::steady_clock::now() < until) {
    const Result<typename Cmd::Ack> ack = session.request(command);
    if (!ack) {
      *why = ack.error();
    } else if (ack->code != AckCode::kOk) {
      *why = "payload answered " + ack_code_text(static_cast<uint8_t>(ack->code));
      return false;
    } else {
      *last = ack.value();
      if (done(*last)) return true;
      *why = "not within 10 s";
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return false;
}

bool shooting(const ShootPhotoState& s) {
  return s.shooting_single || s.shooting_burst || s.shooting_interval || s.storing;
}

std::string photo_state_text(const ShootPhotoState& s) {
  if (!shooting(s)) return "idle";
  std::string out;
  if (s.shooting_single) out += " single";
  if (s.shooting_burst) out += " burst";
  if (s.shooting_interval) out += " interval";
  if (s.storing) out += " storing";
  return "shooting:" + out;
}

std::string angles_text(const GimbalStateReading& a) {
  return "pitch " + std::to_string(a.pitch_deg) + ", roll " + std::to_string(a.roll_deg) +
         ", yaw " + std::to_string(a.yaw_deg) + " deg";
}

// The gimbal state read with the adapter's own table (payload_reading.h).
Result<GimbalStateReading> gimbal_state(Session& session, PayloadReading reading) {
  const AckResult r = session.request_raw(GetGimbalState::key(), nullptr, 0);
  if (!r.received) return Status::fail(r.message);
  return read_gimbal_state(r.data, reading);
}

// poll_until() for the gimbal state.
template <class Done>
bool poll_gimbal(Session& session, PayloadReading reading, Done done, GimbalStateReading* last,
                 std::string* why) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  *why = "no answer";
  while (std::chrono::steady_clock::now() < until) {
    const Result<GimbalStateReading> state = gimbal_state(session, reading);
    if (!state) {
      *why = state.error();
    } else {
      *last = state.value();
      if (done(*last)) return true;
      *why = "not within 10 s";
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return false;
}

}  // namespace

CheckReport AdapterSimulator::check_payload_state() {
  CheckReport report;
  Session& s = *session_;
  exchange(s, report, GetPsdkVersion{}, "PSDK version",
           [](const PsdkVersionAck& a, std::string& d) {
             d += " " + std::to_string(a.version.major) + "." + std::to_string(a.version.minor) +
                  "." + std::to_string(a.version.modify) + "." + std::to_string(a.version.debug);
             return a.version.major > 0 || a.version.minor > 0;
           });
  Handshake handshake;
  handshake.data = Blob<kMaxHandshakeSize>::from("SKYPORT link check 0123456789");
  exchange(s, report, handshake, "hand-shake", [&](const HandshakeAck& a, std::string& d) {
    const bool echoed = a.data == handshake.data;
    d += echoed ? ", data echoed" : ", data NOT echoed";
    return echoed;
  });
  exchange(s, report, GetProductInfo{}, "product information",
           [](const ProductInfoAck& a, std::string& d) {
             d += " '" + a.product_name + "'";
             return !a.product_name.empty();
           });
  exchange(s, report, GetProductAlias{}, "alias");
  exchange(s, report, GetSkyportVersion{}, "SKYPORT version");
  return report;
}

CheckReport AdapterSimulator::check_camera() {
  CheckReport report;
  Session& s = *session_;
  exchange(s, report, GetCameraCapability{}, "capabilities",
           [](const CameraCapabilityAck& a, std::string& d) {
             d += a.supported.camera_commands ? ", camera set supported"
                                              : ", camera set NOT supported";
             return a.supported.camera_commands;
           });

  SetCameraWorkMode mode;
  mode.mode = CameraWorkMode::kShootPhoto;
  exchange(s, report, mode, "work mode: photo");
  exchange(s, report, GetCameraWorkMode{}, "work mode reads back",
           [](const CameraWorkModeAck& a, std::string&) {
             return a.mode == CameraWorkMode::kShootPhoto;
           });
  ShootPhoto photo;
  photo.action = ShootPhotoAction::kStart;
  exchange(s, report, photo, "shoot photo");
  exchange(s, report, GetShootPhotoState{}, "photo state",
           [](const ShootPhotoStateAck& a, std::string& d) {
             d += ", " + photo_state_text(a.state);
             return true;
           });
  // Like DJI Pilot: no further camera command while the camera is still shooting or storing.
  std::string why;
  ShootPhotoStateAck photo_state;
  const bool stored = poll_until(
      s, GetShootPhotoState{}, [](const ShootPhotoStateAck& a) { return !shooting(a.state); },
      &photo_state, &why);
  report.add("photo_stored", stored,
             "photo state " + photo_state_text(photo_state.state) + (stored ? "" : ", " + why));

  check_interval_mode(report);

  mode.mode = CameraWorkMode::kRecordVideo;
  exchange(s, report, mode, "work mode: video");
  RecordVideo record;
  record.action = RecordAction::kStart;
  exchange(s, report, record, "record start");
  exchange(s, report, GetRecordState{}, "recording",
           [](const RecordStateAck& a, std::string&) { return a.recording; });
  record.action = RecordAction::kStop;
  exchange(s, report, record, "record stop");
  exchange(s, report, GetRecordState{}, "not recording",
           [](const RecordStateAck& a, std::string&) { return !a.recording; });
  {
    const AckResult r = s.request_raw(GetSdCardInfo::key(), nullptr, 0);
    const Result<SdCardReading> sd = r.received ? read_sd_card(r.data, options_.reading)
                                                : Result<SdCardReading>::fail(r.message);
    // A card the pod writes to must not read as read-only or faulty in the adapter's layout.
    const bool healthy = sd && (!sd->inserted || (!sd->read_only && !sd->has_error));
    report.add(GetSdCardInfo::kName, healthy,
               !sd ? "SD card: " + sd.error()
                   : std::string("SD card: ") +
                         (sd->inserted ? "inserted, " + std::to_string(sd->free_mb) + " MB free" +
                                             (sd->read_only ? ", READ-ONLY" : "") +
                                             (sd->has_error ? ", ERROR" : "")
                                       : "no card"));
  }

  const OpticalZoomSpecAck spec = exchange(s, report, GetOpticalZoomSpec{}, "optical zoom range",
                                           [](const OpticalZoomSpecAck& a, std::string& d) {
                                             d += " " + std::to_string(a.min_focal_length_mm) +
                                                  ".." + std::to_string(a.max_focal_length_mm) +
                                                  " mm";
                                             return a.min_focal_length_mm <= a.max_focal_length_mm;
                                           });
  SetOpticalZoomFocalLength focal;
  focal.focal_length_mm =
      std::round((spec.min_focal_length_mm + spec.max_focal_length_mm) / 2.0 * 10.0) / 10.0;
  exchange(s, report, focal, "focal length " + std::to_string(focal.focal_length_mm) + " mm");
  const double tolerance_mm = std::max(spec.focal_length_step_mm, 0.1);
  // The lens moves at a finite speed: the read-back follows it until it arrives.
  OpticalZoomFocalLengthAck focal_read;
  const bool arrived = poll_until(
      s, GetOpticalZoomFocalLength{},
      [&](const OpticalZoomFocalLengthAck& a) {
        return std::abs(a.focal_length_mm - focal.focal_length_mm) <= tolerance_mm;
      },
      &focal_read, &why);
  report.add(GetOpticalZoomFocalLength::kName, arrived,
             "focal length reads back: " + std::to_string(focal_read.focal_length_mm) + " mm" +
                 (arrived ? "" : ", " + why));
  exchange(s, report, GetOpticalZoomFactor{}, "optical zoom factor");
  StartContinuousZoom zoom;
  zoom.direction = ZoomDirection::kIn;
  exchange(s, report, zoom, "continuous zoom in");
  exchange(s, report, StopContinuousZoom{}, "zoom stop");

  // Each setting goes to a value other than the usual default and back, so a payload that ignores
  // the command cannot pass by reporting its default.
  for (const FocusMode mode : {FocusMode::kManual, FocusMode::kAuto}) {
    SetFocusMode focus;
    focus.mode = mode;
    const std::string name = mode == FocusMode::kAuto ? "auto" : "manual";
    exchange(s, report, focus, "focus: " + name);
    exchange(s, report, GetFocusMode{}, "focus reads back " + name,
             [mode](const FocusModeAck& a, std::string&) { return a.mode == mode; });
  }
  for (const MeteringMode mode : {MeteringMode::kAverage, MeteringMode::kCenter}) {
    SetMeteringMode metering;
    metering.mode = mode;
    const std::string name = mode == MeteringMode::kCenter ? "centre" : "average";
    exchange(s, report, metering, "metering: " + name);
    exchange(s, report, GetMeteringMode{}, "metering reads back " + name,
             [mode](const MeteringModeAck& a, std::string&) { return a.mode == mode; });
  }
  return report;
}

// Interval shooting set and read back in the payload's layout (P30), written byte by byte as an
// adapter of that layout would (3.4.5: type 6, burst 0, count 255 = until stopped, interval 5 s;
// the headers' interval is a uint16), read with the adapter's own table; then single shots again.
void AdapterSimulator::check_interval_mode(CheckReport& report) {
  Session& s = *session_;
  const bool wide = options_.reading == PayloadReading::kDjiHeaders;
  const std::vector<uint8_t> interval = wide ? std::vector<uint8_t>{0x06, 0x00, 0xFF, 0x05, 0x00}
                                             : std::vector<uint8_t>{0x06, 0x00, 0xFF, 0x05};
  const AckResult set = s.request_raw(SetShootPhotoMode::key(), interval.data(), interval.size());
  report.add(
      SetShootPhotoMode::kName, set.ok(),
      "photo mode: interval 5 s: " + (set.received ? ack_code_text(set.code()) : set.message));
  ShootPhotoModeReading last;
  std::string why = "no answer";
  bool read_back = false;
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (set.ok() && !read_back && std::chrono::steady_clock::now() < until) {
    const AckResult r = s.request_raw(GetShootPhotoMode::key(), nullptr, 0);
    const Result<ShootPhotoModeReading> m = r.received
                                                ? read_shoot_photo_mode(r.data, options_.reading)
                                                : Result<ShootPhotoModeReading>::fail(r.message);
    if (m) {
      last = m.value();
      read_back = last.type == 0x06 && last.interval_count == 0xFF && last.interval_s == 5;
      why = "type " + std::to_string(last.type) + ", interval " + std::to_string(last.interval_s) +
            " s";
    } else {
      why = m.error();
    }
    if (!read_back) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  report.add(GetShootPhotoMode::kName, read_back, "photo mode reads back: " + why);
  const std::vector<uint8_t> single = wide ? std::vector<uint8_t>{0x01, 0x00, 0x00, 0x00, 0x00}
                                           : std::vector<uint8_t>{0x01, 0x00, 0x00, 0x00};
  const AckResult back = s.request_raw(SetShootPhotoMode::key(), single.data(), single.size());
  report.add(SetShootPhotoMode::kName, back.ok(),
             "photo mode: single: " + (back.received ? ack_code_text(back.code()) : back.message));
}

CheckReport AdapterSimulator::check_gimbal() {
  CheckReport report;
  Session& s = *session_;
  exchange(s, report, GetGimbalCapability{}, "capability",
           [](const GimbalCapabilityAck& a, std::string&) { return a.supported; });
  const Result<GimbalStateReading> state = gimbal_state(s, options_.reading);
  report.add(GetGimbalState::kName, static_cast<bool>(state),
             state ? "state: OK, " + state->mode + ", " + angles_text(state.value())
                   : "state: " + state.error());
  // The mode the gimbal says it is in must be accepted; PSDK lets a gimbal answer 0x02 for a mode
  // it does not have (a pod whose yaw is relative to the aircraft has no free mode), never 0x01.
  SetGimbalMode mode;
  mode.mode = state ? static_cast<GimbalMode>(state->set_mode_code) : GimbalMode::kFollowing;
  exchange(s, report, mode, std::string("mode: ") + to_string(mode.mode) + " (its own)");
  mode.mode = GimbalMode::kFree;
  const Result<SetGimbalMode::Ack> free = s.request(mode);
  const bool free_answered =
      free && (free->code == AckCode::kOk || free->code == AckCode::kUnsupported);
  report.add(
      SetGimbalMode::kName, free_answered,
      "mode: free: " + (free ? ack_code_text(static_cast<uint8_t>(free->code)) : free.error()));

  ControlGimbalAngle angle;
  angle.pitch_deg = -30.0f;
  angle.yaw_deg = 20.0f;
  exchange(s, report, angle, "angle pitch -30, yaw 20 deg");
  GimbalStateReading last;
  std::string why;
  const bool reached = poll_gimbal(
      s, options_.reading,
      [](const GimbalStateReading& a) {
        return std::abs(a.pitch_deg + 30.0) <= 2.0 && std::abs(a.yaw_deg - 20.0) <= 2.0;
      },
      &last, &why);
  report.add("gimbal_reaches_angle", reached, angles_text(last) + (reached ? "" : ", " + why));

  ControlGimbalSpeed speed;
  speed.yaw_rate_deg_s = 10.0;
  exchange(s, report, speed, "yaw at 10 deg/s");
  speed.yaw_rate_deg_s = 0.0;
  speed.action = GimbalControlAction::kStop;
  exchange(s, report, speed, "speed control stop");

  exchange(s, report, GimbalReturnHead{}, "return head");
  const bool centred = poll_gimbal(
      s, options_.reading,
      [](const GimbalStateReading& a) {
        return std::abs(a.pitch_deg) <= 2.0 && std::abs(a.yaw_deg) <= 2.0;
      },
      &last, &why);
  report.add("gimbal_returns_to_centre", centred, angles_text(last) + (centred ? "" : ", " + why));

  exchange(s, report, CalibrateGimbal{}, "calibration");
  exchange(s, report, GetCalibrationProgress{}, "calibration progress",
           [](const CalibrationProgressAck& a, std::string& d) {
             d += " " + std::to_string(a.progress_percent) + " %";
             return a.status != CalibrationStatus::kFailed;
           });
  exchange(s, report, GetGimbalAdditionalStatus{}, "additional status");
  return report;
}

CheckReport AdapterSimulator::check_unsupported() {
  CheckReport report;
  // 0x04/0x50 is not in the document's camera set.
  const AckResult r = session_->request_raw({0x04, 0x50}, nullptr, 0);
  const bool passed =
      r.received && r.data.size == 1 && r.code() == static_cast<uint8_t>(AckCode::kUnsupported);
  report.add("unknown_command_0x04_0x50", passed,
             r.received ? "ACK " + ack_code_text(r.code()) + ", " + std::to_string(r.data.size) +
                              " byte(s)"
                        : r.message);
  return report;
}

}  // namespace k40t::psdk::sim
