#include "k40t_driver/sim/video/rtsp_stream_server.h"

#include <gst/app/gstappsrc.h>
#include <gst/gst.h>
#include <gst/rtsp-server/rtsp-server.h>

#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>

#include <opencv2/imgproc.hpp>

#include "k40t_driver/sim/video/frame_renderer.h"

namespace k40t::sim::video {

Status validate(const RtspServerOptions& options) {
  if (options.port < 0 || options.port > 65535) {
    return Status::fail("RTSP port " + std::to_string(options.port) + " is out of range 0..65535");
  }
  if (options.path.size() < 2 || options.path[0] != '/' ||
      options.path.find_first_of(" ?#") != std::string::npos) {
    return Status::fail("RTSP path '" + options.path +
                        "' must start with '/' and contain no spaces, '?' or '#'");
  }
  if (options.fps < 1 || options.fps > 120) {
    return Status::fail("frame rate " + std::to_string(options.fps) + " is out of range 1..120");
  }
  if (options.bitrate_kbps < 100 || options.bitrate_kbps > 100000) {
    return Status::fail("bitrate " + std::to_string(options.bitrate_kbps) +
                        " kbit/s is out of range 100..100000");
  }
  if (options.key_frame_interval < 1 || options.key_frame_interval > 600) {
    return Status::fail("key frame interval " + std::to_string(options.key_frame_interval) +
                        " is out of range 1..600 frames");
  }
  return Status::ok();
}

namespace {

// Appsrc keeps at most two frames: if the encoder ever falls behind, the oldest frame is
// dropped rather than delaying every later one. Both encoders: zero-latency tuning (no B-frames,
// no look-ahead: one access unit out per frame in), the fastest preset, parameter sets before
// every key frame, one NAL unit per RTP packet.
std::string encoder_chain(const RtspServerOptions& options) {
  const std::string rate = " bitrate=" + std::to_string(options.bitrate_kbps) +
                           " key-int-max=" + std::to_string(options.key_frame_interval);
  if (options.codec == k40t::video::Codec::kH265)
    return "x265enc tune=zerolatency speed-preset=ultrafast" + rate +
           " ! rtph265pay name=pay0 pt=96 config-interval=-1 aggregate-mode=none";
  return "x264enc tune=zerolatency speed-preset=ultrafast sliced-threads=false threads=1" + rate +
         " ! video/x-h264,profile=constrained-baseline "
         "! rtph264pay name=pay0 pt=96 config-interval=-1 aggregate-mode=none";
}

std::string launch_line(const RtspServerOptions& options) {
  return "( appsrc name=src is-live=true do-timestamp=true format=time max-bytes=0 "
         "max-buffers=2 leaky-type=downstream ! " +
         encoder_chain(options) + " )";
}

Status check_elements(const RtspServerOptions& options) {
  const bool h265 = options.codec == k40t::video::Codec::kH265;
  for (const char* name :
       {"appsrc", h265 ? "x265enc" : "x264enc", h265 ? "rtph265pay" : "rtph264pay"}) {
    GstElementFactory* factory = gst_element_factory_find(name);
    if (!factory) {
      return Status::fail(std::string("GStreamer element '") + name +
                          "' is missing (install gstreamer1.0-plugins-base/-good/-bad/-ugly)");
    }
    gst_object_unref(factory);
  }
  return Status::ok();
}

void release_mat(gpointer mat) {
  delete static_cast<cv::Mat*>(mat);
}

// What the frame thread and GStreamer's signal handlers share. Each handler holds its own
// reference, released when GStreamer drops the handler, so a signal that comes after the server
// is gone (the media is GStreamer's, torn down on whichever thread drops it last) still finds
// valid state instead of a destroyed mutex.
struct SharedState {
  std::mutex mutex;  // guards what follows
  std::condition_variable wake;
  bool stopping = false;
  GstElement* appsrc = nullptr;  // our reference, while a media is up
  cv::Size caps_size;            // empty after a new media: caps must be set
  StreamCounters counters;

