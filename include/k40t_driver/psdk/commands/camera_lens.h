// Camera command set 0x04, exposure, focus and zoom (protocol document sections 3.4.11 to
// 3.4.32). A "set" command and the ACK of its "get" share one value struct (mixin).
#pragma once

#include "k40t_driver/psdk/commands/declare.h"

namespace k40t::psdk {

enum class MeteringMode : uint8_t { kCenter = 0, kAverage = 1, kSpot = 2 };
const char* to_string(MeteringMode mode);

enum class FocusMode : uint8_t { kManual = 0, kAuto = 1 };
const char* to_string(FocusMode mode);

enum class ZoomSpeed : uint8_t {
  kSlowest = 72,
  kSlow = 73,
  kModeratelySlow = 74,
  kNormal = 75,
  kModeratelyFast = 76,
  kFast = 77,
  kFastest = 78,
};
const char* to_string(ZoomSpeed speed);

enum class ZoomDirection : uint8_t { kOut = 0, kIn = 1 };
const char* to_string(ZoomDirection direction);

constexpr double kMaxOpticalZoomFactor = 30.0;  // 3.4.24

struct MeteringModeValue : ModeValue<MeteringMode, MeteringMode::kCenter> {};

// 3.4.11 / 3.4.12: SetMeteringMode, MeteringModeAck, GetMeteringMode.
K40T_PSDK_SETTING(MeteringMode, metering_mode, MeteringModeValue, kCamera, 0x20, "3.4.11", 0x21,
                  "3.4.12");

// 3.4.13 / 3.4.14: one cell of a 12 x 8 grid.
struct SpotZone {
  K40T_PSDK_FIELDS((uint8_t, column, wire::bits(0, 4)),  // 0..11
                   (uint8_t, row, wire::bits(4, 4)));    // 0..7
};

struct SpotZoneValue {
  K40T_PSDK_FIELDS((SpotZone, zone, wire::packed8));
  Status validate() const {
    return first_failure(check_int("column", zone.column, 0, 11), check_int("row", zone.row, 0, 7));
  }
};

// 3.4.13 / 3.4.14: SetSpotMeteringZone, SpotMeteringZoneAck, GetSpotMeteringZone.
K40T_PSDK_SETTING(SpotMeteringZone, spot_metering_zone, SpotZoneValue, kCamera, 0x22, "3.4.13",
                  0x23, "3.4.14");

struct FocusModeValue : ModeValue<FocusMode, FocusMode::kAuto> {};

// 3.4.15 / 3.4.16: SetFocusMode, FocusModeAck, GetFocusMode.
K40T_PSDK_SETTING(FocusMode, focus_mode, FocusModeValue, kCamera, 0x30, "3.4.15", 0x31, "3.4.16");

// 3.4.17 / 3.4.18: fractions of the image, (0, 0) top left.
struct FocusZoneValue {
  K40T_PSDK_FIELDS((float, x, wire::f32, 0.5f), (float, y, wire::f32, 0.5f));
  Status validate() const {
    return first_failure(check_real("x", x, 0.0, 1.0), check_real("y", y, 0.0, 1.0));
  }
};

// 3.4.17 / 3.4.18: SetFocusZone, FocusZoneAck, GetFocusZone.
K40T_PSDK_SETTING(FocusZone, focus_zone, FocusZoneValue, kCamera, 0x32, "3.4.17", 0x33, "3.4.18");

// 3.4.19 / 3.4.20: 1.0 up to the maximum of 3.4.32 (which the codec does not know).
struct DigitalZoomFactorValue {
  K40T_PSDK_FIELDS((float, factor_x, wire::f32, 1.0f));
  Status validate() const { return check_real("factor_x", factor_x, 1.0, 1e6); }
};

// 3.4.19 / 3.4.20: SetDigitalZoomFactor, DigitalZoomFactorAck, GetDigitalZoomFactor.
K40T_PSDK_SETTING(DigitalZoomFactor, digital_zoom_factor, DigitalZoomFactorValue, kCamera, 0x34,
                  "3.4.19", 0x35, "3.4.20");

// 3.4.21 ACK: focal lengths in 0.1 mm on the wire.
struct OpticalZoomSpecValue {
  K40T_PSDK_FIELDS((double, max_focal_length_mm, wire::scaled<uint16_t>(10)),
                   (double, min_focal_length_mm, wire::scaled<uint16_t>(10)),
                   (double, focal_length_step_mm, wire::scaled<uint16_t>(10)));
  Status validate() const;
};

// 3.4.21: GetOpticalZoomSpec, OpticalZoomSpecAck.
K40T_PSDK_GET(OpticalZoomSpec, optical_zoom_spec, OpticalZoomSpecValue, kCamera, 0x36, "3.4.21");

// 3.4.22 / 3.4.23: the document says "1:2 Float" in 0.1 mm; two bytes cannot hold a float, and
// 3.4.21 gives focal lengths as uint16 0.1 mm, so this is read as uint16 0.1 mm (docs/psdk.md).
struct FocalLengthValue {
  K40T_PSDK_FIELDS((double, focal_length_mm, wire::scaled<uint16_t>(10)));
};

// 3.4.22 / 3.4.23: SetOpticalZoomFocalLength, OpticalZoomFocalLengthAck, GetOpticalZoomFocalLength.
K40T_PSDK_SETTING(OpticalZoomFocalLength, optical_zoom_focal_length, FocalLengthValue, kCamera,
                  0x37, "3.4.22", 0x38, "3.4.23");

// 3.4.24 ACK.
struct OpticalZoomFactorValue {
  K40T_PSDK_FIELDS((float, factor_x, wire::f32, 1.0f));
  Status validate() const { return check_real("factor_x", factor_x, 1.0, kMaxOpticalZoomFactor); }
};

// 3.4.24: GetOpticalZoomFactor, OpticalZoomFactorAck.
K40T_PSDK_GET(OpticalZoomFactor, optical_zoom_factor, OpticalZoomFactorValue, kCamera, 0x39,
              "3.4.24");

// 3.4.25: zoom until the end of travel or 3.4.26.
struct StartContinuousZoom : Command<CommandSet::kCamera, 0x40, Sender::kAdapter, PlainAck> {
  K40T_PSDK_NAMED("start_continuous_zoom", "3.4.25");
  K40T_PSDK_FIELDS((ZoomSpeed, speed, wire::u8, ZoomSpeed::kNormal),
                   (ZoomDirection, direction, wire::u8, ZoomDirection::kIn));
};

// 3.4.26.
K40T_PSDK_NO_DATA(StopContinuousZoom, kCamera, 0x41, PlainAck, "stop_continuous_zoom", "3.4.26");

// 3.4.27 / 3.4.28.
K40T_PSDK_FLAGS(FocusAssistant, for_auto_focus, for_manual_focus);

struct FocusAssistantValue {
  K40T_PSDK_FIELDS((FocusAssistant, assistant, wire::packed8));
};

// 3.4.27 / 3.4.28: SetFocusAssistant, FocusAssistantAck, GetFocusAssistant.
K40T_PSDK_SETTING(FocusAssistant, focus_assistant, FocusAssistantValue, kCamera, 0x42, "3.4.27",
                  0x43, "3.4.28");

// 3.4.29 ACK.
struct FocusRingUpperBoundValue {
  K40T_PSDK_FIELDS((uint16_t, upper_bound, wire::u16));
};

// 3.4.29: GetFocusRingUpperBound, FocusRingUpperBoundAck.
K40T_PSDK_GET(FocusRingUpperBound, focus_ring_upper_bound, FocusRingUpperBoundValue, kCamera, 0x44,
              "3.4.29");

// 3.4.30 / 3.4.31: 0 = infinity .. upper bound = closest focus.
struct FocusRingValue {
  K40T_PSDK_FIELDS((uint16_t, value, wire::u16));
};

// 3.4.30 / 3.4.31: SetFocusRing, FocusRingAck, GetFocusRing.
K40T_PSDK_SETTING(FocusRing, focus_ring, FocusRingValue, kCamera, 0x45, "3.4.30", 0x46, "3.4.31");

// 3.4.32 ACK.
struct DigitalZoomSpecValue {
  K40T_PSDK_FIELDS((float, max_factor_x, wire::f32, 1.0f));
  Status validate() const { return check_real("max_factor_x", max_factor_x, 1.0, 1e6); }
};

// 3.4.32: GetDigitalZoomSpec, DigitalZoomSpecAck.
K40T_PSDK_GET(DigitalZoomSpec, digital_zoom_spec, DigitalZoomSpecValue, kCamera, 0x47, "3.4.32");

}  // namespace k40t::psdk
