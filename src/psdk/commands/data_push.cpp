#include "k40t_driver/psdk/commands/data_push.h"

#include <cmath>

namespace k40t::psdk {

const char* to_string(GpsSignal signal) {
  switch (signal) {
    case GpsSignal::kNone:
      return "none";
    case GpsSignal::kVeryWeak:
      return "very_weak";
    case GpsSignal::kMedium:
      return "medium";
    case GpsSignal::kVeryStrong:
      return "very_strong";
  }
  return nullptr;
}

const char* to_string(LandingState state) {
  switch (state) {
    case LandingState::kUnknown:
      return "unknown";
    case LandingState::kLanded:
      return "landed";
    case LandingState::kInTheSky:
      return "in_the_sky";
  }
  return nullptr;
}

const char* to_string(DroneType type) {
  switch (type) {
    case DroneType::kUnknown:
      return "unknown";
    case DroneType::kM200:
      return "M200";
    case DroneType::kM210:
      return "M210";
    case DroneType::kM210Rtk:
      return "M210 RTK";
    case DroneType::kM600:
      return "M600";
    case DroneType::kM600Pro:
      return "M600 PRO";
    case DroneType::kM200V2:
      return "M200 V2";
    case DroneType::kM210V2:
      return "M210 V2";
    case DroneType::kM210RtkV2:
      return "M210 RTK V2";
  }
  return nullptr;
}

const char* to_string(OtherPayloadType type) {
  switch (type) {
    case OtherPayloadType::kUnknown:
      return "unknown";
    case OtherPayloadType::kZenmuseX5s:
      return "ZENMUSE X5S";
    case OtherPayloadType::kZenmuseZ30:
      return "ZENMUSE Z30";
  }
  return nullptr;
}

Status DateTime::validate() const {
  // Second 60 is a leap second.
  return first_failure(check_int("month", month, 1, 12), check_int("day", day, 1, 31),
                       check_int("hour", hour, 0, 23), check_int("minute", minute, 0, 59),
                       check_int("second", second, 0, 60));
}

Status GpsPush::validate() const {
  return first_failure(check_real("longitude_rad", longitude_rad, -M_PI, M_PI, "rad"),
                       check_real("latitude_rad", latitude_rad, -M_PI / 2, M_PI / 2, "rad"));
}

Status RawGpsPush::validate() const {
  return first_failure(check_real("longitude_deg", longitude_deg, -180.0, 180.0, "deg"),
                       check_real("latitude_deg", latitude_deg, -90.0, 90.0, "deg"));
}

Status RawRtkPush::validate() const {
  return first_failure(check_real("longitude_deg", longitude_deg, -180.0, 180.0, "deg"),
                       check_real("latitude_deg", latitude_deg, -90.0, 90.0, "deg"));
}

}  // namespace k40t::psdk
