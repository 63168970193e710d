#include "k40t_driver/sim/pod_clock.h"

#include <cmath>
#include <cstdio>

namespace k40t::sim {

namespace {
constexpr int64_t kMsPerDay = 86400000;

int64_t floor_div(int64_t a, int64_t b) {
  return a / b - ((a % b != 0) && ((a < 0) != (b < 0)));
}
}  // namespace

CivilDate civil_from_days(int64_t days) {
  days += 719468;
  const int64_t era = floor_div(days, 146097);
  const int64_t doe = days - era * 146097;
  const int64_t yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const int64_t doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const int64_t mp = (5 * doy + 2) / 153;
  CivilDate date;
  date.day = static_cast<unsigned>(doy - (153 * mp + 2) / 5 + 1);
  date.month = static_cast<unsigned>(mp < 10 ? mp + 3 : mp - 9);
  date.year = static_cast<int>(yoe + era * 400 + (date.month <= 2 ? 1 : 0));
  return date;
}

void PodClock::sync(int64_t utc_ms, int32_t minutes_west, int32_t dst_type) {
  base_utc_ms_ = utc_ms;
  since_base_s_ = 0;
  minutes_west_ = minutes_west;
  dst_type_ = dst_type;
  synced_ = true;
}

int64_t PodClock::utc_ms() const {
  return base_utc_ms_ + std::llround(since_base_s_ * 1000.0);
}

TimeOfDay PodClock::utc_time_of_day() const {
  const int64_t ms = utc_ms() - floor_div(utc_ms(), kMsPerDay) * kMsPerDay;
  TimeOfDay t;
  t.hour = static_cast<uint8_t>(ms / 3600000);
  t.minute = static_cast<uint8_t>(ms / 60000 % 60);
  t.second = static_cast<uint8_t>(ms / 1000 % 60);
  t.millisecond = static_cast<uint16_t>(ms % 1000);
  return t;
}

std::string PodClock::local_stamp() const {
  const int64_t local = local_ms();
  const int64_t day = floor_div(local, kMsPerDay);
  const int64_t ms = local - day * kMsPerDay;
  const CivilDate date = civil_from_days(day);
  char text[32];
  std::snprintf(text, sizeof text, "%04d%02u%02u_%02d%02d%02d_%03d", date.year, date.month,
                date.day, static_cast<int>(ms / 3600000), static_cast<int>(ms / 60000 % 60),
                static_cast<int>(ms / 1000 % 60), static_cast<int>(ms % 1000));
  return text;
}

}  // namespace k40t::sim
