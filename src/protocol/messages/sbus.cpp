#include "k40t_driver/protocol/messages/sbus.h"

#include <string>

namespace k40t::protocol {

// ---- 0x000500 -------------------------------------------------------------------------------
Status SbusRangeRequest::validate() const {
  Status ranges = first_failure(check_range("max_value", int64_t{max_value}, 0, kMaxSbusValue),
                                check_range("min_value", int64_t{min_value}, 0, kMaxSbusValue));
  if (ranges && min_value >= max_value) {
    return Status::fail("field 'min_value' must be less than max_value (" +
                        std::to_string(max_value) + "), got " + std::to_string(min_value));
  }
  return ranges;
}

void SbusRangeRequest::write_values(ByteWriter& w, ByteOrder order) const {
  w.u16(max_value, order);
  w.u16(min_value, order);
}

void SbusRangeRequest::read_values(ByteReader& r, ByteOrder order) {
  max_value = r.u16(order);
  min_value = r.u16(order);
}

void SbusRangeRequest::encode(ByteWriter& w, const CodecOptions&) const {
  write_values(w, ByteOrder::kLittle);
  w.zeros(1);
}

Status SbusRangeRequest::decode(ByteReader& r, const CodecOptions&) {
  read_values(r, ByteOrder::kLittle);
  return Status::ok();
}

// ---- 0x000501 -------------------------------------------------------------------------------
namespace {
// Field name and member, in wire order: one table for validation, encoding and decoding.
struct ChannelField {
  const char* name;
  int SbusChannelsRequest::*member;
};
constexpr ChannelField kChannelFields[SbusChannelsRequest::kChannelCount] = {
    {"stream_channel", &SbusChannelsRequest::stream_channel},
    {"zoom_channel", &SbusChannelsRequest::zoom_channel},
    {"photo_channel", &SbusChannelsRequest::photo_channel},
    {"record_channel", &SbusChannelsRequest::record_channel},
    {"pitch_channel", &SbusChannelsRequest::pitch_channel},
    {"yaw_channel", &SbusChannelsRequest::yaw_channel},
    {"centre_channel", &SbusChannelsRequest::centre_channel},
};
}  // namespace

Status SbusChannelsRequest::validate() const {
  for (const ChannelField& f : kChannelFields) {
    const Status s =
        check_range(f.name, int64_t{this->*f.member}, 1, kMaxChannel, "(channel number)");
    if (!s) return s;
  }
  return Status::ok();
}

void SbusChannelsRequest::write_channels(ByteWriter& w) const {
  for (const ChannelField& f : kChannelFields) w.u8(static_cast<uint8_t>(this->*f.member - 1));
}

void SbusChannelsRequest::read_channels(ByteReader& r) {
  for (const ChannelField& f : kChannelFields) this->*f.member = r.u8() + 1;
}

void SbusChannelsRequest::encode(ByteWriter& w, const CodecOptions&) const {
  write_channels(w);
  w.zeros(1);
}

Status SbusChannelsRequest::decode(ByteReader& r, const CodecOptions&) {
  read_channels(r);
  return Status::ok();
}

// ---- 0x010502 -------------------------------------------------------------------------------
void SbusConfigAck::encode(ByteWriter& w, const CodecOptions& o) const {
  w.u16(static_cast<uint16_t>(code), o.ack_byte_order);
  range.write_values(w, o.ack_byte_order);
  channels.write_channels(w);
  w.zeros(1);
}

Status SbusConfigAck::decode(ByteReader& r, const CodecOptions& o) {
  code = static_cast<ResponseCode>(r.u16(o.ack_byte_order));
  if (r.remaining() == 0) {  // a refusal: the code alone; report no configuration
    range.max_value = range.min_value = 0;
    channels = SbusChannelsRequest{0, 0, 0, 0, 0, 0, 0};
    return Status::ok();
  }
  range.read_values(r, o.ack_byte_order);
  channels.read_channels(r);
  return Status::ok();
}

}  // namespace k40t::protocol
