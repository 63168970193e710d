// --allow-motion: the report's signs and the command's scale, learned by moving the gimbal.
//
// 0x000012 (3.1.2.2) names its directions (pitch 0 up / 1 down, yaw 0 left / 1 right), so a
// command says unambiguously which way the gimbal must turn, while its magnitude unit and the
// report's (0x000002) signs are open. The command is absolute, so with an unknown scale only
// targets near the centre are safe: the gimbal is centred first (0x000010's "back to centre" means
// the same under every reading), then told to go right by 1, 10, 100, 1000 counts until it moves
// half a degree (at most ~5 degrees whatever the scale), then 3 degrees right and left at the
// scale found, 3 degrees up and down, and finally back to where it was.
#include <cmath>
#include <cstdio>

#include "k40t_driver/protocol/messages/gimbal.h"
#include "probe_learn.h"

namespace k40t::tool {

namespace {

using namespace std::chrono_literals;

struct Pose {
  double yaw = 0;  // degrees in the report's own sign, -180..180 (a heading is brought back)
  double pitch = 0;
  int raw_yaw = 0;  // as int16: shows signed against heading
};

// 0x000002's joint yaw read so that a signed and a heading yaw give the same direction.
double yaw_degrees(uint16_t raw) {
  const double as_signed = static_cast<int16_t>(raw) / 100.0;
  if (as_signed > 180) return as_signed - 360;     // a heading of 180..327.67
  if (as_signed < -180) return raw / 100.0 - 360;  // a heading of 327.68..360
  return as_signed;
}

class Mover {
 public:
  Mover(ProbeLink& link, std::string& log) : link_(link), log_(log) {}

  // The pose once the gimbal has stopped: three reports in a row with the joint rates under
  // 0.5 deg/s and the joints within 0.05 deg of each other (a real gimbal's readings jitter).
  Result<Pose> settle(std::chrono::milliseconds timeout) {
    const auto since = ProbeClock::now() + 300ms;  // give a commanded move time to start
    std::optional<Pose> pose;
    link_.wait_until(
        [&] {
          const std::vector<HeardFrame> heard =
              link_.frames_since(protocol::GimbalAttitude::kId, since);
          if (heard.size() < 3) return false;
          std::vector<Pose> last;
          for (size_t i = heard.size() - 3; i < heard.size(); ++i) {
            const std::vector<uint8_t>& p = heard[i].payload;
            if (p.size() < 18) return false;
            const auto centi = [&](size_t at) { return static_cast<int16_t>(u16_little(p, at)); };
            if (std::abs(centi(12)) >= 50 || std::abs(centi(14)) >= 50) return false;  // rates
            last.push_back(Pose{yaw_degrees(u16_little(p, 0)), centi(4) / 100.0, centi(0)});
          }
          for (const Pose& p : last) {
            if (std::abs(p.yaw - last.back().yaw) > 0.05 ||
                std::abs(p.pitch - last.back().pitch) > 0.05)
              return false;
          }
          pose = last.back();
          return true;
        },
        timeout);
    if (!pose)
      return Result<Pose>::fail("the gimbal did not come to rest (0x000002) within " +
                                std::to_string(timeout.count() / 1000) + " s");
    return *pose;
  }

  // 0x000012 with raw magnitudes: direction bytes pitch 0 up / 1 down, yaw 0 left / 1 right,
  // 2 no movement; magnitudes low byte first (2.1).
  Status command(uint8_t pitch_dir, uint16_t pitch, uint8_t yaw_dir, uint16_t yaw) {
    const uint8_t payload[7] = {
        pitch_dir, static_cast<uint8_t>(pitch & 0xFF), static_cast<uint8_t>(pitch >> 8),
        yaw_dir,   static_cast<uint8_t>(yaw & 0xFF),   static_cast<uint8_t>(yaw >> 8),
        0};
    char line[120];
    std::snprintf(line, sizeof(line), "0x000012 pitch %s %u, yaw %s %u", direction(pitch_dir, true),
                  pitch, direction(yaw_dir, false), yaw);
    return check(link_.session().request_raw(protocol::GimbalAngleRequest::kId, payload, 7), line);
  }

  Status centre() {
    protocol::GimbalControlRequest request;
    request.mode = protocol::GimbalMode::kCentre;
    return check(link_.session().request(request), "0x000010 back to centre");
  }

  Result<Pose> move_and_settle(Status sent, std::chrono::milliseconds timeout = 6s) {
    if (!sent) return Result<Pose>::fail(sent.message());
    Result<Pose> pose = settle(timeout);
    if (pose) {
      char line[96];
      std::snprintf(line, sizeof(line), "  -> 0x000002 yaw %.2f, pitch %.2f\n", pose->yaw,
                    pose->pitch);
      log_ += line;
    }
    return pose;
  }

 private:
  static const char* direction(uint8_t code, bool pitch) {
    if (code == protocol::GimbalAngleRequest::kNoMovement) return "none";
    if (pitch) return code == 0 ? "up" : "down";
    return code == 0 ? "left" : "right";
  }
  Status check(const session::AckResult& result, const std::string& what) {
    log_ += what + "\n";
    if (result.ok()) return Status::ok();
    return Status::fail(what + ": " + (result.received ? "refused: " : "") + result.message);
  }

