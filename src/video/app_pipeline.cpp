#include "k40t_driver/video/app_pipeline.h"

#include <gst/app/gstappsink.h>
#include <gst/app/gstappsrc.h>
#include <gst/gst.h>
#include <gst/video/video.h>

#include "k40t_driver/video/gst_launch.h"

#include <cstring>
#include <memory>
#include <mutex>

namespace k40t::video {

Result<GstElement*> launch_pipeline(const std::string& description, const std::string& what) {
  GError* error = nullptr;
  GstElement* pipeline = gst_parse_launch(description.c_str(), &error);
  if (!error && pipeline) return pipeline;
  const std::string text = error ? error->message : "no pipeline";
  if (error) g_error_free(error);
  if (pipeline) gst_object_unref(pipeline);
  return Status::fail("cannot build the " + what + " pipeline: " + text);
}

void ensure_gstreamer() {
  static std::once_flag once;
  std::call_once(once, [] {
    if (!gst_is_initialized()) gst_init(nullptr, nullptr);
  });
}

bool has_gstreamer_element(const std::string& name) {
  ensure_gstreamer();
  GstElementFactory* factory = gst_element_factory_find(name.c_str());
  if (!factory) return false;
  gst_object_unref(factory);
  return true;
}

namespace {

// A mapped raw video frame whose planes follow each other with no padding, as a packed copy
// would lay them out; its pixels are then used where they are.
bool planes_packed(const GstVideoFrame& frame) {
  const auto* next = static_cast<const uint8_t*>(GST_VIDEO_FRAME_PLANE_DATA(&frame, 0));
  for (guint p = 0; p < GST_VIDEO_FRAME_N_PLANES(&frame); ++p) {
    const int row_bytes =
        GST_VIDEO_FRAME_COMP_WIDTH(&frame, p) * GST_VIDEO_FRAME_COMP_PSTRIDE(&frame, p);
    if (GST_VIDEO_FRAME_PLANE_DATA(&frame, p) != next ||
        GST_VIDEO_FRAME_PLANE_STRIDE(&frame, p) != row_bytes)
      return false;
    next += static_cast<size_t>(row_bytes) * GST_VIDEO_FRAME_COMP_HEIGHT(&frame, p);
  }
  return true;
}

// Keeps `frame` mapped (and its buffer referenced) until the last holder lets go.
void hold_frame(std::unique_ptr<GstVideoFrame> frame, PipelineSample& out) {
  const auto* data = static_cast<const uint8_t*>(GST_VIDEO_FRAME_PLANE_DATA(frame.get(), 0));
  const guint last = GST_VIDEO_FRAME_N_PLANES(frame.get()) - 1;
  out.held_size =
      static_cast<size_t>(
          static_cast<const uint8_t*>(GST_VIDEO_FRAME_PLANE_DATA(frame.get(), last)) - data) +
      static_cast<size_t>(GST_VIDEO_FRAME_PLANE_STRIDE(frame.get(), last)) *
          GST_VIDEO_FRAME_COMP_HEIGHT(frame.get(), last);
  GstVideoFrame* mapped = frame.release();
  out.held = std::shared_ptr<const uint8_t>(data, [mapped](const uint8_t*) {
    gst_video_frame_unmap(mapped);  // also drops the buffer's reference
    delete mapped;
  });
}

// Raw video planes without the decoder's padding: held where they are if already so, else
// copied row by row; other media copied as they are.
void take_buffer(GstBuffer* buffer, GstCaps* caps, PipelineSample& out) {
  GstVideoInfo info;
  if (out.media == "video/x-raw" && gst_video_info_from_caps(&info, caps)) {
    auto frame = std::make_unique<GstVideoFrame>();
    if (gst_video_frame_map(frame.get(), &info, buffer, GST_MAP_READ)) {
      if (planes_packed(*frame)) return hold_frame(std::move(frame), out);
      size_t total = 0;
      for (guint p = 0; p < GST_VIDEO_FRAME_N_PLANES(frame.get()); ++p)
        total += static_cast<size_t>(GST_VIDEO_FRAME_COMP_WIDTH(frame.get(), p)) *
                 GST_VIDEO_FRAME_COMP_PSTRIDE(frame.get(), p) *
                 GST_VIDEO_FRAME_COMP_HEIGHT(frame.get(), p);
      out.bytes.resize(total);
      uint8_t* to = out.bytes.data();
      for (guint p = 0; p < GST_VIDEO_FRAME_N_PLANES(frame.get()); ++p) {
        const int rows = GST_VIDEO_FRAME_COMP_HEIGHT(frame.get(), p);
        const int row_bytes = GST_VIDEO_FRAME_COMP_WIDTH(frame.get(), p) *
                              GST_VIDEO_FRAME_COMP_PSTRIDE(frame.get(), p);
        const int stride = GST_VIDEO_FRAME_PLANE_STRIDE(frame.get(), p);
        const auto* from = static_cast<const uint8_t*>(GST_VIDEO_FRAME_PLANE_DATA(frame.get(), p));
        for (int r = 0; r < rows; ++r, to += row_bytes)
          std::memcpy(to, from + static_cast<size_t>(r) * stride, row_bytes);
      }
      gst_video_frame_unmap(frame.get());
      return;
    }
  }
  GstMapInfo map;
  if (gst_buffer_map(buffer, &map, GST_MAP_READ)) {
    out.bytes.assign(map.data, map.data + map.size);
    gst_buffer_unmap(buffer, &map);
  }
}

std::optional<PipelineSample> to_sample(GstSample* sample) {
  if (!sample) return std::nullopt;
  PipelineSample out;
  GstBuffer* buffer = gst_sample_get_buffer(sample);
  GstCaps* caps = gst_sample_get_caps(sample);
  if (caps && gst_caps_get_size(caps) > 0) {
    const GstStructure* s = gst_caps_get_structure(caps, 0);
    out.media = gst_structure_get_name(s);
    gst_structure_get_int(s, "width", &out.width);
    gst_structure_get_int(s, "height", &out.height);
  }
  if (buffer) {
    if (GST_BUFFER_PTS_IS_VALID(buffer)) out.pts_ns = GST_BUFFER_PTS(buffer);
    out.key_frame = !GST_BUFFER_FLAG_IS_SET(buffer, GST_BUFFER_FLAG_DELTA_UNIT);
    take_buffer(buffer, caps, out);
  }
  gst_sample_unref(sample);
  return out;
}

}  // namespace

struct AppPipeline::Impl {
  GstElement* pipeline = nullptr;
  GstElement* source = nullptr;
  GstElement* sink = nullptr;
  std::function<void(PipelineSample)> callback;
  mutable std::mutex error_mutex;
  mutable std::string first_error;

