// Streaming frame parser: feed it arbitrary chunks, it calls back once per valid frame.
//
// It searches for STX, checks LEN and the checksum; when a candidate fails it drops only that STX
// byte and rescans from the next byte, so a good frame hidden inside a bad one (a corrupted LEN
// that swallowed it, a false STX in garbage) is never lost. Small reads are copied into a fixed
// buffer and parsed there; large ones are parsed in the caller's chunk (FrameView then points
// into it), and only a frame cut by the chunking is copied. Nothing is allocated.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>

#include "k40t_driver/protocol/codec_options.h"
#include "k40t_driver/protocol/frame.h"

namespace k40t::protocol {

struct ParserStats {
  uint64_t bytes_received = 0;
  uint64_t frames_good = 0;
  uint64_t checksum_errors = 0;  // candidates with a plausible LEN whose checksum failed
  uint64_t length_errors = 0;    // candidates with LEN > 243
  uint64_t bytes_discarded = 0;  // bytes that ended up in no good frame
  uint64_t unknown_ids = 0;      // good frames whose id the catalogue does not know
  uint64_t sequence_gaps = 0;    // gap events, per source, with 8-bit wrap
  uint64_t frames_lost = 0;      // frames missing according to those gaps
  uint64_t frames_repeated = 0;  // a source's sequence number again (a duplicate, not 255 lost)
};

class FrameParser {
 public:
  using FrameCallback = std::function<void(const FrameView&)>;
  // Decides what counts as an unknown id; by default the message catalogue.
  using KnownIdPredicate = bool (*)(MessageId);

  explicit FrameParser(CrcCoverage coverage = CrcCoverage::kAuto);

  void set_known_id_predicate(KnownIdPredicate predicate) {
    known_id_ = predicate;
    known_id_cache_.fill({});
  }

  // Parses `size` bytes; `on_frame` is called for each good frame, in order.
  void feed(const uint8_t* data, size_t size, const FrameCallback& on_frame) {
    // The usual case of small serial reads: a frame is arriving and this read does not complete
    // it, so its bytes are only appended. Inline, because with 1-byte reads the call itself would
    // cost more than the work.
    const size_t have = end_ - begin_;
    if (have != 0 && size < wanted_ - have && size <= kBufferSize - end_) {
      stats_.bytes_received += size;
      for (size_t i = 0; i < size; ++i) buffer_[end_ + i] = data[i];
      end_ += size;
      return;
    }
    feed_chunk(data, size, on_frame);
  }

  // Forget any partial frame (after a reconnect; its bytes count as discarded) and the per-source
  // sequence history.
  void reset();

  const ParserStats& stats() const { return stats_; }
  // Bytes received but not yet part of a good frame or discarded: the start of a frame still
  // arriving. bytes_received == good frame bytes + bytes_discarded + buffered_bytes().
  size_t buffered_bytes() const { return end_ - begin_; }
  // What the checksum coverage is now: the configured one, or in auto mode the locked one
  // (kAuto until kLockFrames consecutive frames agreed).
  CrcCoverage coverage() const { return locked_; }
  CrcCoverage configured_coverage() const { return configured_; }

  static constexpr int kLockFrames = 3;

 private:
  // Delivers the good frames of bytes[0, size) and counts the discarded bytes; returns how many
  // bytes it decided on. What follows is the start of a frame still arriving, which needs
  // wanted_ bytes in all.
  size_t parse(const uint8_t* bytes, size_t size, const FrameCallback& on_frame);
  // feed() for every read that may decide something.
  void feed_chunk(const uint8_t* data, size_t size, const FrameCallback& on_frame);
  bool checksum_matches(const uint8_t* frame, size_t size, CrcCoverage* matched);
  void note_coverage(CrcCoverage matched);
  void track_sequence(Address source, uint8_t sequence);
  bool is_unknown(MessageId id);

  // Reads up to kCopiedReadSize bytes are copied into buffer_ and parsed there (see feed_chunk());
  // larger ones are parsed where they are. buffer_ holds the start of a frame still arriving
  // (< kMaxFrameSize bytes) and the small reads appended after it; a few reads' worth of room
  // means it is compacted only once in several reads.
  static constexpr size_t kCopiedReadSize = 512;
  static constexpr size_t kBufferSize = 8 * kCopiedReadSize;
  static_assert(kBufferSize >= kMaxFrameSize + kCopiedReadSize);
  // The indices come before buffer_, not after it: placed kBufferSize (4096) bytes after
  // buffer_[0], their loads alias the stores into the first bytes of buffer_ (the same low 12
  // address bits, which the CPU's store-to-load check compares first), and with small reads most
  // frames start at buffer_[0]: measured, 16-byte reads were ~10% slower.
  size_t begin_ = 0;   // first undecided byte
  size_t end_ = 0;     // one past the last byte
  size_t wanted_ = 0;  // bytes the candidate at begin_ needs in all before it can be decided
  std::array<uint8_t, kBufferSize> buffer_{};

  CrcCoverage configured_;
  CrcCoverage locked_;
  CrcCoverage candidate_ = CrcCoverage::kAuto;
  int candidate_count_ = 0;
  KnownIdPredicate known_id_;
  // The catalogue lookup is a binary search, and a link carries a handful of distinct ids: the
  // answers are remembered (direct-mapped by id).
  struct KnownIdCacheEntry {
    MessageId id = ~MessageId{0};  // no id is 32 bits wide: an empty slot
    bool known = false;
  };
  std::array<KnownIdCacheEntry, 64> known_id_cache_{};  // 64: see is_unknown()'s hash

  // The last sequence number of each source (up to kMaxSources of them), in an open-addressed
  // table keyed by the source address: one probe per frame in the usual case.
  struct SourceSequence {
    uint16_t source = 0;  // system << 8 | component
    uint8_t last = 0;
    bool used = false;
  };
  static constexpr size_t kMaxSources = 16;
  std::array<SourceSequence, kMaxSources> sources_{};
  size_t source_count_ = 0;

  ParserStats stats_;
};

}  // namespace k40t::protocol
