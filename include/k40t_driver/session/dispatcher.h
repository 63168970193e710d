// Frames in, typed messages out, with no I/O: the parser plus routing by message id. The Session
// owns one for its link; replay mode (frames from a bag) and the tools use one directly.
#pragma once

#include <functional>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include "k40t_driver/protocol/codec_options.h"
#include "k40t_driver/protocol/frame.h"
#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/parser.h"

namespace k40t::session {

class Dispatcher {
 public:
  using FrameHandler = std::function<void(const protocol::FrameView&)>;
  using DecodeErrorHandler = std::function<void(const protocol::FrameView&, const std::string&)>;

  Dispatcher(protocol::CrcCoverage coverage, const protocol::CodecOptions& codec);

  // Register before feeding. Msg::kId selects the frames; a frame whose payload does not decode
  // goes to the decode-error handler instead (and is counted).
  template <class Msg>
  void on(std::function<void(const Msg&, const protocol::FrameView&)> handler);
  // Every good frame, before typed routing (raw/rx topics, monitors, ACK matching).
  void on_frame(FrameHandler handler);
  void on_decode_error(DecodeErrorHandler handler);

  // Bytes as they arrive from a link, in any chunking.
  void feed(const uint8_t* data, size_t size);
  // One whole frame, e.g. from a bag; it goes through the parser too, so counters stay honest.
  void feed_frame(const uint8_t* frame, size_t size) { feed(frame, size); }

  const protocol::ParserStats& parser_stats() const;
  uint64_t decode_errors() const;
  protocol::CrcCoverage locked_coverage() const;
  void reset();  // after a reconnect: drop partial frames and sequence history
};

}  // namespace k40t::session
