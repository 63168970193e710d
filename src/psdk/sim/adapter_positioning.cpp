// The simulated adapter's answer to the payload's get-position command (3.7.1), read and written
// byte by byte from the document with the adapter's own reader and writer (adapter_table.h), not
// the payload's positioning structs. The points come from the simulated flight at the requested
// instants.
#include <cmath>
#include <cstring>

#include "k40t_driver/psdk/sim/adapter_simulator.h"
#include "k40t_driver/psdk/sim/adapter_table.h"

namespace k40t::psdk::sim {
namespace {

constexpr double kRadToDeg = 180.0 / M_PI;
// 3.7.1: the command is count, task index, base time (uint16 year, month, day, hour, minute,
// second: 7 bytes), then 6 bytes per point; the ACK is the code, the same 9 bytes, then 56 bytes
// per point.
constexpr size_t kRequestHeader = 9, kRequestPoint = 6, kAckHeader = 10, kAckPoint = 56;
// 3.7.1's solution "50: fixed point position solution".
constexpr uint8_t kFixedSolution = 50;

uint32_t le(const uint8_t* p, size_t n) {
  uint32_t v = 0;
  for (size_t i = 0; i < n; ++i) v |= static_cast<uint32_t>(p[i]) << (8 * i);
  return v;
}

int64_t unix_us_of(int64_t year, int64_t month, int64_t day, int64_t hour, int64_t minute,
                   int64_t second) {
  // Days from civil (Howard Hinnant), the inverse of utc_from_unix_us().
  const int64_t y = year - (month <= 2 ? 1 : 0);
  const int64_t era = (y >= 0 ? y : y - 399) / 400;
  const int64_t yoe = y - era * 400;
  const int64_t mp = month > 2 ? month - 3 : month + 9;
  const int64_t doy = (153 * mp + 2) / 5 + day - 1;
  const int64_t doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  const int64_t days = era * 146097 + doe - 719468;
  return ((days * 24 + hour) * 60 + minute) * 60000000LL + second * 1000000LL;
}

Data code_only(uint8_t code) {
  Data d;
  d.bytes[0] = code;
  d.size = 1;
  return d;
}

}  // namespace

std::optional<Data> AdapterSimulator::answer_get_position(const IncomingCommand& in) {
  const uint8_t* req = in.data.data();
  const size_t count = in.data.size >= 1 ? req[0] : 0;
  Data data = code_only(0x01);
  // 1..5 points, all present; an ACK of 5 points (290 bytes) does not fit DATA: refused (P18).
  const bool valid = count >= 1 && count <= 5 &&
                     in.data.size >= kRequestHeader + count * kRequestPoint &&
                     kAckHeader + count * kAckPoint <= kMaxDataSize;
  if (valid) {
    table::Request ack;
    ack.u8(0x00).u8(req[0]).u8(req[1]);                          // code, count, task index
    for (size_t i = 2; i < kRequestHeader; ++i) ack.u8(req[i]);  // the base time as sent
    const int64_t base_us = unix_us_of(le(req + 2, 2), req[4], req[5], req[6], req[7], req[8]);
    for (size_t i = 0; i < count; ++i) {
      const uint8_t* point = req + kRequestHeader + i * kRequestPoint;
      const uint32_t offset_us = le(point + 2, 4);
      const double t =
          static_cast<double>(base_us + offset_us - options_.flight.start_utc_us) / 1e6;
      const AirframeState s = flight_.state_at(t);
      ack.u16(static_cast<uint16_t>(le(point, 2)))  // event and target point index, as sent
          .u32(offset_us)
          .u8(kFixedSolution)
          .u8(0)  // reserved
          .i16(static_cast<int16_t>(std::lround(s.pitch_rad * kRadToDeg)))
          .i16(static_cast<int16_t>(std::lround(s.roll_rad * kRadToDeg)))
          .i16(static_cast<int16_t>(std::lround(s.yaw_rad * kRadToDeg)))
          .i16(0)  // offsets from the RTK antenna, N, E, D (mm): none in the simulation
          .i16(0)
          .i16(0)
          .f64(s.longitude_deg)
          .f64(s.latitude_deg)
          .f64(s.altitude_msl_m)
          .f32(0.02f)  // standard deviations of longitude, latitude, height
          .f32(0.02f)
          .f32(0.03f);
    }
    const std::vector<uint8_t>& bytes = ack.bytes();
    std::memcpy(data.bytes.data(), bytes.data(), bytes.size());
    data.size = bytes.size();
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (valid) ++stats_.positions_answered;
    if (roll(protocol_faults_.drop_ack_rate)) {
      ++stats_.acks_dropped;
      return std::nullopt;
    }
    if (protocol_faults_.delay_ack_ms > 0 && roll(protocol_faults_.delay_ack_rate)) {
      ++stats_.acks_delayed;
      const auto delay =
          std::chrono::microseconds(static_cast<int64_t>(protocol_faults_.delay_ack_ms * 1000.0));
      delayed_.push_back({std::chrono::steady_clock::now() + delay, in.header, data});
      return std::nullopt;
    }
  }
  return data;
}

}  // namespace k40t::psdk::sim
