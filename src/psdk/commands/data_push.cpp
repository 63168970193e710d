#include "k40t_driver/psdk/commands/data_push.h"

#include <cmath>

#include "k40t_driver/codec/enum_names.h"

namespace k40t::psdk {

const char* to_string(GpsSignal signal) {
  return consecutive_name(signal, 0, {"none", "very_weak", "medium", "very_strong"});
}

const char* to_string(LandingState state) {
  return consecutive_name(state, 0, {"unknown", "landed", "in_the_sky"});
}

const char* to_string(DroneType type) {
  return consecutive_name(type, 0,
                          {"unknown", "M200", "M210", "M210 RTK", "M600", "M600 PRO", "M200 V2",
                           "M210 V2", "M210 RTK V2"});
}

const char* to_string(OtherPayloadType type) {
  return consecutive_name(type, 0, {"unknown", "ZENMUSE X5S", "ZENMUSE Z30"});
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
