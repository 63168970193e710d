#include "k40t_driver/protocol/messages/flight_controller.h"

#include "camera_codec.h"

namespace k40t::protocol {

using camera_codec::check_time_of_day;

namespace {

constexpr double kDegE7 = 1e7;                  // int32 degrees x1e7
constexpr double kInt32MilliMax = 2147483.647;  // int32 x1000
constexpr double kInt16DeciMin = -3276.8;       // int16 x10
constexpr double kInt16DeciMax = 3276.7;
constexpr double kUint16CentiMax = 655.35;  // uint16 x100
constexpr double kInt16CentiMin = -327.68;  // int16 x100
constexpr double kInt16CentiMax = 327.67;

Status check_position(double longitude_deg, double latitude_deg) {
  return first_failure(check_range("longitude_deg", longitude_deg, -180.0, 180.0, "deg"),
                       check_range("latitude_deg", latitude_deg, -90.0, 90.0, "deg"));
}

// The attitudes are int16 x100: yaw cannot reach 360, so the range is -180..180.
Status check_attitude(double yaw_deg, double roll_deg, double pitch_deg) {
  return first_failure(check_range("yaw_deg", yaw_deg, -180.0, 180.0, "deg"),
                       check_range("roll_deg", roll_deg, -180.0, 180.0, "deg"),
                       check_range("pitch_deg", pitch_deg, -90.0, 90.0, "deg"));
}

Status check_milli_heights(double relative_height_m, double altitude_m) {
  return first_failure(
      check_range("relative_height_m", relative_height_m, -kInt32MilliMax, kInt32MilliMax, "m"),
      check_range("altitude_m", altitude_m, -kInt32MilliMax, kInt32MilliMax, "m"));
}

// 0x000320 and its ACK: int32 longitude/latitude deg x1e7, relative height and altitude m x1000,
// low byte first.
void put_position(ByteWriter& w, double longitude_deg, double latitude_deg,
                  double relative_height_m, double altitude_m) {
  w.i32(to_wire<int32_t>(longitude_deg, kDegE7));
  w.i32(to_wire<int32_t>(latitude_deg, kDegE7));
  w.i32(to_wire<int32_t>(relative_height_m, 1000));
  w.i32(to_wire<int32_t>(altitude_m, 1000));
}

void get_position(ByteReader& r, double& longitude_deg, double& latitude_deg,
                  double& relative_height_m, double& altitude_m) {
  longitude_deg = r.i32() / kDegE7;
  latitude_deg = r.i32() / kDegE7;
  relative_height_m = r.i32() / 1000.0;
  altitude_m = r.i32() / 1000.0;
}

}  // namespace

// ---- 0x000310 ------------------------------------------------------------------------------
Status CameraGpsRequest::validate() const {
  return check_time_of_day(hour, minute, second, millisecond);
}

void CameraGpsRequest::encode(ByteWriter& w, const CodecOptions&) const {
  w.u8(lens_enabled ? 1 : 0);
  for (uint8_t v : {hour, minute, second}) w.u8(v);
  w.u16(millisecond);
}

Status CameraGpsRequest::decode(ByteReader& r, const CodecOptions&) {
  lens_enabled = r.u8() != 0;
  for (uint8_t* v : {&hour, &minute, &second}) *v = r.u8();
  millisecond = r.u16();
  return Status::ok();
}

// ---- ACK 0x010310 --------------------------------------------------------------------------
CameraGpsAck CameraGpsAck::answering(const CameraGpsRequest& request) {
  CameraGpsAck ack;
  ack.hour = request.hour;
  ack.minute = request.minute;
  ack.second = request.second;
  ack.millisecond = request.millisecond;
  return ack;
}

Status CameraGpsAck::validate() const {
  return first_failure(
      check_time_of_day(hour, minute, second, millisecond),
      check_position(longitude_deg, latitude_deg),
      check_range("relative_height_m", relative_height_m, kInt16DeciMin, kInt16DeciMax, "m"),
      check_range("altitude_m", altitude_m, kInt16DeciMin, kInt16DeciMax, "m"),
      check_attitude(yaw_deg, roll_deg, pitch_deg));
}

void CameraGpsAck::encode(ByteWriter& w, const CodecOptions& o) const {
  const ByteOrder order = o.ack_byte_order;
  w.u16(static_cast<uint16_t>(code), order);
  for (uint8_t v : {hour, minute, second}) w.u8(v);
  w.u16(millisecond, order);
  w.i32(to_wire<int32_t>(longitude_deg, kDegE7), order);
  w.i32(to_wire<int32_t>(latitude_deg, kDegE7), order);
  w.i16(to_wire<int16_t>(relative_height_m, 10), order);
  w.i16(to_wire<int16_t>(altitude_m, 10), order);
  for (double deg : {yaw_deg, roll_deg, pitch_deg}) w.i16(to_wire<int16_t>(deg, 100), order);
}

Status CameraGpsAck::decode(ByteReader& r, const CodecOptions& o) {
  const ByteOrder order = o.ack_byte_order;
  code = static_cast<ResponseCode>(r.u16(order));
  if (r.remaining() == 0) return Status::ok();  // a refusal: code only
  for (uint8_t* v : {&hour, &minute, &second}) *v = r.u8();
  millisecond = r.u16(order);
  longitude_deg = r.i32(order) / kDegE7;
  latitude_deg = r.i32(order) / kDegE7;
  relative_height_m = r.i16(order) / 10.0;
  altitude_m = r.i16(order) / 10.0;
  for (double* deg : {&yaw_deg, &roll_deg, &pitch_deg}) *deg = r.i16(order) / 100.0;
  return Status::ok();
}

// ---- 0x000320 ------------------------------------------------------------------------------
Status TargetGpsRequest::validate() const {
  return first_failure(
      camera_codec::check_int("mount_mask", mount_mask, 1, 0xFF), check_enum("fix", fix),
      check_position(longitude_deg, latitude_deg),
      check_milli_heights(relative_height_m, altitude_m),
      check_attitude(yaw_deg, roll_deg, pitch_deg),
      check_range("airspeed_m_s", airspeed_m_s, 0.0, kUint16CentiMax, "m/s"),
      check_range("ground_speed_m_s", ground_speed_m_s, 0.0, kUint16CentiMax, "m/s"),
      check_range("heading_deg", heading_deg, 0.0, 360.0, "deg"),
      check_range("throttle_percent", throttle_percent, 0.0, 100.0, "%"),
      check_range("climb_rate_m_s", climb_rate_m_s, kInt16CentiMin, kInt16CentiMax, "m/s"));
}

void TargetGpsRequest::encode(ByteWriter& w, const CodecOptions&) const {
  w.u8(mount_mask);
  camera_codec::put_code(w, fix);
  w.u64(utc_time_ms);
  put_position(w, longitude_deg, latitude_deg, relative_height_m, altitude_m);
  for (double deg : {yaw_deg, roll_deg, pitch_deg}) w.i16(to_wire<int16_t>(deg, 100));
  for (double v : {airspeed_m_s, ground_speed_m_s, heading_deg, throttle_percent}) {
    w.u16(to_wire<uint16_t>(v, 100));
  }
  w.i16(to_wire<int16_t>(climb_rate_m_s, 100));
}

Status TargetGpsRequest::decode(ByteReader& r, const CodecOptions&) {
  mount_mask = r.u8();
  fix = camera_codec::get_code<GpsFixStatus>(r);
  utc_time_ms = r.u64();
  get_position(r, longitude_deg, latitude_deg, relative_height_m, altitude_m);
  for (double* deg : {&yaw_deg, &roll_deg, &pitch_deg}) *deg = r.i16() / 100.0;
  for (double* v : {&airspeed_m_s, &ground_speed_m_s, &heading_deg, &throttle_percent}) {
    *v = r.u16() / 100.0;
  }
  climb_rate_m_s = r.i16() / 100.0;
  return Status::ok();
}

// ---- ACK 0x010320 --------------------------------------------------------------------------
Status TargetGpsAck::validate() const {
  return first_failure(check_position(longitude_deg, latitude_deg),
                       check_milli_heights(relative_height_m, altitude_m));
}

void TargetGpsAck::encode(ByteWriter& w, const CodecOptions& o) const {
  w.u16(static_cast<uint16_t>(code), o.ack_byte_order);
  w.u8(mount_mask);
  w.u64(utc_time_ms);  // the data fields are low byte first whatever ack_byte_order says
  put_position(w, longitude_deg, latitude_deg, relative_height_m, altitude_m);
}

Status TargetGpsAck::decode(ByteReader& r, const CodecOptions& o) {
  code = static_cast<ResponseCode>(r.u16(o.ack_byte_order));
  if (r.remaining() == 0) return Status::ok();  // a refusal: code only
  mount_mask = r.u8();
  utc_time_ms = r.u64();
  get_position(r, longitude_deg, latitude_deg, relative_height_m, altitude_m);
  return Status::ok();
}

}  // namespace k40t::protocol
