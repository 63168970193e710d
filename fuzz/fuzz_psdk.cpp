// libFuzzer target for the PSDK layer: arbitrary bytes through the streaming parser (in two
// chunks split where the input says), every frame opened (with and without an AES key) and
// decoded through the catalogue; and, since random bytes rarely pass two CRCs, the input's tail
// decoded directly as the DATA of the catalogue entry its first byte picks. Nothing may crash, hang
// or read out of bounds, and the parser's byte accounting must add up.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "k40t_driver/psdk/aes.h"
#include "k40t_driver/psdk/catalogue.h"
#include "k40t_driver/psdk/commands/header_variants.h"
#include "k40t_driver/psdk/parser.h"
#include "k40t_driver/psdk/sim/payload_reading.h"
#include "null_sink.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace k40t::psdk;
  static const Aes128Ecb cipher(AesKey{0x71, 0xc6, 0x82, 0xc7});
  FrameParser parser;
  k40t::fuzz::NullSink sink;
  size_t frame_bytes = 0;
  const auto on_frame = [&](const FrameView& frame) {
    frame_bytes += frame.size;
    for (const Aes128Ecb* key : {static_cast<const Aes128Ecb*>(nullptr), &cipher}) {
      const k40t::Result<Data> plain = open_data(frame, key);
      if (!plain) continue;
      const CommandInfo* info = find_command(frame.header.command, frame.header.packet_type);
      if (info != nullptr) (void)info->describe(plain->data(), plain->size, sink);
    }
  };
  if (size >= 1) {
    const auto& all = catalogue();
    (void)all[data[0] % all.size()].describe(data + 1, size - 1, sink);
  }
  // The layouts read by their length (header_variants.h) and the simulated adapter's own readers
  // (payload_reading.h), on the input as DATA.
  bool has_osdk = false;
  (void)decode_shoot_photo_mode(data, size);
  (void)decode_link_bandwidth(data, size, &has_osdk);
  if (size <= kMaxDataSize) {
    Data ack;
    for (size_t i = 0; i < size; ++i) ack.bytes[i] = data[i];
    ack.size = size;
    for (const sim::PayloadReading reading :
         {sim::PayloadReading::kDjiHeaders, sim::PayloadReading::kDocument}) {
      (void)sim::read_gimbal_state(ack, reading);
      (void)sim::read_sd_card(ack, reading);
      (void)sim::read_shoot_photo_mode(ack, reading);
    }
  }
  const size_t split = size > 0 ? data[0] % (size + 1) : 0;
  parser.feed(data, split, on_frame);
  parser.feed(data + split, size - split, on_frame);
  const ParserStats& s = parser.stats();
  // Every byte is in a good frame, discarded, or still buffered (less than one frame).
  if (s.bytes_received != size || frame_bytes + s.bytes_discarded > size ||
      size - frame_bytes - s.bytes_discarded > kMaxFrameSize) {
    std::abort();
  }
  return 0;
}
