#include "k40t_driver/geo/state_history.h"

#include <algorithm>
#include <cmath>

#include "k40t_driver/geo/geodesy.h"

namespace k40t::geo {

namespace {

double lerp(double a, double b, double f) {
  return a + (b - a) * f;
}
// Angles (degrees) along the shorter way round, so 359 -> 1 passes through 0, not 180.
double lerp_angle(double a, double b, double f) {
  return a + std::remainder(b - a, 360.0) * f;
}

PositionSample blend(const PositionSample& a, const PositionSample& b, double f) {
  return {lerp(a.latitude_deg, b.latitude_deg, f), lerp_angle(a.longitude_deg, b.longitude_deg, f),
          lerp(a.height_ellipsoid_m, b.height_ellipsoid_m, f)};
}
AttitudeSample blend(const AttitudeSample& a, const AttitudeSample& b, double f) {
  const double heading = lerp_angle(a.heading_deg, b.heading_deg, f);
  return {std::fmod(heading + 360.0, 360.0), lerp_angle(a.pitch_deg, b.pitch_deg, f),
          lerp_angle(a.roll_deg, b.roll_deg, f)};
}
VelocitySample blend(const VelocitySample& a, const VelocitySample& b, double f) {
  return {lerp(a.east, b.east, f), lerp(a.north, b.north, f), lerp(a.up, b.up, f)};
}

constexpr int64_t kDayMs = 86400000;

}  // namespace

template <class T>
void StateHistory::add(std::deque<Timed<T>>& series, int64_t stamp_ns, const T& value) {
  const int64_t span_ns = static_cast<int64_t>(limits_.span_s * 1e9);
  if (!series.empty() && stamp_ns < series.back().stamp_ns - span_ns) return;
  auto place = std::upper_bound(series.begin(), series.end(), stamp_ns,
                                [](int64_t t, const Timed<T>& s) { return t < s.stamp_ns; });
  series.insert(place, Timed<T>{stamp_ns, value});
  const int64_t oldest = series.back().stamp_ns - span_ns;
  while (series.size() > 1 &&
         (series.front().stamp_ns < oldest || series.size() > limits_.max_samples))
    series.pop_front();
}

void StateHistory::add_position(int64_t stamp_ns, const PositionSample& sample) {
  add(positions_, stamp_ns, sample);
}
void StateHistory::add_attitude(int64_t stamp_ns, const AttitudeSample& sample) {
  add(attitudes_, stamp_ns, sample);
}
void StateHistory::add_velocity(int64_t stamp_ns, const VelocitySample& sample) {
  add(velocities_, stamp_ns, sample);
}
void StateHistory::clear() {
  positions_.clear();
  attitudes_.clear();
  velocities_.clear();
}

template <class T, class Blend>
std::optional<Lookup<T>> StateHistory::at(const std::deque<Timed<T>>& series, int64_t stamp_ns,
                                          Blend blend_fn) {
  if (series.empty()) return std::nullopt;
  const auto after = std::lower_bound(series.begin(), series.end(), stamp_ns,
                                      [](const Timed<T>& s, int64_t t) { return s.stamp_ns < t; });
  if (after == series.begin() || after == series.end()) {
    const Timed<T>& nearest = after == series.end() ? series.back() : series.front();
    const bool exact = nearest.stamp_ns == stamp_ns;
    return Lookup<T>{nearest.value, exact, std::abs(nearest.stamp_ns - stamp_ns) * 1e-9};
  }
  const Timed<T>& before = *(after - 1);
  const double f = static_cast<double>(stamp_ns - before.stamp_ns) /
                   static_cast<double>(after->stamp_ns - before.stamp_ns);
  const int64_t gap = std::min(stamp_ns - before.stamp_ns, after->stamp_ns - stamp_ns);
  return Lookup<T>{blend_fn(before.value, after->value, f), true, gap * 1e-9};
}

std::optional<Lookup<PositionSample>> StateHistory::position_at(int64_t stamp_ns) const {
  return at(positions_, stamp_ns, [](const PositionSample& a, const PositionSample& b, double f) {
    return blend(a, b, f);
  });
}

std::optional<Lookup<AttitudeSample>> StateHistory::attitude_at(int64_t stamp_ns) const {
  return at(attitudes_, stamp_ns, [](const AttitudeSample& a, const AttitudeSample& b, double f) {
    return blend(a, b, f);
  });
}

std::optional<Lookup<VelocitySample>> StateHistory::velocity_at(int64_t stamp_ns) const {
  if (!velocities_.empty()) {
    return at(
        velocities_, stamp_ns,
        [](const VelocitySample& a, const VelocitySample& b, double f) { return blend(a, b, f); });
  }
  return velocity_from_positions(stamp_ns);
}

// The displacement between the two positions around the time (or the last two), in the ENU
// frame of the first, over their time difference.
std::optional<Lookup<VelocitySample>> StateHistory::velocity_from_positions(
    int64_t stamp_ns) const {
  if (positions_.size() < 2) return std::nullopt;
  auto after =
      std::lower_bound(positions_.begin(), positions_.end(), stamp_ns,
                       [](const Timed<PositionSample>& s, int64_t t) { return s.stamp_ns < t; });
  const bool inside = after != positions_.begin() && after != positions_.end();
  if (after == positions_.begin()) ++after;
  if (after == positions_.end()) --after;
  const Timed<PositionSample>& a = *(after - 1);
  const Timed<PositionSample>& b = *after;
  const Result<LocalFrame> frame =
      LocalFrame::at({a.value.latitude_deg, a.value.longitude_deg, a.value.height_ellipsoid_m});
  if (!frame) return std::nullopt;
  const Enu d =
      frame->to_enu({b.value.latitude_deg, b.value.longitude_deg, b.value.height_ellipsoid_m});
  const double dt = (b.stamp_ns - a.stamp_ns) * 1e-9;
  if (dt <= 0) return std::nullopt;  // two fixes with one stamp
  const double gap =
      inside ? 0.0
             : std::min(std::abs(stamp_ns - a.stamp_ns), std::abs(stamp_ns - b.stamp_ns)) * 1e-9;
  return Lookup<VelocitySample>{{d.east / dt, d.north / dt, d.up / dt}, inside, gap};
}

int64_t unix_ms_of_time_of_day(int64_t time_of_day_ms, int64_t now_unix_ms) {
  const int64_t midnight = now_unix_ms - ((now_unix_ms % kDayMs) + kDayMs) % kDayMs;
  int64_t best = midnight + time_of_day_ms;
  for (int64_t candidate : {best - kDayMs, best + kDayMs}) {
    if (std::llabs(candidate - now_unix_ms) < std::llabs(best - now_unix_ms)) best = candidate;
  }
  return best;
}

}  // namespace k40t::geo
