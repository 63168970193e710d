// The simulated adapter's scripted exchanges: what DJI Pilot would send, with every ACK checked.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <thread>

#include "k40t_driver/psdk/sim/adapter_simulator.h"
#include "k40t_driver/psdk/sim/adapter_table.h"
#include "k40t_driver/psdk/sim/gimbal_expectation.h"
#include "k40t_driver/psdk/sim/payload_reading.h"

namespace k40t::psdk::sim {
namespace {

using table::Reading;
using table::Request;

// Sends `request` (DATA written with the adapter's own writer) as command `key`, reads the ACK
// with the adapter's own table (adapter_table.h), reports it, and, when it is OK, whether
// `expect` holds for it.
template <class Expect>
Reading exchange(Session& session, CheckReport& report, CommandKey key, const Request& request,
                 const std::string& what, Expect expect) {
  const table::AckEntry* entry = table::find_ack(key);
  const std::string name = entry ? entry->name : "unknown";
  const std::vector<uint8_t>& bytes = request.bytes();
  const AckResult r = session.request_raw(key, bytes.data(), bytes.size());
  const Result<Reading> ack =
      r.received ? table::read(key, r.data) : Result<Reading>::fail(r.message);
  if (!ack) {
    report.add(name, false, what + ": " + ack.error());
    return {};
  }
  std::string detail = what + ": OK";
  const bool passed = expect(ack.value(), detail);
  report.add(name, passed, detail);
  return ack.value();
}

Reading exchange(Session& session, CheckReport& report, CommandKey key, const Request& request,
                 const std::string& what) {
  return exchange(session, report, key, request, what,
                  [](const Reading&, std::string&) { return true; });
}

// Polls with `key` until `done` holds for its ACK or a generous deadline passes, as DJI Pilot
// does: the gimbal and the lens move at a finite speed, the camera takes time to store a photo.
// `last` keeps the last OK answer; a refusal ends the polling (asking again will not help) and
// `why` says what went wrong.
template <class Done>
bool poll_until(Session& session, CommandKey key, Done done, Reading* last, std::string* why) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  *why = "no answer";
  while (std::chrono::steady_clock::now() < until) {
    const AckResult r = session.request_raw(key, nullptr, 0);
    if (!r.received) {
      *why = r.message;
    } else {
      const Result<Reading> ack = table::read(key, r.data);
      if (!ack) {
        *why = ack.error();
        return false;
      }
      *last = ack.value();
      if (done(*last)) return true;
      *why = "not within 10 s";
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return false;
}

// 3.4.4 byte 2.
bool shooting(const Reading& s) {
  return s.number("single") || s.number("interval") || s.number("burst") || s.number("storing");
}

std::string photo_state_text(const Reading& s) {
  if (!shooting(s)) return "idle";
  std::string out;
  if (s.number("single")) out += " single";
  if (s.number("burst")) out += " burst";
  if (s.number("interval")) out += " interval";
  if (s.number("storing")) out += " storing";
  return "shooting:" + out;
}

std::string version_text(const Reading& v) {
  return std::to_string(static_cast<int>(v.number("major"))) + "." +
         std::to_string(static_cast<int>(v.number("minor"))) + "." +
         std::to_string(static_cast<int>(v.number("modify"))) + "." +
         std::to_string(static_cast<int>(v.number("debug")));
}

// The document's keys (2.4 and chapter 3), written here again rather than taken from the structs.
constexpr CommandKey kPsdkVersion{0x01, 0x02}, kHandshake{0x01, 0x03}, kProductInfo{0x01, 0x04},
    kSkyportVersion{0x01, 0x05}, kAlias{0x01, 0x06};
constexpr CommandKey kSetWorkMode{0x04, 0x01}, kGetWorkMode{0x04, 0x02}, kShootPhoto{0x04, 0x03},
    kPhotoState{0x04, 0x04}, kSetPhotoMode{0x04, 0x05}, kGetPhotoMode{0x04, 0x06},
    kRecord{0x04, 0x07}, kRecordState{0x04, 0x08}, kSdCard{0x04, 0x09}, kSetMetering{0x04, 0x20},
    kGetMetering{0x04, 0x21}, kSetFocus{0x04, 0x30}, kGetFocus{0x04, 0x31}, kZoomSpec{0x04, 0x36},
    kSetFocal{0x04, 0x37}, kGetFocal{0x04, 0x38}, kZoomFactor{0x04, 0x39}, kZoomStart{0x04, 0x40},
    kZoomStop{0x04, 0x41}, kCameraCapability{0x04, 0xFF};
constexpr CommandKey kGimbalState{0x05, 0x01}, kGimbalMode{0x05, 0x02}, kReturnHead{0x05, 0x03},
    kGimbalSpeed{0x05, 0x04}, kGimbalAngle{0x05, 0x05}, kCalibrate{0x05, 0x07},
    kCalibrationProgress{0x05, 0x08}, kAdditionalStatus{0x05, 0x09}, kGimbalCapability{0x05, 0xFF};

std::string angles_text(const GimbalStateReading& a) {
  return "pitch " + std::to_string(a.pitch_deg) + ", roll " + std::to_string(a.roll_deg) +
         ", yaw " + std::to_string(a.yaw_deg) + " deg";
}

std::string expected_text(const ExpectedYaw& e) {
  return "yaw expected " + std::to_string(e.yaw_deg) + " +- " + std::to_string(e.tolerance_deg);
}

// The gimbal state read with the adapter's own table (payload_reading.h).
Result<GimbalStateReading> gimbal_state(Session& session, PayloadReading reading) {
  const AckResult r = session.request_raw(kGimbalState, nullptr, 0);
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
  exchange(s, report, kPsdkVersion, Request(), "PSDK version",
           [](const Reading& a, std::string& d) {
             d += " " + version_text(a);
             return a.number("major") > 0 || a.number("minor") > 0;
           });
  // 3.1.3: the ACK's bytes 2:(N+1) are the command's N bytes.
  const std::string text = "SKYPORT link check 0123456789";
  {
    const AckResult r =
        s.request_raw(kHandshake, reinterpret_cast<const uint8_t*>(text.data()), text.size());
    const Result<Reading> ack =
        r.received ? table::read(kHandshake, r.data) : Result<Reading>::fail(r.message);
    const bool echoed = ack && r.data.size == text.size() + 1 &&
                        std::equal(text.begin(), text.end(), r.data.data() + 1);
    report.add(
        "link_handshake", echoed,
        !ack ? "hand-shake: " + ack.error()
             : std::string("hand-shake: OK, ") + (echoed ? "data echoed" : "data NOT echoed"));
  }
  exchange(s, report, kProductInfo, Request(), "product information",
           [](const Reading& a, std::string& d) {
             d += " '" + a.text("product_name") + "'";
             return !a.text("product_name").empty();
           });
  exchange(s, report, kAlias, Request(), "alias");
  exchange(s, report, kSkyportVersion, Request(), "SKYPORT version");
  return report;
}

CheckReport AdapterSimulator::check_camera() {
  CheckReport report;
  Session& s = *session_;
  exchange(s, report, kCameraCapability, Request(), "capabilities",
           [](const Reading& a, std::string& d) {
             const bool set = a.number("camera_commands") != 0;
             d += set ? ", camera set supported" : ", camera set NOT supported";
             return set;
           });
  // 3.4.1: 0 shoot photo, 1 record video.
  exchange(s, report, kSetWorkMode, Request().u8(0), "work mode: photo");
  exchange(s, report, kGetWorkMode, Request(), "work mode reads back",
           [](const Reading& a, std::string&) { return a.number("mode") == 0; });
  exchange(s, report, kShootPhoto, Request().u8(1), "shoot photo");  // 3.4.3: 1 start
  exchange(s, report, kPhotoState, Request(), "photo state", [](const Reading& a, std::string& d) {
    d += ", " + photo_state_text(a);
    return true;
  });
  // Like DJI Pilot: no further camera command while the camera is still shooting or storing.
  std::string why;
  Reading photo_state;
  const bool stored = poll_until(
      s, kPhotoState, [](const Reading& a) { return !shooting(a); }, &photo_state, &why);
  report.add("photo_stored", stored,
             "photo state " + photo_state_text(photo_state) + (stored ? "" : ", " + why));

  check_interval_mode(report);

  exchange(s, report, kSetWorkMode, Request().u8(1), "work mode: video");
  exchange(s, report, kRecord, Request().u8(1), "record start");  // 3.4.7: 1 start, 0 stop
  exchange(s, report, kRecordState, Request(), "recording",
           [](const Reading& a, std::string&) { return a.number("recording") == 1; });
  exchange(s, report, kRecord, Request().u8(0), "record stop");
  exchange(s, report, kRecordState, Request(), "not recording",
           [](const Reading& a, std::string&) { return a.number("recording") == 0; });
  {
    const AckResult r = s.request_raw(kSdCard, nullptr, 0);
    const Result<SdCardReading> sd = r.received ? read_sd_card(r.data, options_.reading)
                                                : Result<SdCardReading>::fail(r.message);
    // A card the pod writes to must not read as read-only or faulty in the adapter's layout.
    const bool healthy = sd && (!sd->inserted || (!sd->read_only && !sd->has_error));
    report.add("get_sd_card_info", healthy,
               !sd ? "SD card: " + sd.error()
                   : std::string("SD card: ") +
                         (sd->inserted ? "inserted, " + std::to_string(sd->free_mb) + " MB free" +
                                             (sd->read_only ? ", READ-ONLY" : "") +
                                             (sd->has_error ? ", ERROR" : "")
                                       : "no card"));
  }

  const Reading spec = exchange(s, report, kZoomSpec, Request(), "optical zoom range",
                                [](const Reading& a, std::string& d) {
                                  d += " " + std::to_string(a.number("min_mm")) + ".." +
                                       std::to_string(a.number("max_mm")) + " mm";
                                  return a.number("min_mm") <= a.number("max_mm");
                                });
  // 3.4.22: uint16 focal length in 0.1 mm, the middle of the range.
  const int focal_tenths =
      static_cast<int>(std::lround((spec.number("min_mm") + spec.number("max_mm")) / 2.0 * 10.0));
  const double focal_mm = focal_tenths / 10.0;
  exchange(s, report, kSetFocal, Request().u16(static_cast<uint16_t>(focal_tenths)),
           "focal length " + std::to_string(focal_mm) + " mm");
  const double tolerance_mm = std::max(spec.number("step_mm"), 0.1);
  // The lens moves at a finite speed: the read-back follows it until it arrives.
  Reading focal_read;
  const bool arrived = poll_until(
      s, kGetFocal,
      [&](const Reading& a) {
        return std::abs(a.number("focal_mm") - focal_mm) <= tolerance_mm + 1e-9;
      },
      &focal_read, &why);
  report.add("get_optical_zoom_focal_length", arrived,
             "focal length reads back: " + std::to_string(focal_read.number("focal_mm")) + " mm" +
                 (arrived ? "" : ", " + why));
  exchange(s, report, kZoomFactor, Request(), "optical zoom factor");
  // 3.4.25: speed 75 NORMAL, direction 1 ZOOM_IN.
  exchange(s, report, kZoomStart, Request().u8(75).u8(1), "continuous zoom in");
  exchange(s, report, kZoomStop, Request(), "zoom stop");

  // Each setting goes to a value other than the usual default and back, so a payload that ignores
  // the command cannot pass by reporting its default. 3.4.15: 0 manual, 1 auto; 3.4.11: 0
  // centre, 1 average.
  for (const uint8_t focus : {0, 1}) {
    const std::string name = focus == 1 ? "auto" : "manual";
    exchange(s, report, kSetFocus, Request().u8(focus), "focus: " + name);
    exchange(s, report, kGetFocus, Request(), "focus reads back " + name,
             [focus](const Reading& a, std::string&) { return a.number("mode") == focus; });
  }
  for (const uint8_t metering : {1, 0}) {
    const std::string name = metering == 0 ? "centre" : "average";
    exchange(s, report, kSetMetering, Request().u8(metering), "metering: " + name);
    exchange(s, report, kGetMetering, Request(), "metering reads back " + name,
             [metering](const Reading& a, std::string&) { return a.number("mode") == metering; });
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
  const AckResult set = s.request_raw(kSetPhotoMode, interval.data(), interval.size());
  report.add(
      "set_shoot_photo_mode", set.ok(),
      "photo mode: interval 5 s: " + (set.received ? ack_code_text(set.code()) : set.message));
  ShootPhotoModeReading last;
  std::string why = "no answer";
  bool read_back = false;
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (set.ok() && !read_back && std::chrono::steady_clock::now() < until) {
    const AckResult r = s.request_raw(kGetPhotoMode, nullptr, 0);
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
  report.add("get_shoot_photo_mode", read_back, "photo mode reads back: " + why);
  const std::vector<uint8_t> single = wide ? std::vector<uint8_t>{0x01, 0x00, 0x00, 0x00, 0x00}
                                           : std::vector<uint8_t>{0x01, 0x00, 0x00, 0x00};
  const AckResult back = s.request_raw(kSetPhotoMode, single.data(), single.size());
  report.add("set_shoot_photo_mode", back.ok(),
             "photo mode: single: " + (back.received ? ack_code_text(back.code()) : back.message));
}

CheckReport AdapterSimulator::check_gimbal() {
  CheckReport report;
  Session& s = *session_;
  exchange(s, report, kGimbalCapability, Request(), "capability",
           [](const Reading& a, std::string&) { return a.number("supported") == 1; });
  const Result<GimbalStateReading> state = gimbal_state(s, options_.reading);
  report.add("get_gimbal_state", static_cast<bool>(state),
             state ? "state: OK, " + state->mode + ", " + angles_text(state.value())
                   : "state: " + state.error());
  // The mode the gimbal says it is in must be accepted; PSDK lets a gimbal answer 0x02 for a mode
  // it does not have (a pod whose yaw is relative to the aircraft has no free mode), never 0x01.
  // 3.5.2: 0 free, 1 FPV, 2 following.
  const uint8_t own = state ? state->set_mode_code : 2;
  exchange(s, report, kGimbalMode, Request().u8(own),
           "mode: " + (state ? state->mode : std::string("following")) + " (its own)");
  {
    const std::vector<uint8_t> free{0x00};
    const AckResult r = s.request_raw(kGimbalMode, free.data(), free.size());
    const bool answered = r.received && r.data.size >= 1 &&
                          (r.code() == static_cast<uint8_t>(AckCode::kOk) ||
                           r.code() == static_cast<uint8_t>(AckCode::kUnsupported));
    report.add("set_gimbal_mode", answered,
               "mode: free: " + (r.received ? ack_code_text(r.code()) : r.message));
  }
  // 3.5.5: floats in degrees, pitch, roll, yaw; in the payload's frame (P28): read back as set
  // with joint angles, with the heading's turn since the command in NED (gimbal_expectation.h).
  // The simulated pod is level: its NED pitch is its joint pitch.
  const GimbalExpectation expect(flight_, options_.reading == PayloadReading::kDjiHeaders, 2.0);
  const double command_s = elapsed_s();
  exchange(s, report, kGimbalAngle, Request().f32(-30.0f).f32(0.0f).f32(20.0f),
           "angle pitch -30, yaw 20 deg");
  GimbalStateReading last;
  std::string why;
  const bool reached = poll_gimbal(
      s, options_.reading,
      [&](const GimbalStateReading& a) {
        return std::abs(a.pitch_deg + 30.0) <= 2.0 &&
               expect.after_angle(20.0, command_s, elapsed_s()).holds(a.yaw_deg);
      },
      &last, &why);
  report.add("gimbal_reaches_angle", reached,
             angles_text(last) + ", " +
                 expected_text(expect.after_angle(20.0, command_s, elapsed_s())) +
                 (reached ? "" : ", " + why));

  // 3.5.4: int16 rates in 0.1 deg/s (pitch, roll, yaw), then the action (1 control, 0 stop).
  exchange(s, report, kGimbalSpeed, Request().i16(0).i16(0).i16(100).u8(1), "yaw at 10 deg/s");
  exchange(s, report, kGimbalSpeed, Request().i16(0).i16(0).i16(0).u8(0), "speed control stop");

  exchange(s, report, kReturnHead, Request(), "return head");
  const bool centred = poll_gimbal(
      s, options_.reading,
      [&](const GimbalStateReading& a) {
        return std::abs(a.pitch_deg) <= 2.0 && expect.centred(elapsed_s()).holds(a.yaw_deg);
      },
      &last, &why);
  report.add("gimbal_returns_to_centre", centred,
             angles_text(last) + ", " + expected_text(expect.centred(elapsed_s())) +
                 (centred ? "" : ", " + why));

  exchange(s, report, kCalibrate, Request(), "calibration");
  exchange(s, report, kCalibrationProgress, Request(), "calibration progress",
           [](const Reading& a, std::string& d) {
             d += " " + std::to_string(static_cast<int>(a.number("percent"))) + " %";
             return a.number("status") != 2;  // 2: failed
           });
  exchange(s, report, kAdditionalStatus, Request(), "additional status");
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
