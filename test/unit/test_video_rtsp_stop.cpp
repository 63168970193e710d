// Stopping the simulated RTSP server while its clients are busy: clients sending requests back to
// back (so the server is reading from them as it stops), and grabbers that have just hung up (so
// the server is tearing their session and the shared media down as it stops). The server must
// close every connection and be done with the media before its destructor returns: when clients
// were served on a thread of GStreamer's pool, a client read from a connection the stopping
// server had just closed (GLib-GIO critical "G_IS_POLLABLE_INPUT_STREAM", then a crash) or
// dropped the media after the server was destroyed (a destroyed mutex locked: abort).
#include <gtest/gtest.h>

#include <glib.h>
#include <gst/rtsp/rtsp.h>

#include <atomic>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "k40t_driver/sim/video/rtsp_stream_server.h"
#include "k40t_driver/video/frame_grabber.h"
#include "video_test_support.h"

namespace k40t::video {
namespace {

using namespace sim::video;  // RtspStreamServer, RtspServerOptions, VideoSnapshot
using std::chrono::seconds;
using testing::wait_until;

std::unique_ptr<RtspStreamServer> start_server() {
  RtspServerOptions options;
  options.port = 0;
  options.key_frame_interval = 10;  // a new client gets a picture within a third of a second
  auto server = RtspStreamServer::start(options, [] { return VideoSnapshot{}; });
  EXPECT_TRUE(server) << server.error();
  return server ? std::move(server.value()) : nullptr;
}

// Counts GLib criticals (failed g_return_if_fail checks) while it lives, and still prints them.
class CriticalCounter {
 public:
  CriticalCounter() { previous_ = g_log_set_default_handler(&CriticalCounter::handle, this); }
  ~CriticalCounter() { g_log_set_default_handler(previous_, nullptr); }
  int count() const { return count_; }

 private:
  static void handle(const gchar* domain, GLogLevelFlags level, const gchar* message,
                     gpointer self) {
    if (level & G_LOG_LEVEL_CRITICAL) ++static_cast<CriticalCounter*>(self)->count_;
    g_log_default_handler(domain, level, message, nullptr);
  }
  GLogFunc previous_ = nullptr;
  std::atomic<int> count_{0};
};

// An RTSP client that sends OPTIONS requests, a few at a time, until the connection fails.
class Talker {
 public:
  explicit Talker(const std::string& url) : thread_([this, url] { run(url); }) {}
  ~Talker() {
    done_ = true;
    thread_.join();
  }
  int answered() const { return answered_; }
  bool ended() const { return ended_; }

 private:
  void run(const std::string& url) {
    GstRTSPUrl* parsed = nullptr;
    GstRTSPConnection* connection = nullptr;
    constexpr gint64 kTimeoutUs = 2'000'000;
    if (gst_rtsp_url_parse(url.c_str(), &parsed) == GST_RTSP_OK &&
        gst_rtsp_connection_create(parsed, &connection) == GST_RTSP_OK &&
        gst_rtsp_connection_connect_usec(connection, kTimeoutUs) == GST_RTSP_OK) {
      for (int cseq = 1; !done_;) {
        constexpr int kBatch = 4;  // sent before reading the answers: the server stays busy
        bool ok = true;
        for (int i = 0; i < kBatch && ok; ++i, ++cseq) {
          GstRTSPMessage request = {};
          gst_rtsp_message_init_request(&request, GST_RTSP_OPTIONS, url.c_str());
          gst_rtsp_message_add_header(&request, GST_RTSP_HDR_CSEQ, std::to_string(cseq).c_str());
          ok = gst_rtsp_connection_send_usec(connection, &request, kTimeoutUs) == GST_RTSP_OK;
          gst_rtsp_message_unset(&request);
        }
        for (int i = 0; i < kBatch && ok; ++i) {
          GstRTSPMessage response = {};
          ok = gst_rtsp_connection_receive_usec(connection, &response, kTimeoutUs) == GST_RTSP_OK;
          gst_rtsp_message_unset(&response);
          if (ok) ++answered_;
        }
        if (!ok) break;
      }
    }
    if (connection) gst_rtsp_connection_free(connection);
    if (parsed) gst_rtsp_url_free(parsed);
    ended_ = true;
  }

  std::atomic<bool> done_{false};
  std::atomic<bool> ended_{false};
  std::atomic<int> answered_{0};
  std::thread thread_;
};

// Every talker is answered, then the server stops under them; each sees its connection end.
void stop_while_talking(std::unique_ptr<RtspStreamServer> server, int talkers) {
  ASSERT_TRUE(server);
  std::vector<std::unique_ptr<Talker>> clients;
  for (int i = 0; i < talkers; ++i) clients.push_back(std::make_unique<Talker>(server->url()));
  for (auto& client : clients) {
    ASSERT_TRUE(wait_until([&] { return client->answered() > 0 || client->ended(); }, seconds(5)));
    ASSERT_GT(client->answered(), 0) << "the server never answered OPTIONS";
  }
  server.reset();
  for (auto& client : clients) {
    EXPECT_TRUE(wait_until([&] { return client->ended(); }, seconds(3)))
        << "a client is still connected to the stopped server";
  }
}

TEST(VideoRtspServerStop, ClientsBusySendingRequestsAreClosedCleanly) {
  CriticalCounter criticals;
  for (int cycle = 0; cycle < 20; ++cycle) {
    SCOPED_TRACE("cycle " + std::to_string(cycle));
    stop_while_talking(start_server(), 3);
    if (::testing::Test::HasFatalFailure()) return;
  }
  EXPECT_EQ(criticals.count(), 0);
}

// The end of every streaming test: the grabber hangs up (the server tears its session and the
// media down) and the server stops at once, with another client still talking.
TEST(VideoRtspServerStop, AServerStoppedJustAfterAGrabberHungUpStopsCleanly) {
  CriticalCounter criticals;
  for (int cycle = 0; cycle < 4; ++cycle) {
    SCOPED_TRACE("cycle " + std::to_string(cycle));
    auto server = start_server();
    ASSERT_TRUE(server);
    CaptureOptions capture;
    capture.url = server->url();
    capture.backend = cycle % 2 == 0 ? Backend::kGStreamer : Backend::kFFmpeg;
    capture.read_timeout_s = 1.0;
    capture.open_timeout_s = 4.0;
    Talker talker(server->url());
    {
      FrameGrabber grabber(capture);
      grabber.start();
      ASSERT_TRUE(grabber.wait_newer(0, seconds(10))) << grabber.stats().last_error;
      EXPECT_EQ(server->counters().media_started, 1u);
    }
    server.reset();
    EXPECT_TRUE(wait_until([&] { return talker.ended(); }, seconds(3)));
  }
  EXPECT_EQ(criticals.count(), 0);
}

}  // namespace
}  // namespace k40t::video