  ~SharedState() {
    if (appsrc) gst_object_unref(appsrc);
  }
};
using SharedRef = std::shared_ptr<SharedState>;

void release_shared(gpointer shared, GClosure*) {
  delete static_cast<SharedRef*>(shared);
}

template <typename Handler>
void connect_shared(gpointer instance, const char* signal, Handler handler,
                    const SharedRef& shared) {
  g_signal_connect_data(instance, signal, G_CALLBACK(handler), new SharedRef(shared),
                        &release_shared, GConnectFlags(0));
}

SharedState& shared_of(gpointer data) {
  return **static_cast<SharedRef*>(data);
}

void on_media_unprepared(GstRTSPMedia*, gpointer data) {
  SharedState& shared = shared_of(data);
  std::lock_guard<std::mutex> lock(shared.mutex);
  if (shared.appsrc) gst_object_unref(shared.appsrc);
  shared.appsrc = nullptr;
}

void on_media_configure(GstRTSPMediaFactory*, GstRTSPMedia* media, gpointer data) {
  GstElement* pipeline = gst_rtsp_media_get_element(media);
  GstElement* appsrc = gst_bin_get_by_name_recurse_up(GST_BIN(pipeline), "src");
  gst_object_unref(pipeline);
  connect_shared(media, "unprepared", &on_media_unprepared, *static_cast<SharedRef*>(data));
  SharedState& shared = shared_of(data);
  std::lock_guard<std::mutex> lock(shared.mutex);
  if (shared.appsrc) gst_object_unref(shared.appsrc);
  shared.appsrc = appsrc;  // our reference
  shared.caps_size = cv::Size();
  ++shared.counters.media_started;
}

}  // namespace

class RtspStreamServer::Impl {
 public:
  Impl(const RtspServerOptions& options, SnapshotSource source)
      : options_(options), source_(std::move(source)) {}

  ~Impl() { stop(); }

  Status start() {
    static std::once_flag gst_once;
    std::call_once(gst_once, [] { gst_init(nullptr, nullptr); });
    if (Status s = check_elements(options_); !s) return s;

    context_ = g_main_context_new();
    loop_ = g_main_loop_new(context_, FALSE);
    server_ = gst_rtsp_server_new();
    gst_rtsp_server_set_address(server_, options_.address.c_str());
    gst_rtsp_server_set_service(server_, std::to_string(options_.port).c_str());
    serve_clients_on_the_loop_thread();

    GstRTSPMediaFactory* factory = gst_rtsp_media_factory_new();
    gst_rtsp_media_factory_set_launch(factory, launch_line(options_).c_str());
    gst_rtsp_media_factory_set_shared(factory, TRUE);
    connect_shared(factory, "media-configure", &on_media_configure, shared_);
    GstRTSPMountPoints* mounts = gst_rtsp_server_get_mount_points(server_);
    gst_rtsp_mount_points_add_factory(mounts, options_.path.c_str(), factory);  // takes factory
    g_object_unref(mounts);

    GError* error = nullptr;
    listener_ = gst_rtsp_server_create_source(server_, nullptr, &error);
    if (!listener_) {
      std::string message = "cannot serve RTSP on " + options_.address + ":" +
                            std::to_string(options_.port) + ": " +
                            (error ? error->message : "unknown error");
      if (error) g_error_free(error);
      return Status::fail(message);
    }
    bound_port_ = gst_rtsp_server_get_bound_port(server_);
    g_source_attach(listener_, context_);

    loop_thread_ = std::thread([this] {
      g_main_context_push_thread_default(context_);
      g_main_loop_run(loop_);
      g_main_context_pop_thread_default(context_);
    });
    frame_thread_ = std::thread([this] { frame_loop(); });
    return Status::ok();
  }

  std::string url() const {
    return "rtsp://" + options_.address + ":" + std::to_string(bound_port_) + options_.path;
  }

  StreamCounters counters() const {
    std::lock_guard<std::mutex> lock(shared_->mutex);
    return shared_->counters;
  }

 private:
  // By default gst-rtsp-server serves clients on a thread of its own pool. stop() closes the
  // connections from the loop thread, and a client being served meanwhile (reading a request, or
  // tearing down after its peer hung up) then read from a closed connection (a GLib-GIO critical,
  // then a crash) or dropped the media only after the server was destroyed. On the loop thread,
  // closing a client cannot overlap serving it, and stop() returns with every client gone.
  void serve_clients_on_the_loop_thread() {
    GstRTSPThreadPool* pool = gst_rtsp_server_get_thread_pool(server_);
    gst_rtsp_thread_pool_set_max_threads(pool, 0);
    g_object_unref(pool);
  }

  void frame_loop() {
    using Clock = std::chrono::steady_clock;
    const auto period = std::chrono::nanoseconds(1000000000LL / options_.fps);
    auto next = Clock::now();
    uint32_t counter = 0;
    SharedState& shared = *shared_;
    std::unique_lock<std::mutex> lock(shared.mutex);
    while (!shared.stopping) {
      shared.wake.wait_until(lock, next, [&shared] { return shared.stopping; });
      if (shared.stopping) break;
      next += period;
      if (Clock::now() > next) next = Clock::now() + period;  // late: skip, never burst
      if (!shared.appsrc) continue;
      GstElement* appsrc = GST_ELEMENT(gst_object_ref(shared.appsrc));
      const cv::Size caps_size = shared.caps_size;
      lock.unlock();
      push_frame(appsrc, counter++, caps_size);
      gst_object_unref(appsrc);
      lock.lock();
    }
  }

