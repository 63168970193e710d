// The pod's wall clock. It starts at a fixed instant (deterministic runs), is set by the host's
// time sync (0x00030E, docs/protocol/decisions.md#a8: ms since the epoch plus tz_minuteswest), and
// advances with the model's steps. Photo and video file names use its local time; the GPS request
// before a photo (0x000310) carries its UTC time of day.
#pragma once

#include <cstdint>
#include <string>

#include "k40t_driver/sim/events.h"

namespace k40t::sim {

constexpr int64_t kDefaultPodEpochMs = 1704067200000;  // 2024-01-01T00:00:00Z

class PodClock {
 public:
  explicit PodClock(int64_t start_utc_ms = kDefaultPodEpochMs) : base_utc_ms_(start_utc_ms) {}

  void advance(double dt_s) { since_base_s_ += dt_s; }
  void sync(int64_t utc_ms, int32_t minutes_west, int32_t dst_type);

  int64_t utc_ms() const;
  int64_t local_ms() const { return utc_ms() - int64_t{minutes_west_} * 60000; }
  bool synced() const { return synced_; }
  int32_t minutes_west() const { return minutes_west_; }
  int32_t dst_type() const { return dst_type_; }

  TimeOfDay utc_time_of_day() const;
  // "YYYYMMDD_HHMMSS_mmm" in local time, for file names.
  std::string local_stamp() const;

 private:
  int64_t base_utc_ms_;
  double since_base_s_ = 0;
  int32_t minutes_west_ = 0;
  int32_t dst_type_ = 0;
  bool synced_ = false;
};

// Proleptic Gregorian calendar date of a day count since 1970-01-01 (H. Hinnant's algorithm), so
// names do not depend on the machine's time zone.
struct CivilDate {
  int year = 1970;
  unsigned month = 1;
  unsigned day = 1;
};
CivilDate civil_from_days(int64_t days);

}  // namespace k40t::sim
