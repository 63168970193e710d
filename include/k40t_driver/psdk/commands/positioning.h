// Positioning command set 0x07 (protocol document section 3.7): the payload asks the adapter
// where target points were at given instants (events), based on the synchronised UTC time (the
// instants must lie within the 2 s before the newest synchronised timestamp; at most 5 Hz).
#pragma once

#include "k40t_driver/psdk/commands/data_push.h"
#include "k40t_driver/psdk/commands/declare.h"

namespace k40t::psdk {

constexpr size_t kMaxTargetPoints = 5;
constexpr uint32_t kMaxTimeOffsetUs = 2000000;
constexpr size_t kPositionRequestPointSize = 6;
constexpr size_t kTargetPositionSize = 56;
constexpr size_t kPositionHeaderSize = 9;  // count, task index, base date and time

enum class PositionSolution : uint8_t {
  kNotAvailable = 0,
  kSinglePoint = 16,
  kFloat = 34,
  kFixed = 50
};
const char* to_string(PositionSolution solution);

// Bits 0..12 event index, bits 13..15 target point index.
struct PositionEvent {
  K40T_PSDK_FIELDS((uint16_t, event_index, wire::bits(0, 13)),         // 0..8191
                   (uint8_t, target_point_index, wire::bits(13, 3)));  // 0..7
};

struct PositionRequestPoint {
  K40T_PSDK_FIELDS((PositionEvent, event, wire::packed16),
                   (uint32_t, time_offset_us, wire::u32));  // after the base time, 0..2000000
  Status validate() const;
};

struct TargetPosition {
  K40T_PSDK_FIELDS((PositionEvent, event, wire::packed16), (uint32_t, time_offset_us, wire::u32),
                   (PositionSolution, solution, wire::u8, PositionSolution::kNotAvailable),
                   (reserved, wire::Reserved{1}),
                   (int16_t, uav_pitch_deg, wire::i16),  // -180..180, whole degrees on the wire
                   (int16_t, uav_roll_deg, wire::i16), (int16_t, uav_yaw_deg, wire::i16),
                   (int16_t, offset_north_mm, wire::i16),  // RTK main antenna -> target point, NED
                   (int16_t, offset_east_mm, wire::i16), (int16_t, offset_down_mm, wire::i16),
                   (double, longitude_deg, wire::f64), (double, latitude_deg, wire::f64),
                   (double, height_m, wire::f64),          // above sea level
                   (float, longitude_std_dev, wire::f32),  // the document gives no unit
                   (float, latitude_std_dev, wire::f32), (float, height_std_dev, wire::f32));
  Status validate() const;
};

// What 3.7.1's request and its ACK both carry: count, task index, base time, then `count`
// points (PositionRequestPoint in the request, TargetPosition in the ACK).
template <class Point, uint8_t kDefaultCount>
struct PositionList {
  uint8_t count = kDefaultCount;
  uint8_t task_index = 0;
  DateTime base_time;
  std::array<Point, kMaxTargetPoints> points{};

  K40T_PSDK_VARIABLE_LENGTH();  // validate(): count 1..5, the base time and each point
};

// 3.7.1 ACK: one position per requested point. At 56 bytes a point, DATA (256 bytes at most)
// holds 4 of them, although the document allows 5 (docs/psdk.md).
struct GetPositionAck : Reply<CommandSet::kPositioning, 0x01, Sender::kAdapter>,
                        PositionList<TargetPosition, 0> {
  K40T_PSDK_NAMED("get_position_ack", "3.7.1");
  static constexpr size_t kMinBodySize = kPositionHeaderSize;
  static constexpr size_t kMaxBodySize = kMaxDataSize - 1;
  Status validate() const;  // also: no more positions than DATA holds
};

// 3.7.1: 1..5 points. Encrypted by the payload (docs/psdk.md#frames).
struct GetPosition : Command<CommandSet::kPositioning, 0x01, Sender::kPayload, GetPositionAck>,
                     PositionList<PositionRequestPoint, 1> {
  K40T_PSDK_NAMED("get_position", "3.7.1");
  static constexpr size_t kMinBodySize = kPositionHeaderSize + kPositionRequestPointSize;
  static constexpr size_t kMaxBodySize =
      kPositionHeaderSize + kMaxTargetPoints * kPositionRequestPointSize;
};

}  // namespace k40t::psdk
