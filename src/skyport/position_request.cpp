#include "k40t_driver/skyport/position_request.h"

#include <ctime>

namespace k40t::driver::skyport {

using namespace psdk;

namespace {
constexpr int64_t kNsPerS = 1'000'000'000, kNsPerUs = 1000;

std::string seconds_text(int64_t ns) {
  return std::to_string(static_cast<double>(ns) / kNsPerS);
}

}  // namespace

Result<GetPosition> plan_position_request(int64_t base_ns, const std::vector<uint32_t>& offsets_us,
                                          std::optional<int64_t> newest_sync_ns,
                                          uint16_t first_event_index) {
  if (offsets_us.empty() || offsets_us.size() > 4)
    return Status::fail("time_offsets_us: 1..4 points, got " + std::to_string(offsets_us.size()));
  if (base_ns < 0) return Status::fail("base_time before 1970");
  if (!newest_sync_ns)
    return Status::fail("no UTC time push from the adapter yet: nothing to ask positions against");
  const int64_t whole_ns = base_ns / kNsPerS * kNsPerS;
  const int64_t fraction_us = (base_ns - whole_ns) / kNsPerUs;
  GetPosition request;
  const std::time_t seconds = static_cast<std::time_t>(whole_ns / kNsPerS);
  std::tm tm{};
  gmtime_r(&seconds, &tm);
  request.base_time =
      DateTime{static_cast<uint16_t>(tm.tm_year + 1900), static_cast<uint8_t>(tm.tm_mon + 1),
               static_cast<uint8_t>(tm.tm_mday),         static_cast<uint8_t>(tm.tm_hour),
               static_cast<uint8_t>(tm.tm_min),          static_cast<uint8_t>(tm.tm_sec)};
  request.count = static_cast<uint8_t>(offsets_us.size());
  for (size_t i = 0; i < offsets_us.size(); ++i) {
    const int64_t offset_us = static_cast<int64_t>(offsets_us[i]) + fraction_us;
    if (offset_us > kMaxTimeOffsetUs)
      return Status::fail("time_offsets_us[" + std::to_string(i) +
                          "]: " + std::to_string(offsets_us[i]) +
                          " us plus the base time's fraction (" + std::to_string(fraction_us) +
                          " us) exceeds 3.7.1's " + std::to_string(kMaxTimeOffsetUs) + " us");
    const int64_t at_ns = whole_ns + offset_us * kNsPerUs;
    if (at_ns > *newest_sync_ns || at_ns < *newest_sync_ns - kPositionWindowNs)
      return Status::fail("point " + std::to_string(i) + " at " + seconds_text(at_ns) +
                          " s is outside the 2 s before the newest synchronised time " +
                          seconds_text(*newest_sync_ns) + " s (3.7.1)");
    request.points[i].time_offset_us = static_cast<uint32_t>(offset_us);
    request.points[i].event.event_index =
        static_cast<uint16_t>((first_event_index + i) % kEventIndexCount);
  }
  const Status valid = validate(request);
  if (!valid) return valid;
  return request;
}

int64_t unix_seconds(const DateTime& t) {
  std::tm tm{};
  tm.tm_year = t.year - 1900;
  tm.tm_mon = t.month - 1;
  tm.tm_mday = t.day;
  tm.tm_hour = t.hour;
  tm.tm_min = t.minute;
  tm.tm_sec = t.second;
  return static_cast<int64_t>(timegm(&tm));
}

int64_t position_time_ns(const GetPosition& request, uint32_t time_offset_us) {
  return unix_seconds(request.base_time) * kNsPerS +
         static_cast<int64_t>(time_offset_us) * kNsPerUs;
}

std::vector<std::optional<TargetPosition>> match_positions(const GetPosition& request,
                                                           const GetPositionAck& ack) {
  std::vector<std::optional<TargetPosition>> out(request.count);
  for (size_t i = 0; i < request.count && i < request.points.size(); ++i) {
    for (size_t j = 0; j < ack.count && j < ack.points.size(); ++j) {
      if (ack.points[j].event.event_index == request.points[i].event.event_index) {
        out[i] = ack.points[j];
        break;
      }
    }
  }
  return out;
}

}  // namespace k40t::driver::skyport
