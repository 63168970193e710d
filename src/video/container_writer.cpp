#include "k40t_driver/video/container_writer.h"

#include <gst/app/gstappsrc.h>
#include <gst/gst.h>
#include <unistd.h>

#include <optional>

#include "k40t_driver/video/gst_launch.h"

namespace k40t::video {

namespace {

bool ends_with(const std::string& text, const std::string& tail) {
  return text.size() >= tail.size() &&
         text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

// The bus's first error (or nothing), waiting up to `timeout` for it or for end-of-stream.
std::optional<std::string> wait_end(GstElement* pipeline, GstClockTime timeout) {
  GstBus* bus = gst_element_get_bus(pipeline);
  GstMessage* message = gst_bus_timed_pop_filtered(
      bus, timeout, static_cast<GstMessageType>(GST_MESSAGE_ERROR | GST_MESSAGE_EOS));
  gst_object_unref(bus);
  if (!message) return std::string("the muxer did not finish in time");
  std::optional<std::string> error;
  if (GST_MESSAGE_TYPE(message) == GST_MESSAGE_ERROR) {
    GError* e = nullptr;
    gst_message_parse_error(message, &e, nullptr);
    error = e ? e->message : "unknown GStreamer error";
    if (e) g_error_free(e);
  }
  gst_message_unref(message);
  return error;
}

}  // namespace

Result<Container> container_for(const std::string& path) {
  if (ends_with(path, ".mp4") || ends_with(path, ".m4v")) return Container::kMp4;
  if (ends_with(path, ".mkv")) return Container::kMatroska;
  return Result<Container>::fail("video file '" + path + "' must end in .mp4, .m4v or .mkv");
}

struct ContainerWriter::Impl {
  std::string path;
  GstElement* pipeline = nullptr;
  GstElement* source = nullptr;
  std::optional<int64_t> first_stamp_ns;
  int64_t last_pts_ns = -1;
  bool finished = false;

  ~Impl() {
    if (pipeline) gst_element_set_state(pipeline, GST_STATE_NULL);
    if (source) gst_object_unref(source);
    if (pipeline) gst_object_unref(pipeline);
    if (!finished) ::unlink(path.c_str());
  }
};

ContainerWriter::ContainerWriter(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
ContainerWriter::~ContainerWriter() = default;

Result<std::unique_ptr<ContainerWriter>> ContainerWriter::open(const std::string& path,
                                                               Codec codec) {
  Result<Container> container = container_for(path);
  if (!container) return container.status();
  if (path.find_first_of("\"\\") != std::string::npos)
    return Status::fail("video file '" + path + "' contains a quote or backslash");
  ensure_gstreamer();
  const std::string parser = codec == Codec::kH265 ? "h265parse" : "h264parse";
  const std::string muxer = container.value() == Container::kMp4 ? "mp4mux" : "matroskamux";
  // Not live, blocking when 4 MB are queued: a long bag streams through in bounded memory.
  const std::string description =
      "appsrc name=in format=time block=true max-bytes=4000000 caps=\"" + access_unit_caps(codec) +
      "\" ! " + parser + " ! " + muxer + " ! filesink location=\"" + path + "\"";
  Result<GstElement*> pipeline = launch_pipeline(description, muxer);
  if (!pipeline) return pipeline.status();
  auto impl = std::make_unique<Impl>();
  impl->path = path;
  impl->pipeline = pipeline.value();
  impl->source = gst_bin_get_by_name(GST_BIN(impl->pipeline), "in");
  if (gst_element_set_state(impl->pipeline, GST_STATE_PLAYING) == GST_STATE_CHANGE_FAILURE) {
    std::optional<std::string> why = wait_end(impl->pipeline, 0);
    return Status::fail("cannot write " + path + ": " + why.value_or("the pipeline did not start"));
  }
  return std::unique_ptr<ContainerWriter>(new ContainerWriter(std::move(impl)));
}

Result<bool> ContainerWriter::write(const uint8_t* data, size_t size, bool key_frame,
                                    int64_t stamp_ns) {
  if (!impl_->first_stamp_ns) {
    if (!key_frame) return false;
    impl_->first_stamp_ns = stamp_ns;
  }
  int64_t pts = stamp_ns - *impl_->first_stamp_ns;
  if (pts <= impl_->last_pts_ns) pts = impl_->last_pts_ns + 1'000'000;
  impl_->last_pts_ns = pts;
  GstBuffer* buffer = gst_buffer_new_allocate(nullptr, size, nullptr);
  gst_buffer_fill(buffer, 0, data, size);
  GST_BUFFER_PTS(buffer) = static_cast<GstClockTime>(pts);
  GST_BUFFER_DTS(buffer) = static_cast<GstClockTime>(pts);
  if (!key_frame) GST_BUFFER_FLAG_SET(buffer, GST_BUFFER_FLAG_DELTA_UNIT);
  if (gst_app_src_push_buffer(GST_APP_SRC(impl_->source), buffer) != GST_FLOW_OK) {
    std::optional<std::string> why = wait_end(impl_->pipeline, 0);
    return Status::fail("cannot write " + impl_->path + ": " + why.value_or("the muxer stopped"));
  }
  ++written_;
  return true;
}

Status ContainerWriter::finish() {
  gst_app_src_end_of_stream(GST_APP_SRC(impl_->source));
  std::optional<std::string> error = wait_end(impl_->pipeline, 60 * GST_SECOND);
  gst_element_set_state(impl_->pipeline, GST_STATE_NULL);
  if (error) return Status::fail("cannot write " + impl_->path + ": " + *error);
  if (written_ == 0) return Status::fail(impl_->path + ": no key frame, nothing to write");
  impl_->finished = true;
  return Status::ok();
}

}  // namespace k40t::video
