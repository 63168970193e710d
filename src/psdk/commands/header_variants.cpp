#include "k40t_driver/psdk/commands/header_variants.h"

#include <array>
#include <cstring>

namespace k40t::psdk {

namespace {
// The SD card state's flags, and each one's bit in the two layouts (-1: absent).
struct SdBit {
  bool SdCardState::*flag;
  int document;
  int headers;
};
constexpr std::array<SdBit, 9> kSdBits{{{&SdCardState::inserted, 0, 0},
                                        {&SdCardState::initializing, 1, 2},
                                        {&SdCardState::read_only, 2, 3},
                                        {&SdCardState::formatted, 3, -1},
                                        {&SdCardState::formatting, 4, 4},
                                        {&SdCardState::full, 5, 5},
                                        {&SdCardState::verified, 6, 1},
                                        {&SdCardState::invalid_format, 7, 6},
                                        {&SdCardState::has_error, 8, 7}}};

int bit_of(const SdBit& b, PsdkLayout layout) {
  return layout == PsdkLayout::kDocument ? b.document : b.headers;
}

// A shoot photo mode copied between the two interval widths (the caller checks that it fits).
template <class From, class To>
void copy_shoot_photo_mode(const BasicShootPhotoMode<From>& from, BasicShootPhotoMode<To>& to) {
  to.type = from.type;
  to.burst_count = from.burst_count;
  to.interval_count = from.interval_count;
  to.interval_s = static_cast<To>(from.interval_s);
}
}  // namespace

const char* to_string(PsdkLayout layout) {
  return layout == PsdkLayout::kDocument ? "document" : "dji_headers";
}

bool parse_psdk_layout(const std::string& text, PsdkLayout& out) {
  if (text == "dji_headers") {
    out = PsdkLayout::kDjiHeaders;
    return true;
  }
  if (text == "document") {
    out = PsdkLayout::kDocument;
    return true;
  }
  return false;
}

uint8_t gimbal_state_mode_code(GimbalMode mode, PsdkLayout layout) {
  if (layout == PsdkLayout::kDjiHeaders) return static_cast<uint8_t>(mode);  // one enum
  return static_cast<uint8_t>(to_state_mode(mode));                          // 3.5.1's own
}

uint16_t sd_card_state_word(const SdCardState& state, PsdkLayout layout) {
  uint16_t word = 0;
  for (const SdBit& b : kSdBits) {
    const int bit = bit_of(b, layout);
    if (bit >= 0 && state.*(b.flag)) word = static_cast<uint16_t>(word | (1u << bit));
  }
  return word;
}

SdCardState sd_card_state_from_word(uint16_t word, PsdkLayout layout) {
  SdCardState state;
  for (const SdBit& b : kSdBits) {
    const int bit = bit_of(b, layout);
    state.*(b.flag) = bit >= 0 && (word >> bit & 1u) != 0;
  }
  return state;
}

SdCardInfoAck sd_card_ack_for(const SdCardInfoAck& ack, PsdkLayout layout) {
  SdCardInfoAck out = ack;
  out.state = sd_card_state_from_word(sd_card_state_word(ack.state, layout), PsdkLayout::kDocument);
  return out;
}

Result<ShootPhotoModeWide> decode_shoot_photo_mode(const uint8_t* data, size_t size) {
  if (size >= min_body_size<ShootPhotoModeWideAck>()) {
    ShootPhotoModeWide mode;
    ByteReader r(data, size);
    ShootPhotoModeWide::layout(mode, LayoutReader(r));
    if (r.ok()) return mode;
  }
  const Result<SetShootPhotoMode> narrow = decode_data<SetShootPhotoMode>(data, size);
  if (!narrow) return Result<ShootPhotoModeWide>::fail(narrow.error());
  ShootPhotoModeWide mode;
  copy_shoot_photo_mode(*narrow, mode);
  return mode;
}

Result<Data> encode_shoot_photo_mode_ack(const ShootPhotoModeWide& mode, PsdkLayout layout) {
  if (layout == PsdkLayout::kDjiHeaders) {
    ShootPhotoModeWideAck ack;
    static_cast<ShootPhotoModeWide&>(ack) = mode;
    return encode_data(ack);
  }
  if (mode.interval_s > 255)
    return Result<Data>::fail("interval " + std::to_string(mode.interval_s) +
                              " s does not fit the document's uint8");
  ShootPhotoModeAck ack;
  copy_shoot_photo_mode(mode, ack);
  return encode_data(ack);
}

Result<LinkBandwidthPush> decode_link_bandwidth(const uint8_t* data, size_t size,
                                                bool* has_osdk_fields) {
  const size_t full = min_body_size<LinkBandwidthPush>();
  if (size >= full) {
    if (has_osdk_fields) *has_osdk_fields = true;
    return decode_data<LinkBandwidthPush>(data, size);
  }
  if (size < kLinkBandwidthShortSize)
    return Result<LinkBandwidthPush>::fail(
        describe_size_error(LinkBandwidthPush::kName, size, kLinkBandwidthShortSize));
  // 33 bytes: the fields up to the network data rate; the OSDK ones read as zero.
  std::array<uint8_t, 64> padded{};
  std::memcpy(padded.data(), data, kLinkBandwidthShortSize);
  if (has_osdk_fields) *has_osdk_fields = false;
  return decode_data<LinkBandwidthPush>(padded.data(), full);
}

}  // namespace k40t::psdk
