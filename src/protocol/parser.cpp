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
  wanted_ = 0;
  sources_.fill({});
  source_count_ = 0;
}

// The per-frame steps, defined before parse() so that they are inlined into it.
inline bool FrameParser::checksum_matches(const uint8_t* frame, size_t size, CrcCoverage* matched) {
  const uint16_t received = static_cast<uint16_t>(frame[size - 2] | (frame[size - 1] << 8));
  // Unlocked auto mode tries both coverages; once locked (or configured) only one is computed.
  const CrcCoverage mode = locked_;
  if (mode != CrcCoverage::kWholeFrame) {
    if (crc16(frame + 1, size - 1 - kChecksumSize) == received) {  // STX excluded
      *matched = CrcCoverage::kHeaderExcluded;
      return true;
    }
  }
  if (mode != CrcCoverage::kHeaderExcluded) {
    if (crc16(frame, size - kChecksumSize) == received) {
      *matched = CrcCoverage::kWholeFrame;
      return true;
    }
  }
  return false;
}

inline void FrameParser::note_coverage(CrcCoverage matched) {
  if (configured_ != CrcCoverage::kAuto || locked_ != CrcCoverage::kAuto) return;
  if (matched == candidate_) {
    if (++candidate_count_ >= kLockFrames) locked_ = matched;
  } else {
    candidate_ = matched;
    candidate_count_ = 1;
  }
}

inline bool FrameParser::is_unknown(MessageId id) {
  if (known_id_ == nullptr) return false;
  // Fibonacci hashing: the ids of one link (0x000001.., 0x0203xx, 0x0104xx) spread well.
  KnownIdCacheEntry& slot = known_id_cache_[(id * 2654435761u) >> 26];  // 64 slots
  if (slot.id != id) slot = {id, known_id_(id)};
  return !slot.known;
}

inline void FrameParser::track_sequence(Address source_address, uint8_t sequence) {
  const uint16_t source =
      static_cast<uint16_t>(source_address.system << 8 | source_address.component);
  size_t i = (source_address.system + source_address.component * 5u) % kMaxSources;
  for (size_t probe = 0; probe < kMaxSources; ++probe, i = (i + 1) % kMaxSources) {
    SourceSequence& s = sources_[i];
    if (!s.used) {  // a new source: its first frame starts its count
      s = {source, sequence, true};
      ++source_count_;
      return;
    }
    if (s.source != source) continue;
    const uint8_t expected = static_cast<uint8_t>(s.last + 1);
    if (sequence == s.last) {
      // A duplicated frame (a link that repeats, a sender retrying with the same number): counting
      // it as a gap would report 255 frames lost for one extra frame.
      ++stats_.frames_repeated;
    } else if (sequence != expected) {
      ++stats_.sequence_gaps;
      stats_.frames_lost += static_cast<uint8_t>(sequence - expected);
    }
    s.last = sequence;
    return;
  }
  // More than kMaxSources sources: the others are not tracked.
}

