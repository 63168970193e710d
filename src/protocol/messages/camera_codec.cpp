#include "camera_codec.h"

#include <string>

namespace k40t::protocol::camera_codec {

Status check_one_of(const char* field, int64_t value, std::initializer_list<int64_t> allowed,
                    const char* unit) {
  std::string list;
  for (int64_t a : allowed) {
    if (a == value) return Status::ok();
    list += (list.empty() ? "" : ", ") + std::to_string(a);
  }
  if (unit != nullptr && *unit != '\0') list += std::string(" ") + unit;
  return Status::fail(std::string("field '") + field + "' must be one of " + list + ", got " +
                      std::to_string(value));
}

Status check_photo_settings(uint8_t time_lapse_interval_s, uint8_t burst_count) {
  return first_failure(
      check_one_of("time_lapse_interval_s", time_lapse_interval_s, {5, 7, 30, 60}, "s"),
      check_one_of("burst_count", burst_count, {3, 5}));
}

}  // namespace k40t::protocol::camera_codec
