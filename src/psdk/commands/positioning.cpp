#include "k40t_driver/psdk/commands/positioning.h"

#include "k40t_driver/codec/enum_names.h"
#include "k40t_driver/psdk/indexed_sink.h"

namespace k40t::psdk {

const char* to_string(PositionSolution solution) {
  return name_in({{PositionSolution::kNotAvailable, "not_available"},
                  {PositionSolution::kSinglePoint, "single_point"},
                  {PositionSolution::kFloat, "float"},
                  {PositionSolution::kFixed, "fixed"}},
                 solution, nullptr);
}

namespace {

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

template <class Point, uint8_t kDefaultCount>
Status PositionList<Point, kDefaultCount>::validate() const {
  Status s = first_failure(check_int("count", count, 1, static_cast<int64_t>(kMaxTargetPoints)),
                           base_time.validate());
  for (size_t i = 0; s && i < count; ++i) {
    s = psdk::validate(points[i]);  // the layout's checks (bit widths, enums) and the point's own
  }
  return s;
}

template <class Point, uint8_t kDefaultCount>
void PositionList<Point, kDefaultCount>::encode(ByteWriter& w) const {
  w.u8(count);
  w.u8(task_index);
  DateTime::layout(base_time, LayoutWriter(w));
  for (size_t i = 0; i < count; ++i) Point::layout(points[i], LayoutWriter(w));
}

template <class Point, uint8_t kDefaultCount>
Status PositionList<Point, kDefaultCount>::decode(ByteReader& r) {
  count = r.u8();
  task_index = r.u8();
  DateTime::layout(base_time, LayoutReader(r));
  if (count > kMaxTargetPoints) {
    return Status::fail("target point count " + std::to_string(count) + " is more than 5");
  }
  for (size_t i = 0; i < count; ++i) Point::layout(points[i], LayoutReader(r));
  return Status::ok();
}

template <class Point, uint8_t kDefaultCount>
void PositionList<Point, kDefaultCount>::describe(FieldSink& sink) const {
  sink.unsigned_integer("count", count);
  sink.unsigned_integer("task_index", task_index);
  DateTime::layout(base_time, LayoutSink(sink));
  for (size_t i = 0; i < count && i < kMaxTargetPoints; ++i) {
    IndexedSink point(sink, "point", i + 1);
    Point::layout(points[i], LayoutSink(point));
  }
}

template struct PositionList<PositionRequestPoint, 1>;
template struct PositionList<TargetPosition, 0>;

Status GetPositionAck::validate() const {
  if (count > kMaxPositionsInAck && count <= kMaxTargetPoints) {
    return Status::fail("field 'count' must be 1..4: " + std::to_string(count) +
                        " positions need " +
                        std::to_string(1 + kPositionHeaderSize + count * kTargetPositionSize) +
                        " bytes of DATA, more than 256");
  }
  return PositionList::validate();
}

}  // namespace k40t::psdk
