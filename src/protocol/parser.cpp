#include "k40t_driver/protocol/parser.h"

#include <algorithm>
#include <cstring>

#include "k40t_driver/protocol/catalogue.h"
#include "k40t_driver/protocol/crc.h"

namespace k40t::protocol {

FrameParser::FrameParser(CrcCoverage coverage)
    : configured_(coverage), locked_(coverage), known_id_(&is_known_id) {}

void FrameParser::reset() {
  stats_.bytes_discarded += end_ - begin_;
  begin_ = end_ = 0;
  source_count_ = 0;
}

void FrameParser::feed(const uint8_t* data, size_t size, const FrameCallback& on_frame) {
  stats_.bytes_received += size;
  while (size > 0) {
    // Compact only when the free tail is too small for the next chunk: at most one memmove of a
    // partial frame (< 255 bytes) per buffer's worth of input.
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

void FrameParser::parse_buffer(const FrameCallback& on_frame) {
  while (begin_ < end_) {
    // Hunt for STX; everything before it is discarded.
    if (buffer_[begin_] != kStx) {
      const uint8_t* found =
          static_cast<const uint8_t*>(std::memchr(buffer_.data() + begin_, kStx, end_ - begin_));
      const size_t next = found ? static_cast<size_t>(found - buffer_.data()) : end_;
      stats_.bytes_discarded += next - begin_;
      begin_ = next;
      continue;
    }
    if (end_ - begin_ < 2) return;  // need LEN
    const size_t payload_size = buffer_[begin_ + 1];
    if (payload_size > kMaxPayloadSize) {
      ++stats_.length_errors;
      ++stats_.bytes_discarded;
      ++begin_;  // not a real STX: rescan from the next byte
      continue;
    }
    const size_t frame_size = kFrameOverhead + payload_size;
    if (end_ - begin_ < frame_size) return;  // wait for the rest

    const uint8_t* f = buffer_.data() + begin_;
    CrcCoverage matched = CrcCoverage::kHeaderExcluded;
    if (!checksum_matches(f, frame_size, &matched)) {
      ++stats_.checksum_errors;
      ++stats_.bytes_discarded;
      ++begin_;  // the frame may hide a good one: rescan from the byte after this STX
      continue;
    }
    note_coverage(matched);

    FrameView view;
    view.header.destination = {f[2], f[3]};
    view.header.sequence = f[4];
    view.header.source = {f[5], f[6]};
    view.header.message_id = static_cast<MessageId>(f[7]) | (static_cast<MessageId>(f[8]) << 8) |
                             (static_cast<MessageId>(f[9]) << 16);
    view.payload = f + kHeaderSize;
    view.payload_size = payload_size;
    view.bytes = f;
    view.size = frame_size;
    view.coverage = matched;

    ++stats_.frames_good;
    if (known_id_ != nullptr && !known_id_(view.header.message_id)) ++stats_.unknown_ids;
    track_sequence(view.header);
    begin_ += frame_size;
    on_frame(view);
  }
  begin_ = end_ = 0;
}

bool FrameParser::checksum_matches(const uint8_t* frame, size_t size, CrcCoverage* matched) {
  const uint16_t received = static_cast<uint16_t>(frame[size - 2] | (frame[size - 1] << 8));
  // Unlocked auto mode tries both coverages; once locked (or configured) only one is computed.
  const CrcCoverage mode = locked_;
  if (mode != CrcCoverage::kWholeFrame) {
    if (frame_checksum(frame, size, CrcCoverage::kHeaderExcluded) == received) {
      *matched = CrcCoverage::kHeaderExcluded;
      return true;
    }
  }
  if (mode != CrcCoverage::kHeaderExcluded) {
    if (frame_checksum(frame, size, CrcCoverage::kWholeFrame) == received) {
      *matched = CrcCoverage::kWholeFrame;
      return true;
    }
  }
  return false;
}

void FrameParser::note_coverage(CrcCoverage matched) {
  if (configured_ != CrcCoverage::kAuto || locked_ != CrcCoverage::kAuto) return;
  if (matched == candidate_) {
    if (++candidate_count_ >= kLockFrames) locked_ = matched;
  } else {
    candidate_ = matched;
    candidate_count_ = 1;
  }
}

void FrameParser::track_sequence(const FrameHeader& header) {
  const uint16_t source =
      static_cast<uint16_t>(header.source.system << 8 | header.source.component);
  for (size_t i = 0; i < source_count_; ++i) {
    SourceSequence& s = sources_[i];
    if (s.source != source) continue;
    const uint8_t expected = static_cast<uint8_t>(s.last + 1);
    if (header.sequence != expected) {
      ++stats_.sequence_gaps;
      stats_.frames_lost += static_cast<uint8_t>(header.sequence - expected);
    }
    s.last = header.sequence;
    return;
  }
  if (source_count_ < kMaxSources) sources_[source_count_++] = {source, header.sequence};
}

}  // namespace k40t::protocol