  ~Impl() {
    if (pipeline) gst_element_set_state(pipeline, GST_STATE_NULL);
    if (source) gst_object_unref(source);
    if (sink) gst_object_unref(sink);
    if (pipeline) gst_object_unref(pipeline);
  }

  static GstFlowReturn new_sample(GstAppSink* sink, gpointer self) {
    auto* impl = static_cast<Impl*>(self);
    std::optional<PipelineSample> sample = to_sample(gst_app_sink_pull_sample(sink));
    if (sample && impl->callback) impl->callback(std::move(*sample));
    return GST_FLOW_OK;
  }

  // The first error the pipeline ever posted (later ones are consequences).
  std::string bus_error() const {
    std::lock_guard<std::mutex> lock(error_mutex);
    GstBus* bus = gst_element_get_bus(pipeline);
    while (GstMessage* message = gst_bus_pop_filtered(bus, GST_MESSAGE_ERROR)) {
      GError* error = nullptr;
      gchar* debug = nullptr;
      gst_message_parse_error(message, &error, &debug);
      if (first_error.empty() && error) {
        first_error = std::string(GST_OBJECT_NAME(GST_MESSAGE_SRC(message))) + ": " +
                      error->message + (debug ? std::string(" (") + debug + ")" : "");
      }
      if (error) g_error_free(error);
      g_free(debug);
      gst_message_unref(message);
    }
    gst_object_unref(bus);
    return first_error;
  }

