// `k40t monitor`'s output, shared by the link monitor (cmd_monitor.cpp) and the ROS build's
// topic monitor (tools/k40t_topic_monitor/): one human line per frame on stdout.
#pragma once

#include <cstdint>
#include <ctime>
#include <mutex>
#include <string>

#include "k40t_driver/protocol/ack_order_setting.h"
#include "k40t_driver/protocol/codec_options.h"
#include "k40t_driver/protocol/frame.h"

namespace k40t::tool {

// "13:04:05.123" (local time) of a wall-clock instant.
std::string time_of_day_text(const timespec& when);
// The same for now.
std::string wall_clock();

// Prints one line per frame and counts the frames whose payload did not decode.
class FramePrinter {
 public:
  // `ack_order`: the link's ACK byte order (the Dispatcher's; with --ack-byte-order auto it locks
  // on the pod's ACKs), or null to print with `codec` as given.
  explicit FramePrinter(const protocol::CodecOptions& codec,
                        const protocol::AckOrderSetting* ack_order = nullptr)
      : codec_(codec), ack_order_(ack_order) {}
  // "<when> <frame summary>"
  void print(const std::string& when, const protocol::FrameView& frame);
  uint64_t undecodable() const;

 private:
  const protocol::CodecOptions codec_;
  const protocol::AckOrderSetting* const ack_order_;
  mutable std::mutex mutex_;
  uint64_t undecodable_ = 0;
};

}  // namespace k40t::tool
