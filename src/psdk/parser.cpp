#include "k40t_driver/psdk/parser.h"

#include <algorithm>
#include <cstring>

#include "k40t_driver/psdk/crc.h"

namespace k40t::psdk {

void FrameParser::reset() {
  begin_ = end_ = 0;
  have_sequence_ = false;
}

void FrameParser::feed(const uint8_t* data, size_t size, const FrameCallback& on_frame) {
  stats_.bytes_received += size;
  while (size > 0) {
    // Compact only when the free tail is too small for the next chunk: at most one memmove of a
    // partial frame (< 272 bytes) per buffer's worth of input.
    if (kBufferSize - end_ < std::min(size, kBufferSize / 2) && begin_ > 0) {
      std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
      end_ -= begin_;
      begin_ = 0;
    }
    const size_t n = std::min(size, kBufferSize - end_);
    std::memcpy(buffer_.data() + end_, data, n);
    end_ += n;
    data += n;
    size -= n;
    parse_buffer(on_frame);
  }
}

void FrameParser::reject_candidate(uint64_t& counter) {
  ++counter;
  ++stats_.bytes_discarded;
  ++begin_;  // not a frame after all: rescan from the byte after this SOF
}

void FrameParser::parse_buffer(const FrameCallback& on_frame) {
  while (begin_ < end_) {
    if (buffer_[begin_] != kSof) {
      const auto* found =
          static_cast<const uint8_t*>(std::memchr(buffer_.data() + begin_, kSof, end_ - begin_));
      const size_t next = found ? static_cast<size_t>(found - buffer_.data()) : end_;
      stats_.bytes_discarded += next - begin_;
      begin_ = next;
      continue;
    }
    const uint8_t* f = buffer_.data() + begin_;
    const size_t available = end_ - begin_;
    if (available < 3) return;  // need the length/version field
    const size_t length = frame_length_field(f);
    if (length < kMinFrameSize || length > kMaxFrameSize) {
      reject_candidate(stats_.length_errors);
      continue;
    }
    if (frame_version_field(f) != kProtocolVersion) {
      reject_candidate(stats_.version_errors);
      continue;
    }
    if (available < kHeaderSize) return;
    // Check the header before waiting for the rest, so a false SOF with a large length does not
    // hold back the frames behind it.
    if (crc16(f, kHeaderCrcOffset) != static_cast<uint16_t>(f[10] | (f[11] << 8))) {
      reject_candidate(stats_.header_crc_errors);
      continue;
    }
    if (available < length) return;
    uint32_t received = 0;
    for (int i = 0; i < 4; ++i) received |= static_cast<uint32_t>(f[length - 4 + i]) << (8 * i);
    if (crc32(f, length - kCrc32Size) != received) {
      reject_candidate(stats_.frame_crc_errors);
      continue;
    }

    FrameView view;
    view.header = parse_header(f);
    view.data = f + kHeaderSize;
    view.data_size = length - kFrameOverhead;
    view.bytes = f;
    view.size = length;
    ++stats_.frames_good;
    if (view.header.packet_type == PacketType::kCommand) track_sequence(view.header);
    begin_ += length;
    on_frame(view);
  }
  begin_ = end_ = 0;
}

void FrameParser::track_sequence(const FrameHeader& header) {
  // ACKs echo our own sequence numbers, so only the other side's commands show its counter.
  if (have_sequence_) {
    const auto expected = static_cast<uint16_t>(last_sequence_ + 1);
    if (header.sequence != expected) {
      ++stats_.sequence_gaps;
      // A step backwards (more than half the range) is the other side restarting, not loss.
      const auto missing = static_cast<uint16_t>(header.sequence - expected);
      if (missing < 0x8000) stats_.commands_lost += missing;
    }
  }
  have_sequence_ = true;
  last_sequence_ = header.sequence;
}

}  // namespace k40t::psdk
