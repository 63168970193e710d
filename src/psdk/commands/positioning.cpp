#include "k40t_driver/psdk/commands/positioning.h"

#include "k40t_driver/psdk/indexed_sink.h"

namespace k40t::psdk {

const char* to_string(PositionSolution solution) {
  switch (solution) {
    case PositionSolution::kNotAvailable:
      return "not_available";
    case PositionSolution::kSinglePoint:
      return "single_point";
    case PositionSolution::kFloat:
      return "float";
    case PositionSolution::kFixed:
      return "fixed";
  }
  return nullptr;
}

namespace {

template <class Point>
Status validate_points(uint8_t count, size_t max_count, const DateTime& base_time,
                       const std::array<Point, kMaxTargetPoints>& points) {
  Status s = first_failure(check_int("count", count, 1, static_cast<int64_t>(max_count)),
                           base_time.validate());
  for (size_t i = 0; s && i < count; ++i) {
    s = validate(points[i]);  // the layout's checks (bit widths, enums) and the point's own
  }
  return s;
}

template <class Point>
void encode_points(ByteWriter& w, uint8_t count, uint8_t task_index, const DateTime& base_time,
                   const std::array<Point, kMaxTargetPoints>& points) {
  w.u8(count);
  w.u8(task_index);
  DateTime::layout(base_time, LayoutWriter(w));
  for (size_t i = 0; i < count; ++i) Point::layout(points[i], LayoutWriter(w));
}

template <class Point>
Status decode_points(ByteReader& r, uint8_t& count, uint8_t& task_index, DateTime& base_time,
                     std::array<Point, kMaxTargetPoints>& points) {
  count = r.u8();
  task_index = r.u8();
  DateTime::layout(base_time, LayoutReader(r));
  if (count > kMaxTargetPoints) {
    return Status::fail("target point count " + std::to_string(count) + " is more than 5");
  }
  for (size_t i = 0; i < count; ++i) Point::layout(points[i], LayoutReader(r));
  return Status::ok();
}

template <class Point>
void describe_points(FieldSink& sink, uint8_t count, uint8_t task_index, const DateTime& base_time,
                     const std::array<Point, kMaxTargetPoints>& points) {
  sink.unsigned_integer("count", count);
  sink.unsigned_integer("task_index", task_index);
  DateTime::layout(base_time, LayoutSink(sink));
  for (size_t i = 0; i < count && i < kMaxTargetPoints; ++i) {
    IndexedSink point(sink, "point", i + 1);
    Point::layout(points[i], LayoutSink(point));
  }
}

// DATA holds 256 bytes: the return code, the 9-byte header and 56 bytes per point.
constexpr size_t kMaxPositionsInAck =
    (kMaxDataSize - 1 - kPositionHeaderSize) / kTargetPositionSize;

}  // namespace

Status PositionRequestPoint::validate() const {
  return check_int("time_offset_us", time_offset_us, 0, kMaxTimeOffsetUs, "us");
}

Status TargetPosition::validate() const {
  return first_failure(check_int("time_offset_us", time_offset_us, 0, kMaxTimeOffsetUs, "us"),
                       check_int("uav_pitch_deg", uav_pitch_deg, -180, 180, "deg"),
                       check_int("uav_roll_deg", uav_roll_deg, -180, 180, "deg"),
                       check_int("uav_yaw_deg", uav_yaw_deg, -180, 180, "deg"),
                       check_real("longitude_deg", longitude_deg, -180.0, 180.0, "deg"),
                       check_real("latitude_deg", latitude_deg, -90.0, 90.0, "deg"));
}

Status GetPosition::validate() const {
  return validate_points(count, kMaxTargetPoints, base_time, points);
}
void GetPosition::encode(ByteWriter& w) const {
  encode_points(w, count, task_index, base_time, points);
}
Status GetPosition::decode(ByteReader& r) {
  return decode_points(r, count, task_index, base_time, points);
}
void GetPosition::describe(FieldSink& sink) const {
  describe_points(sink, count, task_index, base_time, points);
}

Status GetPositionAck::validate() const {
  if (count > kMaxPositionsInAck && count <= kMaxTargetPoints) {
    return Status::fail("field 'count' must be 1..4: " + std::to_string(count) +
                        " positions need " +
                        std::to_string(1 + kPositionHeaderSize + count * kTargetPositionSize) +
                        " bytes of DATA, more than 256");
  }
  return validate_points(count, kMaxTargetPoints, base_time, points);
}
void GetPositionAck::encode(ByteWriter& w) const {
  encode_points(w, count, task_index, base_time, points);
}
Status GetPositionAck::decode(ByteReader& r) {
  return decode_points(r, count, task_index, base_time, points);
}
void GetPositionAck::describe(FieldSink& sink) const {
  describe_points(sink, count, task_index, base_time, points);
}

}  // namespace k40t::psdk