  Status push(GstBuffer* buffer, uint64_t pts_ns) {
    GST_BUFFER_PTS(buffer) = pts_ns;
    GST_BUFFER_DTS(buffer) = pts_ns;
    // Takes the buffer.
    if (gst_app_src_push_buffer(GST_APP_SRC(source), buffer) != GST_FLOW_OK)
      return Status::fail("the GStreamer pipeline refused a buffer (stopped)");
    return Status::ok();
  }
};

AppPipeline::AppPipeline(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
AppPipeline::~AppPipeline() = default;

Result<std::unique_ptr<AppPipeline>> AppPipeline::create(const std::string& input_caps,
                                                         const std::string& middle,
                                                         const std::string& output_caps) {
  ensure_gstreamer();
  // Unbounded input queue: a codec must see every access unit (a dropped one corrupts the frames
  // that refer to it until the next key frame); the caller decides what not to push.
  const std::string description =
      "appsrc name=in is-live=true format=time block=false max-bytes=0 caps=\"" + input_caps +
      "\" ! " + middle + " ! appsink name=out sync=false enable-last-sample=false" +
      (output_caps.empty() ? "" : " caps=\"" + output_caps + "\"");
  Result<GstElement*> pipeline = launch_pipeline(description, "'" + middle + "'");
  if (!pipeline) return pipeline.status();
  auto impl = std::make_unique<Impl>();
  impl->pipeline = pipeline.value();
  impl->source = gst_bin_get_by_name(GST_BIN(impl->pipeline), "in");
  impl->sink = gst_bin_get_by_name(GST_BIN(impl->pipeline), "out");
  if (gst_element_set_state(impl->pipeline, GST_STATE_PLAYING) == GST_STATE_CHANGE_FAILURE) {
    const std::string text = impl->bus_error();
    return Status::fail("GStreamer pipeline '" + middle + "' does not start: " + text);
  }
  return std::unique_ptr<AppPipeline>(new AppPipeline(std::move(impl)));
}

Status AppPipeline::push(const uint8_t* data, size_t size, uint64_t pts_ns) {
  if (std::string e = error(); !e.empty()) return Status::fail(e);
  GstBuffer* buffer = gst_buffer_new_allocate(nullptr, size, nullptr);
  gst_buffer_fill(buffer, 0, data, size);
  return impl_->push(buffer, pts_ns);
}

Status AppPipeline::push_rows(const uint8_t* data, size_t step, size_t row_bytes, size_t rows,
                              uint64_t pts_ns) {
  if (std::string e = error(); !e.empty()) return Status::fail(e);
  GstCaps* caps = gst_app_src_get_caps(GST_APP_SRC(impl_->source));
  GstVideoInfo info;
  const bool video = caps && gst_video_info_from_caps(&info, caps);
  if (caps) gst_caps_unref(caps);
  if (!video || GST_VIDEO_INFO_N_PLANES(&info) != 1 ||
      static_cast<size_t>(GST_VIDEO_INFO_HEIGHT(&info)) != rows ||
      static_cast<size_t>(GST_VIDEO_INFO_PLANE_STRIDE(&info, 0)) < row_bytes)
    return Status::fail("the frame does not match the pipeline's single-plane video caps");
  const size_t stride = GST_VIDEO_INFO_PLANE_STRIDE(&info, 0);
  GstBuffer* buffer = gst_buffer_new_allocate(nullptr, GST_VIDEO_INFO_SIZE(&info), nullptr);
  GstMapInfo map;
  gst_buffer_map(buffer, &map, GST_MAP_WRITE);
  for (size_t r = 0; r < rows; ++r) std::memcpy(map.data + r * stride, data + r * step, row_bytes);
  gst_buffer_unmap(buffer, &map);
  return impl_->push(buffer, pts_ns);
}

std::optional<PipelineSample> AppPipeline::pull(std::chrono::milliseconds timeout) {
  GstSample* sample = gst_app_sink_try_pull_sample(
      GST_APP_SINK(impl_->sink), static_cast<GstClockTime>(timeout.count()) * GST_MSECOND);
  return to_sample(sample);
}

void AppPipeline::on_sample(std::function<void(PipelineSample)> callback) {
  impl_->callback = std::move(callback);
  GstAppSinkCallbacks callbacks{};
  callbacks.new_sample = &Impl::new_sample;
  gst_app_sink_set_callbacks(GST_APP_SINK(impl_->sink), &callbacks, impl_.get(), nullptr);
}

std::string AppPipeline::error() const {
  return impl_->bus_error();
}

}  // namespace k40t::video
