#include "k40t_driver/psdk/sim/adapter_table.h"

#include <cstring>

#include "k40t_driver/psdk/command.h"

namespace k40t::psdk::sim::table {
namespace {

// 3.1.2 and 3.1.5: bytes 2:5 Uint32, 0xAABBCCDD = version AA.BB.CC.DD (little-endian: DD first).
std::vector<Field> version_fields() {
  return {{"debug", 1, Kind::kU8},
          {"modify", 2, Kind::kU8},
          {"minor", 3, Kind::kU8},
          {"major", 4, Kind::kU8}};
}

// One-bit flags in the byte at `offset`, bit 0 first, then the fields `after` them.
std::vector<Field> flags(uint8_t offset, std::initializer_list<const char*> names,
                         std::vector<Field> after = {}) {
  std::vector<Field> out;
  uint8_t bit = 0;
  for (const char* name : names) out.push_back({name, offset, Kind::kBit, bit++});
  out.insert(out.end(), after.begin(), after.end());
  return out;
}

uint32_t le(const Data& d, size_t at, size_t n) {
  uint32_t v = 0;
  for (size_t i = 0; i < n; ++i) v |= static_cast<uint32_t>(d.bytes[at + i]) << (8 * i);
  return v;
}

}  // namespace

const std::vector<AckEntry>& acks() {
  using K = Kind;
  static const std::vector<AckEntry> all = {
      {0x01, 0x02, "get_psdk_version", "3.1.2", 5, version_fields()},
      {0x01, 0x03, "link_handshake", "3.1.3", 2, {}},  // 2:(N+1): the command's bytes, N >= 1
      {0x01,
       0x04,
       "get_product_info",
       "3.1.4",
       113,
       {{"product_name", 1, K::kText, 32},
        {"product_id", 33, K::kText, 16},
        {"developer_account", 49, K::kText, 64}}},
      {0x01, 0x05, "get_skyport_version", "3.1.5", 5, version_fields()},
      {0x01, 0x06, "get_product_alias", "3.1.6", 33, {{"alias", 1, K::kText, 32}}},
      // 3.3.3: the battery push's ACK, byte 2 = power-off preparation complete.
      {0x03, 0x03, "battery_info_push", "3.3.3", 2, {{"power_off_ready", 1, K::kU8}}},
      {0x04, 0x01, "set_camera_work_mode", "3.4.1", 1, {}},
      {0x04, 0x02, "get_camera_work_mode", "3.4.2", 2, {{"mode", 1, K::kU8}}},  // 0 photo, 1 video
      {0x04, 0x03, "shoot_photo", "3.4.3", 1, {}},
      {0x04, 0x04, "get_shoot_photo_state", "3.4.4", 4,
       flags(1, {"single", "interval", "burst", "storing"}, {{"countdown_s", 2, K::kU16}})},
      {0x04, 0x05, "set_shoot_photo_mode", "3.4.5", 1, {}},
      {0x04, 0x07, "record_video", "3.4.7", 1, {}},
      {0x04,
       0x08,
       "get_record_state",
       "3.4.8",
       4,
       {{"recording", 1, K::kU8}, {"duration_s", 2, K::kU16}}},
      {0x04, 0x20, "set_metering_mode", "3.4.11", 1, {}},
      {0x04, 0x21, "get_metering_mode", "3.4.12", 2, {{"mode", 1, K::kU8}}},  // 0 centre, 1 average
      {0x04, 0x30, "set_focus_mode", "3.4.15", 1, {}},
      {0x04, 0x31, "get_focus_mode", "3.4.16", 2, {{"mode", 1, K::kU8}}},  // 0 manual, 1 auto
      {0x04, 0x34, "set_digital_zoom_factor", "3.4.19", 1, {}},
      {0x04,
       0x36,
       "get_optical_zoom_spec",
       "3.4.21",
       7,
       {{"max_mm", 1, K::kU16, 0, 0.1},
        {"min_mm", 3, K::kU16, 0, 0.1},
        {"step_mm", 5, K::kU16, 0, 0.1}}},
      {0x04, 0x37, "set_optical_zoom_focal_length", "3.4.22", 1, {}},
      // "1:2" counted from the return code in 3.4.23: the focal length follows it (P13).
      {0x04,
       0x38,
       "get_optical_zoom_focal_length",
       "3.4.23",
       3,
       {{"focal_mm", 1, K::kU16, 0, 0.1}}},
      {0x04, 0x39, "get_optical_zoom_factor", "3.4.24", 5, {{"factor", 1, K::kF32}}},
      {0x04, 0x40, "start_continuous_zoom", "3.4.25", 1, {}},
      {0x04, 0x41, "stop_continuous_zoom", "3.4.26", 1, {}},
      {0x04, 0xFF, "get_camera_capability", "3.4.33", 2,
       flags(1, {"camera_commands", "optical_zoom", "digital_zoom", "focus", "metering"})},
      {0x05, 0x02, "set_gimbal_mode", "3.5.2", 1, {}},
      {0x05, 0x03, "gimbal_return_head", "3.5.3", 1, {}},
      {0x05, 0x04, "control_gimbal_speed", "3.5.4", 1, {}},
      {0x05, 0x05, "control_gimbal_angle", "3.5.5", 1, {}},
      {0x05, 0x07, "calibrate_gimbal", "3.5.7", 1, {}},
      {0x05,
       0x08,
       "get_calibration_progress",
       "3.5.8",
       3,
       {{"percent", 1, K::kU8}, {"status", 2, K::kU8}}},  // 0 complete, 1 processing, 2 failed
      {0x05,
       0x09,
       "get_gimbal_additional_status",
       "3.5.9",
       13,
       {{"pitch_deg_s", 1, K::kF32, 0, 0.1},
        {"roll_deg_s", 5, K::kF32, 0, 0.1},
        {"yaw_deg_s", 9, K::kF32, 0, 0.1}}},
      {0x05, 0xFF, "get_gimbal_capability", "3.5.10", 2, {{"supported", 1, K::kU8}}},
  };
  return all;
}

const AckEntry* find_ack(CommandKey key) {
  for (const AckEntry& e : acks()) {
    if (e.set == key.set && e.id == key.id) return &e;
  }
  return nullptr;
}

double Reading::number(const std::string& name) const {
  const auto it = numbers.find(name);
  return it == numbers.end() ? 0.0 : it->second;
}

std::string Reading::text(const std::string& name) const {
  const auto it = texts.find(name);
  return it == texts.end() ? std::string() : it->second;
}

Result<Reading> read(CommandKey key, const Data& ack) {
  const AckEntry* entry = find_ack(key);
  if (entry == nullptr) return Status::fail("the adapter's table has no ACK for this command");
  const std::string name = entry->name;
  if (ack.size == 0) return Status::fail(name + ": empty ACK");
  if (ack.bytes[0] != 0x00)
    return Status::fail(name + ": payload answered " + ack_code_text(ack.bytes[0]));
  if (ack.size < entry->size)
    return Status::fail(name + ": " + std::to_string(ack.size) + " bytes, " + entry->section +
                        " has " + std::to_string(entry->size));
  Reading out;
  for (const Field& f : entry->fields) {
    double value = 0;
    switch (f.kind) {
      case Kind::kU8:
        value = ack.bytes[f.offset];
        break;
      case Kind::kU16:
        value = le(ack, f.offset, 2);
        break;
      case Kind::kI16:
        value = static_cast<int16_t>(le(ack, f.offset, 2));
        break;
      case Kind::kU32:
        value = le(ack, f.offset, 4);
        break;
      case Kind::kF32: {
        const uint32_t bits = le(ack, f.offset, 4);
        float real = 0;
        std::memcpy(&real, &bits, sizeof real);
        value = real;
        break;
      }
      case Kind::kBit:
        value = (ack.bytes[f.offset] >> f.extra) & 1u;
        break;
      case Kind::kText: {
        const char* start = reinterpret_cast<const char*>(ack.bytes.data() + f.offset);
        out.texts[f.name] = std::string(start, strnlen(start, f.extra));
        continue;
      }
    }
    out.numbers[f.name] = value * f.scale;
  }
  return out;
}

Request& Request::u8(uint8_t value) {
  bytes_.push_back(value);
  return *this;
}

Request& Request::u16(uint16_t value) {
  bytes_.push_back(static_cast<uint8_t>(value & 0xFF));
  bytes_.push_back(static_cast<uint8_t>(value >> 8));
  return *this;
}

Request& Request::i16(int16_t value) {
  return u16(static_cast<uint16_t>(value));
}

Request& Request::u32(uint32_t value) {
  for (int i = 0; i < 4; ++i) bytes_.push_back(static_cast<uint8_t>(value >> (8 * i)));
  return *this;
}

Request& Request::f64(double value) {
  uint64_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  for (int i = 0; i < 8; ++i) bytes_.push_back(static_cast<uint8_t>(bits >> (8 * i)));
  return *this;
}

Request& Request::f32(float value) {
  uint32_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  for (int i = 0; i < 4; ++i) bytes_.push_back(static_cast<uint8_t>(bits >> (8 * i)));
  return *this;
}

Request& Request::text(const std::string& value) {
  bytes_.insert(bytes_.end(), value.begin(), value.end());
  return *this;
}

}  // namespace k40t::psdk::sim::table
