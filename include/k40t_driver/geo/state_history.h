// A bounded history of the vehicle's inputs (fix, attitude, optional velocity), each kept with its
// own stamps, so that the pod's GPS request (0x000310), which asks for the position at the time a
// photo was taken, is answered with the state at that time rather than the latest one. At 15 m/s
// the difference between the two is 3 m per 200 ms of lag.
//
// Lookups interpolate linearly between the two samples around the requested time (latitude,
// longitude and height; attitude angles along the shorter way round; velocity). A time outside
// the history gets the nearest sample, flagged `in_history = false`, so the caller can count it.
// ROS-free; stamps are nanoseconds of whatever clock the caller uses (ROS time in the driver).
#pragma once

#include <cstdint>
#include <deque>
#include <optional>

namespace k40t::geo {

struct PositionSample {
  double latitude_deg = 0;
  double longitude_deg = 0;
  double height_ellipsoid_m = 0;  // above the WGS 84 ellipsoid
};

// Aviation convention: heading clockwise from north, nose-up pitch and right-wing-down roll
// positive, degrees.
struct AttitudeSample {
  double heading_deg = 0;
  double pitch_deg = 0;
  double roll_deg = 0;
};

struct VelocitySample {  // m/s in the local east-north-up frame
  double east = 0;
  double north = 0;
  double up = 0;
};

template <class T>
struct Lookup {
  T value;
  bool in_history = true;  // false: the nearest sample of a history that does not span the time
  double gap_s = 0;        // distance from the requested time to the nearest sample
};

struct HistoryLimits {
  double span_s = 10.0;       // samples older than the newest minus this are dropped
  size_t max_samples = 2000;  // per input, whatever their rate
};

class StateHistory {
 public:
  explicit StateHistory(HistoryLimits limits = {}) : limits_(limits) {}

  // Samples normally arrive in time order; an older one is inserted at its place, one older
  // than the span is ignored.
  void add_position(int64_t stamp_ns, const PositionSample& sample);
  void add_attitude(int64_t stamp_ns, const AttitudeSample& sample);
  void add_velocity(int64_t stamp_ns, const VelocitySample& sample);
  void clear();

  std::optional<Lookup<PositionSample>> position_at(int64_t stamp_ns) const;
  std::optional<Lookup<AttitudeSample>> attitude_at(int64_t stamp_ns) const;
  // The velocity input when there is one; otherwise the derivative of the positions around that
  // time (none with fewer than two positions).
  std::optional<Lookup<VelocitySample>> velocity_at(int64_t stamp_ns) const;

  bool has_velocity_input() const { return !velocities_.empty(); }

 private:
  template <class T>
  struct Timed {
    int64_t stamp_ns;
    T value;
  };
  template <class T>
  void add(std::deque<Timed<T>>& series, int64_t stamp_ns, const T& value);
  template <class T, class Blend>
  static std::optional<Lookup<T>> at(const std::deque<Timed<T>>& series, int64_t stamp_ns,
                                     Blend blend);
  std::optional<Lookup<VelocitySample>> velocity_from_positions(int64_t stamp_ns) const;

  HistoryLimits limits_;
  std::deque<Timed<PositionSample>> positions_;
  std::deque<Timed<AttitudeSample>> attitudes_;
  std::deque<Timed<VelocitySample>> velocities_;
};

// The Unix time (ms) of a UTC time of day (ms since midnight) on the day that puts it nearest to
// `now_unix_ms`: the pod's 0x000310 carries hh:mm:ss.ms only, and a request just after midnight
// about a photo just before it belongs to the day before.
int64_t unix_ms_of_time_of_day(int64_t time_of_day_ms, int64_t now_unix_ms);

}  // namespace k40t::geo