  ProbeLink& link_;
  std::string& log_;
};

constexpr uint8_t kUp = 0, kDown = 1, kLeft = 0, kRight = 1;
constexpr uint8_t kNone = protocol::GimbalAngleRequest::kNoMovement;
constexpr double kStepDeg = 3;

std::string deg_text(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%+.2f", value);
  return text;
}

// Back to `start`, with what was learned (the command's signs are the document's: right, up).
Status go_back(Mover& mover, const Pose& start, int scale, bool yaw_right, bool pitch_up) {
  const double yaw = yaw_right ? start.yaw : -start.yaw;
  const double pitch = pitch_up ? start.pitch : -start.pitch;
  Result<Pose> back = mover.move_and_settle(
      mover.command(
          pitch >= 0 ? kUp : kDown, static_cast<uint16_t>(std::lround(std::abs(pitch) * scale)),
          yaw >= 0 ? kRight : kLeft, static_cast<uint16_t>(std::lround(std::abs(yaw) * scale))),
      20s);
  if (!back) return back.status();
  if (std::abs(back->yaw - start.yaw) > 0.5 || std::abs(back->pitch - start.pitch) > 0.5)
    return Status::fail("returned to yaw " + deg_text(back->yaw) + ", pitch " +
                        deg_text(back->pitch) + " instead of " + deg_text(start.yaw) + ", " +
                        deg_text(start.pitch));
  return Status::ok();
}

}  // namespace

Status learn_from_motion(ProbeLink& link, ProbeReport& report, std::string& log) {
  Mover mover(link, log);
  Result<Pose> start = mover.settle(6s);
  if (!start) return start.status();
  if (std::abs(start->yaw) > 0.5 || std::abs(start->pitch) > 0.5) {
    Result<Pose> centred = mover.move_and_settle(mover.centre(), 30s);
    if (!centred) return centred.status();
    if (std::abs(centred->yaw) > 0.5 || std::abs(centred->pitch) > 0.5)
      return Status::fail("0x000010 back to centre left the gimbal at yaw " +
                          deg_text(centred->yaw) + ", pitch " + deg_text(centred->pitch));
  }
  // Right by 1, 10, 100, 1000 counts until half a degree shows: a first estimate of the scale.
  std::optional<Pose> first;
  uint16_t counts = 1;
  for (; counts <= 1000; counts *= 10) {
    Result<Pose> pose = mover.move_and_settle(mover.command(kNone, 0, kRight, counts));
    if (!pose) return pose.status();
    if (std::abs(pose->yaw) >= 0.5) {
      first = *pose;
      break;
    }
  }
  if (!first) return Status::fail("the gimbal did not move: 0x000012 yaw right 1000 counts");
  const double estimate = counts / std::abs(first->yaw);
  const auto step = static_cast<uint16_t>(std::lround(kStepDeg * estimate));
  Result<Pose> right = mover.move_and_settle(mover.command(kNone, 0, kRight, step));
  if (!right) return right.status();
  Result<Pose> left = mover.move_and_settle(mover.command(kNone, 0, kLeft, step));
  if (!left) return left.status();
  const double span = right->yaw - left->yaw;
  if (std::abs(span) < kStepDeg) {
    return Status::fail("0x000012 right then left " + std::to_string(step) +
                        " counts moved the yaw only " + deg_text(span) + " deg");
  }
  const int scale = static_cast<int>(std::lround(2 * step / std::abs(span)));
  const bool yaw_right = span > 0;
  report.learned("angle_command_scale", std::to_string(scale),
                 "0x000012 right/left " + std::to_string(step) + " counts: yaw span " +
                     deg_text(std::abs(span)) + " deg");
  report.learned("yaw_sign", yaw_right ? "right" : "left",
                 "0x000012 right: 0x000002 yaw " + deg_text(right->yaw));
  // One of the two sides is below zero in the command's own terms: signed or heading shows.
  const int below_zero = yaw_right ? left->raw_yaw : right->raw_yaw;
  report.learned("yaw_range", below_zero < 0 && below_zero >= -18000 ? "signed" : "heading",
                 "0x000012 " + std::string(yaw_right ? "left" : "right") + " of centre: raw " +
                     std::to_string(below_zero));
  // Pitch, at the scale found: up, then down.
  const auto pitch_step = static_cast<uint16_t>(std::lround(kStepDeg * scale));
  Result<Pose> up = mover.move_and_settle(mover.command(kUp, pitch_step, kNone, 0));
  if (!up) return up.status();
  Result<Pose> down = mover.move_and_settle(mover.command(kDown, pitch_step, kNone, 0));
  if (!down) return down.status();
  const double pitch_span = up->pitch - down->pitch;
  if (std::abs(std::abs(pitch_span) - 2 * kStepDeg) > 0.5)
    return Status::fail("0x000012 up then down " + deg_text(kStepDeg) + " deg moved the pitch " +
                        deg_text(pitch_span) + " deg: pitch and yaw scales differ");
  const bool pitch_up = pitch_span > 0;
  report.learned("pitch_sign", pitch_up ? "up" : "down",
                 "0x000012 up: 0x000002 pitch " + deg_text(up->pitch));
  return go_back(mover, *start, scale, yaw_right, pitch_up);
}

}  // namespace k40t::tool
