// --calibration: one drift calibration (0x000013, 3.1.2.3) and how its end shows. The document
// gives the calibrations only an ACK; 0x000008 (3.2.1.4) is the camera's upgrade/repair report.
// The reading `calibration_end` (docs/protocol/decisions.md#conventions) is "status" when the pod
// reports "repairing" (state 3) in 0x000008 soon after the OK ACK, and "ack" when it does not: a
// pod that answers the calibration when it is done (the session waits up to 60 s for that ACK,
// protocol/repeat_safety.h).
#include <cstdio>

#include "k40t_driver/protocol/messages/camera_reports.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "probe_learn.h"

namespace k40t::tool {

namespace {

using namespace std::chrono_literals;

// The same window the driver's `auto` uses (conventions.h, CalibrationEnd::kAuto).
constexpr auto kRepairingWindow = 1500ms;
constexpr auto kLongestCalibration = 180s;
constexpr uint8_t kSucceeded = 0, kFailed = 1, kRepairing = 3;

// The first 0x000008 state after `since` among `states`; with `after_repairing`, only after a
// "repairing" (a pod that reports an idle "succeeded" every second must not end it early).
std::optional<uint8_t> state_since(const ProbeLink& link, ProbeClock::time_point since,
                                   std::initializer_list<uint8_t> states,
                                   bool after_repairing = false) {
  bool repairing_seen = !after_repairing;
  for (const HeardFrame& f : link.frames_since(protocol::CameraUpgradeStatus::kId, since)) {
    if (f.payload.empty()) continue;
    if (!repairing_seen) {
      repairing_seen = f.payload[0] == kRepairing;
      continue;
    }
    for (uint8_t s : states) {
      if (f.payload[0] == s) return s;
    }
  }
  return std::nullopt;
}

double seconds_since(ProbeClock::time_point start) {
  return std::chrono::duration<double>(ProbeClock::now() - start).count();
}

}  // namespace

Status learn_calibration_end(ProbeLink& link, ProbeReport& report, std::string& log) {
  const ProbeClock::time_point sent = ProbeClock::now();
  const session::AckResult ack = link.session().request(protocol::GimbalDriftCalibrationRequest{});
  log += "0x000013 drift calibration\n";
  if (!ack.ok())
    return Status::fail(std::string("0x000013 drift calibration: ") +
                        (ack.received ? "refused: " : "") + ack.message);
  const ProbeClock::time_point acked = ProbeClock::now();
  char line[160];
  std::snprintf(line, sizeof(line), "  OK ACK after %.2f s\n", seconds_since(sent));
  log += line;
  link.wait_until([&] { return state_since(link, acked, {kRepairing}).has_value(); },
                  std::chrono::duration_cast<std::chrono::milliseconds>(kRepairingWindow));
  if (!state_since(link, acked, {kRepairing})) {
    // A pod whose ACK is the end answers once the calibration is done: the ACK's delay is its
    // length (an OK at once is a calibration the pod does not time for the host).
    std::snprintf(line, sizeof(line),
                  "0x010013 OK %.1f s after the request, then no 0x000008 'repairing' within "
                  "1.5 s: the ACK is the end",
                  std::chrono::duration<double>(acked - sent).count());
    report.learned("calibration_end", "ack", line);
    return Status::ok();
  }
  // "repairing": the end is the next "succeeded" or "failed" after it.
  std::optional<uint8_t> end;
  link.wait_until(
      [&] {
        end = state_since(link, acked, {kSucceeded, kFailed}, true);
        return end.has_value();
      },
      std::chrono::duration_cast<std::chrono::milliseconds>(kLongestCalibration));
  if (!end) {
    report.learned("calibration_end", "status",
                   "0x000008 'repairing' after 0x010013 OK, but no end within 180 s");
    return Status::fail("the calibration did not end within 180 s (0x000008)");
  }
  std::snprintf(line, sizeof(line), "0x000008 'repairing', then '%s' %.1f s after the OK ACK",
                *end == kSucceeded ? "succeeded" : "failed", seconds_since(acked));
  report.learned("calibration_end", "status", line);
  return Status::ok();
}

}  // namespace k40t::tool
