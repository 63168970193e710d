#include "frame_printer.h"

#include <cstdio>

#include "frame_text.h"
#include "k40t_driver/protocol/catalogue.h"

namespace k40t::tool {

std::string time_of_day_text(const timespec& when) {
  tm local{};
  localtime_r(&when.tv_sec, &local);
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%02d:%02d:%02d.%03ld", local.tm_hour, local.tm_min,
                local.tm_sec, when.tv_nsec / 1000000);
  return buffer;
}

std::string wall_clock() {
  timespec now{};
  clock_gettime(CLOCK_REALTIME, &now);
  return time_of_day_text(now);
}

void FramePrinter::print(const std::string& when, const protocol::FrameView& frame) {
  bool decoded = false;
  const std::string line =
      frame_summary(frame, ack_order_ ? ack_order_->codec_with(codec_) : codec_, &decoded);
  std::lock_guard<std::mutex> lock(mutex_);
  if (!decoded && protocol::is_known_id(frame.header.message_id)) ++undecodable_;
  std::printf("%s %s\n", when.c_str(), line.c_str());
  std::fflush(stdout);
}

uint64_t FramePrinter::undecodable() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return undecodable_;
}

}  // namespace k40t::tool
