// Access units into a playable file without re-encoding: GStreamer's parser and muxer
// (appsrc ! h264parse|h265parse ! mp4mux|matroskamux ! filesink). `k40t bag --video` writes a
// recorded passthrough topic with it. The file starts at the first key frame (what comes before
// cannot be decoded); presentation times are the messages' stamps relative to that frame.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "k40t_driver/protocol/result.h"
#include "k40t_driver/video/video_codec.h"

namespace k40t::video {

enum class Container { kMp4, kMatroska };

// From the file name: .mp4 / .m4v -> MP4, .mkv -> Matroska; anything else is an error.
Result<Container> container_for(const std::string& path);

class ContainerWriter {
 public:
  static Result<std::unique_ptr<ContainerWriter>> open(const std::string& path, Codec codec);
  ~ContainerWriter();  // without finish(): the file is left unfinished and removed
  ContainerWriter(const ContainerWriter&) = delete;
  ContainerWriter& operator=(const ContainerWriter&) = delete;

  // Queues one access unit stamped `stamp_ns` (any epoch; non-increasing stamps are nudged 1 ms
  // past the previous). Units before the first key frame are skipped: false.
  Result<bool> write(const uint8_t* data, size_t size, bool key_frame, int64_t stamp_ns);
  // Ends the stream and waits until the muxer has written the file (index, duration).
  Status finish();
  uint64_t written() const { return written_; }

  struct Impl;

 private:
  explicit ContainerWriter(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
  uint64_t written_ = 0;
};

}  // namespace k40t::video
