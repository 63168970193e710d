// The simulated pod's RTSP server in the test's own process (sim/video/rtsp_stream_server.h) on
// a free port, showing an image mode the test can change.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <mutex>
#include <string>

#include "k40t_driver/sim/video/rtsp_stream_server.h"

namespace k40t::video::testing {

class Stream {
 public:
  explicit Stream(sim::video::ImageMode mode, int port = 0, int key_frame_interval = 10,
                  Codec codec = Codec::kH264) {
    snapshot_.image_mode = mode;
    sim::video::RtspServerOptions options;
    options.port = port;
    options.codec = codec;
    options.key_frame_interval = key_frame_interval;  // 10: a new client's picture within 1/3 s
    auto server = sim::video::RtspStreamServer::start(options, [this] {
      std::lock_guard<std::mutex> lock(mutex_);
      return snapshot_;
    });
    EXPECT_TRUE(server) << server.error();
    if (server) server_ = std::move(server.value());
  }
  std::string url() const { return server_ ? server_->url() : ""; }
  void set_mode(sim::video::ImageMode mode) {
    std::lock_guard<std::mutex> lock(mutex_);
    snapshot_.image_mode = mode;
  }
  void stop() { server_.reset(); }

 private:
  std::mutex mutex_;
  sim::video::VideoSnapshot snapshot_;
  std::unique_ptr<sim::video::RtspStreamServer> server_;
};

}  // namespace k40t::video::testing
