#include "k40t_driver/protocol/messages/gimbal.h"

#include <cmath>
#include <string>

namespace k40t::protocol {

// ---- enums ----------------------------------------------------------------------------------
const char* to_string(GimbalLinkState state) {
  switch (state) {
    case GimbalLinkState::kNormal:
      return "normal";
    case GimbalLinkState::kAbnormal:
      return "abnormal";
  }
  return nullptr;
}

const char* to_string(GimbalUpgradeState state) {
  switch (state) {
    case GimbalUpgradeState::kNormal:
      return "normal";
    case GimbalUpgradeState::kKernelUpgradeIncomplete:
      return "kernel upgrade incomplete";
    case GimbalUpgradeState::kFirmwareUpgradeIncomplete:
      return "firmware upgrade incomplete";
  }
  return nullptr;
}

const char* to_string(GimbalStabilisationState state) {
  switch (state) {
    case GimbalStabilisationState::kOff:
      return "off";
    case GimbalStabilisationState::kStabilising:
      return "stabilising";
    case GimbalStabilisationState::kFailed:
      return "failed";
    case GimbalStabilisationState::kFeatureLost:
      return "feature lost";
  }
  return nullptr;
}

const char* to_string(GimbalMode mode) {
  switch (mode) {
    case GimbalMode::kNone:
      return "none";
    case GimbalMode::kCentre:
      return "centre";
    case GimbalMode::kLookDown:
      return "look down";
  }
  return nullptr;
}

const char* to_string(GimbalYawDirection direction) {
  switch (direction) {
    case GimbalYawDirection::kLeft:
      return "left";
    case GimbalYawDirection::kRight:
      return "right";
    case GimbalYawDirection::kStop:
      return "stop";
  }
  return nullptr;
}

const char* to_string(GimbalPitchDirection direction) {
  switch (direction) {
    case GimbalPitchDirection::kUp:
      return "up";
    case GimbalPitchDirection::kDown:
      return "down";
    case GimbalPitchDirection::kStop:
      return "stop";
  }
  return nullptr;
}

const char* to_string(GimbalAimLens lens) {
  switch (lens) {
    case GimbalAimLens::kTele:
      return "telephoto";
    case GimbalAimLens::kWide:
      return "wide-angle";
    case GimbalAimLens::kThermal:
      return "thermal";
  }
  return nullptr;
}

// ---- 0x000012 -------------------------------------------------------------------------------
namespace {

// How one axis of 0x000012 maps a sign to its direction byte.
struct AngleAxis {
  const char* name;
  uint8_t positive_code;  // the direction byte for a positive angle
  uint8_t negative_code;
  const char* codes;  // for error messages
};
constexpr uint8_t kNoMovement = 2;
constexpr AngleAxis kPitchAxis{"pitch", 0, 1, "0 (up), 1 (down) or 2 (no movement)"};
constexpr AngleAxis kYawAxis{"yaw", 1, 0, "0 (left), 1 (right) or 2 (no movement)"};

void encode_axis(ByteWriter& w, const AngleAxis& axis, bool move, double deg, int scale) {
  if (!move) {
    w.u8(kNoMovement);
    w.u16(0);
    return;
  }
  w.u8(deg < 0 ? axis.negative_code : axis.positive_code);
  w.u16(to_wire<uint16_t>(std::fabs(deg), scale));
}

Status decode_axis(ByteReader& r, const AngleAxis& axis, int scale, bool* move, double* deg) {
  const uint8_t direction = r.u8();
  const double magnitude = r.u16() / static_cast<double>(scale);
  *move = direction != kNoMovement;
  if (direction == kNoMovement) {
    *deg = 0;
  } else if (direction == axis.positive_code) {
    *deg = magnitude;
  } else if (direction == axis.negative_code) {
    *deg = -magnitude;
  } else if (r.ok()) {
    return Status::fail(std::string(axis.name) + " direction byte must be " + axis.codes +
                        ", got " + std::to_string(direction));
  }
  return Status::ok();
}

}  // namespace

Status GimbalAngleRequest::validate() const {
  return first_failure(
      check_range("pitch_deg", pitch_deg, kPitchMinDeg, kPitchMaxDeg, "deg (up positive)"),
      check_range("yaw_deg", yaw_deg, -kYawLimitDeg, kYawLimitDeg, "deg (right positive)"));
}

void GimbalAngleRequest::encode(ByteWriter& w, const CodecOptions& o) const {
  encode_axis(w, kPitchAxis, pitch_move, pitch_deg, o.angle_command_scale);
  encode_axis(w, kYawAxis, yaw_move, yaw_deg, o.angle_command_scale);
  w.zeros(1);
}

Status GimbalAngleRequest::decode(ByteReader& r, const CodecOptions& o) {
  if (o.angle_command_scale <= 0) {
    return Status::fail("angle_command_scale must be positive, got " +
                        std::to_string(o.angle_command_scale));
  }
  const Status pitch = decode_axis(r, kPitchAxis, o.angle_command_scale, &pitch_move, &pitch_deg);
  if (!pitch) return pitch;
  return decode_axis(r, kYawAxis, o.angle_command_scale, &yaw_move, &yaw_deg);
}

// ---- 0x010018 -------------------------------------------------------------------------------
Status GimbalVersionAck::finish_decode(size_t payload_size) const {
  constexpr size_t kVersionSize = kSize - 1;  // the reserved last byte is optional
  if (payload_size == kMinSize || payload_size >= kVersionSize) return Status::ok();
  return payload_size_error(kName, kId, payload_size, kVersionSize);
}

// ---- 0x00002C -------------------------------------------------------------------------------
namespace {
constexpr double kZoomScale = 10;  // uint16 x0.1
}

Status GimbalPointAtRequest::validate() const {
  const Status lens_ok = check_enum("lens", lens);
  if (!lens_ok) return lens_ok;
  Status zoom_ok = Status::ok();
  if (lens == GimbalAimLens::kTele) {
    zoom_ok = check_range("zoom_x", zoom_x, 3.5, 160.0, "x for the telephoto lens");
  } else {
    const std::string unit = std::string("x (whole numbers) for the ") + to_string(lens) + " lens";
    zoom_ok = check_range("zoom_x", zoom_x, 1.0, 8.0, unit.c_str());
    if (zoom_ok && zoom_x != std::floor(zoom_x)) {
      zoom_ok = Status::fail("field 'zoom_x' must be a whole number 1..8 for the " +
                             std::string(to_string(lens)) + " lens, got " + std::to_string(zoom_x));
    }
  }
  return first_failure(zoom_ok, check_range("x_px", int64_t{x_px}, 1, 1920, "px"),
                       check_range("y_px", int64_t{y_px}, 1, 1080, "px"));
}

void GimbalPointAtRequest::encode(ByteWriter& w, const CodecOptions&) const {
  w.u8(static_cast<uint8_t>(lens));
  w.u16(to_wire<uint16_t>(zoom_x, kZoomScale));
  w.u16(x_px);
  w.u16(y_px);
}

Status GimbalPointAtRequest::decode(ByteReader& r, const CodecOptions&) {
  lens = static_cast<GimbalAimLens>(r.u8());
  zoom_x = r.u16() / kZoomScale;
  x_px = r.u16();
  y_px = r.u16();
  return Status::ok();
}

}  // namespace k40t::protocol