  void push_frame(GstElement* appsrc, uint32_t counter, cv::Size caps_size) {
    const VideoSnapshot snapshot = source_ ? source_() : VideoSnapshot{};
    const cv::Mat bgr = renderer_.render(snapshot, {counter, system_time_us()});
    if (bgr.size() != caps_size) {
      GstCaps* caps = gst_caps_new_simple("video/x-raw", "format", G_TYPE_STRING, "I420", "width",
                                          G_TYPE_INT, bgr.cols, "height", G_TYPE_INT, bgr.rows,
                                          "framerate", GST_TYPE_FRACTION, options_.fps, 1, nullptr);
      gst_app_src_set_caps(GST_APP_SRC(appsrc), caps);
      gst_caps_unref(caps);
      std::lock_guard<std::mutex> lock(shared_->mutex);
      shared_->caps_size = bgr.size();
    }
    auto* yuv = new cv::Mat();
    cv::cvtColor(bgr, *yuv, cv::COLOR_BGR2YUV_I420);
    const gsize bytes = yuv->total() * yuv->elemSize();
    GstBuffer* buffer = gst_buffer_new_wrapped_full(GST_MEMORY_FLAG_READONLY, yuv->data, bytes, 0,
                                                    bytes, yuv, &release_mat);
    if (gst_app_src_push_buffer(GST_APP_SRC(appsrc), buffer) == GST_FLOW_OK) {
      std::lock_guard<std::mutex> lock(shared_->mutex);
      ++shared_->counters.frames_pushed;
    }
  }

  // On the loop thread: no new client from now on, every client closed (which tears the shared
  // media down), then the loop ends.
  static gboolean shut_down(gpointer self) {
    auto* impl = static_cast<Impl*>(self);
    g_source_destroy(impl->listener_);
    gst_rtsp_server_client_filter(
        impl->server_,
        [](GstRTSPServer*, GstRTSPClient*, gpointer) { return GST_RTSP_FILTER_REMOVE; }, nullptr);
    g_main_loop_quit(impl->loop_);
    return G_SOURCE_REMOVE;
  }

  void stop() {
    {
      std::lock_guard<std::mutex> lock(shared_->mutex);
      shared_->stopping = true;
    }
    shared_->wake.notify_all();
    if (frame_thread_.joinable()) frame_thread_.join();
    if (loop_thread_.joinable()) {
      // An idle source, not g_main_context_invoke(): that runs the function on the calling
      // thread when the loop has not acquired the context yet, and the loop would then start
      // after its quit and never end.
      GSource* idle = g_idle_source_new();
      g_source_set_callback(idle, &Impl::shut_down, this, nullptr);
      g_source_attach(idle, context_);
      g_source_unref(idle);
      loop_thread_.join();
    }
    {
      std::lock_guard<std::mutex> lock(shared_->mutex);
      if (shared_->appsrc) gst_object_unref(shared_->appsrc);
      shared_->appsrc = nullptr;
    }
    if (listener_) g_source_unref(listener_);
    if (server_) g_object_unref(server_);
    if (loop_) g_main_loop_unref(loop_);
    if (context_) g_main_context_unref(context_);
    listener_ = nullptr;
    server_ = nullptr;
    loop_ = nullptr;
    context_ = nullptr;
  }

  RtspServerOptions options_;
  SnapshotSource source_;
  GMainContext* context_ = nullptr;
  GMainLoop* loop_ = nullptr;
  GstRTSPServer* server_ = nullptr;
  GSource* listener_ = nullptr;  // our reference, to stop accepting before closing the clients
  int bound_port_ = 0;
  std::thread loop_thread_;
  std::thread frame_thread_;
  FrameRenderer renderer_;  // used by the frame thread only
  SharedRef shared_ = std::make_shared<SharedState>();
};

Result<std::unique_ptr<RtspStreamServer>> RtspStreamServer::start(const RtspServerOptions& options,
                                                                  SnapshotSource source) {
  if (Status s = validate(options); !s) return s;
  auto impl = std::make_unique<Impl>(options, std::move(source));
  if (Status s = impl->start(); !s) return s;
  return std::unique_ptr<RtspStreamServer>(new RtspStreamServer(std::move(impl)));
}

RtspStreamServer::RtspStreamServer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
RtspStreamServer::~RtspStreamServer() = default;

std::string RtspStreamServer::url() const {
  return impl_->url();
}

StreamCounters RtspStreamServer::counters() const {
  return impl_->counters();
}

}  // namespace k40t::sim::video
