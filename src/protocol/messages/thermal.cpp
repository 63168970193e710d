#include "k40t_driver/protocol/messages/thermal.h"

#include <string>

#include "k40t_driver/codec/enum_names.h"
#include "k40t_driver/protocol/cfg_enum_names.h"
#include "setting_bytes.h"

namespace k40t::protocol {

const char* to_string(Palette palette) {
  return cfg_enums::constant_of(cfg_enums::palette, static_cast<int>(palette), "palette_");
}

const char* to_string(ThermalGainMode mode) {
  return cfg_enums::constant_of(cfg_enums::thermal_gain, static_cast<int>(mode), "gain_");
}

const char* to_string(ThermalMeasurementType type) {
  return consecutive_name(type, 0, {"point", "area"});
}

const char* to_string(ThermalCoreType type) {
  return consecutive_name(type, 0, {"sighting", "radiometric"});
}

// ---- 0x010100 ------------------------------------------------------------------------------
Status ThermalSettingsAck::finish_decode(size_t payload_size) const {
  return detail::settings_follow(payload_size, code, kSettingsMinSize);
}

// ---- 0x000110 ------------------------------------------------------------------------------
namespace {
// centre -+ size/2 must stay inside lo..hi. Integer halves, as the pod's C code would compute
// "half the width" (a 1-pixel rectangle on the edge is inside).
Status check_span(const char* size_field, const char* center_field, const char* axis, int64_t size,
                  int64_t center, int64_t lo, int64_t hi) {
  const int64_t first = center - size / 2;
  const int64_t last = center + size / 2;
  if (first >= lo && last <= hi) return Status::ok();
  return Status::fail(std::string("fields '") + size_field + "' and '" + center_field +
                      "' put the rectangle at " + axis + " " + std::to_string(first) + ".." +
                      std::to_string(last) + ", outside the measurable area " + axis + " " +
                      std::to_string(lo) + ".." + std::to_string(hi) + " (section 3.2.2.11)");
}
}  // namespace

Status ThermalAreaRequest::extra_checks() const {
  return first_failure(check_span("width_px", "center_x_px", "x", width_px, center_x_px,
                                  kThermalMeasurableXMin, kThermalMeasurableXMax),
                       check_span("height_px", "center_y_px", "y", height_px, center_y_px,
                                  kThermalMeasurableYMin, kThermalMeasurableYMax));
}

}  // namespace k40t::protocol
