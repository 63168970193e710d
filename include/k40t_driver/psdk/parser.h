// Streaming PSDK frame parser: feed it arbitrary chunks, it calls back once per valid frame.
//
// It searches for SOF 0xAA, checks the length (16..272) and version (0) fields, then the header
// CRC16, then the frame CRC32. When a candidate fails any check it drops only that SOF byte and
// rescans from the next byte, so a good frame hidden inside a bad one (a false SOF in garbage, a
// corrupted length that swallowed the next frame) is never lost. Memory is a fixed buffer;
// steady state allocates nothing. Decryption is not its job (see open_data()).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>

#include "k40t_driver/psdk/frame.h"

namespace k40t::psdk {

struct ParserStats {
  uint64_t bytes_received = 0;
  uint64_t frames_good = 0;
  uint64_t length_errors = 0;      // SOF candidates with a length outside 16..272
  uint64_t version_errors = 0;     // SOF candidates with a version other than 0
  uint64_t header_crc_errors = 0;  // CRC16 over bytes 0..9 did not match
  uint64_t frame_crc_errors = 0;   // header fine, CRC32 over the frame did not match
  uint64_t bytes_discarded = 0;    // bytes that ended up in no good frame
  uint64_t sequence_gaps = 0;      // gaps in the other side's command sequence (16-bit wrap)
  uint64_t commands_lost = 0;      // commands missing according to those gaps
};

class FrameParser {
 public:
  using FrameCallback = std::function<void(const FrameView&)>;

  // Parses `size` bytes; `on_frame` is called for each good frame, in order.
  void feed(const uint8_t* data, size_t size, const FrameCallback& on_frame);

  // Forget any partial frame (after a reconnect) and the sequence history.
  void reset();

  const ParserStats& stats() const { return stats_; }

 private:
  void parse_buffer(const FrameCallback& on_frame);
  void reject_candidate(uint64_t& counter);
  void track_sequence(const FrameHeader& header);

  static constexpr size_t kBufferSize = 4096;
  std::array<uint8_t, kBufferSize> buffer_{};
  size_t begin_ = 0;  // first unparsed byte
  size_t end_ = 0;    // one past the last byte

  bool have_sequence_ = false;
  uint16_t last_sequence_ = 0;
  ParserStats stats_;
};

}  // namespace k40t::psdk