// A small read (a serial port's usual 1..64 bytes) is appended to buffer_ whole and parsed there
// in one pass: the frame cut by the previous read and the frames after it are decided together.
// Parsing the read where it is would mean two passes (top up and decide the cut frame in buffer_,
// then parse the rest of the read) and a copy of the new cut frame: at 64-byte reads, where nearly
// every read cuts a frame, that cost ~25% of the time. A candidate left over stays where it is and
// is moved to the front only when buffer_ is full.
// A large read is parsed where the caller has it: only the start of a frame still arriving is
// copied, into buffer_, and then topped up with just the bytes it needs to be decided.
void FrameParser::feed_chunk(const uint8_t* data, size_t size, const FrameCallback& on_frame) {
  stats_.bytes_received += size;
  if (size <= kCopiedReadSize) {
    if (kBufferSize - end_ < size) {  // the candidate left over is < kMaxFrameSize bytes
      std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
      end_ -= begin_;
      begin_ = 0;
    }
    const bool had_candidate = begin_ != end_;
    if (size < 16) {  // serial reads are often a few bytes: cheaper than a call to memcpy
      for (size_t i = 0; i < size; ++i) buffer_[end_ + i] = data[i];
    } else if (size <= 64) {  // two overlapping fixed-size copies, inline
      uint8_t* to = buffer_.data() + end_;
      if (size <= 32) {
        std::memcpy(to, data, 16);
        std::memcpy(to + size - 16, data + size - 16, 16);
      } else {
        std::memcpy(to, data, 32);
        std::memcpy(to + size - 32, data + size - 32, 32);
      }
    } else {
      std::memcpy(buffer_.data() + end_, data, size);
    }
    end_ += size;
    if (had_candidate && end_ - begin_ < wanted_) return;  // still incomplete
    begin_ += parse(buffer_.data() + begin_, end_ - begin_, on_frame);
    if (begin_ == end_) begin_ = end_ = 0;
    return;
  }
  while (size > 0) {
    if (begin_ == end_) {
      const size_t decided = parse(data, size, on_frame);
      const size_t rest = size - decided;  // an incomplete candidate: < kMaxFrameSize bytes
      std::memcpy(buffer_.data(), data + decided, rest);
      begin_ = 0;
      end_ = rest;
      return;
    }
    // The buffered candidate needs wanted_ bytes in all (2 for its LEN, then the whole frame).
    const size_t need = std::min(size, wanted_ - (end_ - begin_));
    if (kBufferSize - end_ < need) {
      std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
      end_ -= begin_;
      begin_ = 0;
    }
    if (need < 16) {  // serial reads are often a few bytes: cheaper than a call to memcpy
      for (size_t i = 0; i < need; ++i) buffer_[end_ + i] = data[i];
    } else {
      std::memcpy(buffer_.data() + end_, data, need);
    }
    end_ += need;
    data += need;
    size -= need;
    if (end_ - begin_ < wanted_) return;  // still incomplete, and no input left
    begin_ += parse(buffer_.data() + begin_, end_ - begin_, on_frame);
    if (begin_ == end_) begin_ = end_ = 0;
  }
}

size_t FrameParser::parse(const uint8_t* bytes, size_t size, const FrameCallback& on_frame) {
  size_t pos = 0;
  while (pos < size) {
    // Hunt for STX; everything before it is discarded.
    if (bytes[pos] != kStx) {
      size_t next = pos + 1;
      if (size - next < 16) {
        // A few bytes (a small read, just copied into buffer_): memchr's vector load over bytes
        // stored a moment ago waits for the stores to complete; a byte loop does not.
        while (next < size && bytes[next] != kStx) ++next;
      } else {
        const void* found = std::memchr(bytes + next, kStx, size - next);
        next = found ? static_cast<size_t>(static_cast<const uint8_t*>(found) - bytes) : size;
      }
      stats_.bytes_discarded += next - pos;
      pos = next;
      continue;
    }
    if (size - pos < 2) {  // need LEN
      wanted_ = 2;
      return pos;
    }
    const size_t payload_size = bytes[pos + 1];
    if (payload_size > kMaxPayloadSize) {
      ++stats_.length_errors;
      ++stats_.bytes_discarded;
      ++pos;  // not a real STX: rescan from the next byte
      continue;
    }
    const size_t frame_size = kFrameOverhead + payload_size;
    if (size - pos < frame_size) {  // wait for the rest
      wanted_ = frame_size;
      return pos;
    }

    const uint8_t* f = bytes + pos;
    CrcCoverage matched = CrcCoverage::kHeaderExcluded;
    if (!checksum_matches(f, frame_size, &matched)) {
      ++stats_.checksum_errors;
      ++stats_.bytes_discarded;
      ++pos;  // the frame may hide a good one: rescan from the byte after this STX
      continue;
    }
    if (locked_ == CrcCoverage::kAuto) note_coverage(matched);

    // Header fields go to the statistics from the frame bytes, not read back from `view` (which
    // has just been written byte by byte: reading two of those bytes as one word stalls store
    // forwarding; measured at a fifth of the parser's time).
    const Address source{f[5], f[6]};
    const uint8_t sequence = f[4];
    const MessageId id = static_cast<MessageId>(f[7]) | (static_cast<MessageId>(f[8]) << 8) |
                         (static_cast<MessageId>(f[9]) << 16);
    ++stats_.frames_good;
    if (is_unknown(id)) ++stats_.unknown_ids;
    track_sequence(source, sequence);

    FrameView view;
    view.header.destination = {f[2], f[3]};
    view.header.sequence = sequence;
    view.header.source = source;
    view.header.message_id = id;
    view.payload = f + kHeaderSize;
    view.payload_size = payload_size;
    view.bytes = f;
    view.size = frame_size;
    view.coverage = matched;
    pos += frame_size;
    on_frame(view);
  }
  return pos;
}

}  // namespace k40t::protocol
