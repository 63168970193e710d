#include "k40t_driver/video/access_unit_source.h"

#include <gst/app/gstappsink.h>
#include <gst/gst.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <deque>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

#include "k40t_driver/transport/backoff.h"
#include "k40t_driver/video/gst_launch.h"
#include "k40t_driver/video/rtsp_probe.h"
#include "k40t_driver/video/source_state.h"
#include "k40t_driver/video/stall_guard.h"

namespace k40t::video {

using Clock = std::chrono::steady_clock;

std::string access_unit_pipeline(const CaptureOptions& options) {
  const long long open_us = std::llround(options.open_timeout_s * 1e6);
  const long long read_ms = std::llround(options.read_timeout_s * 1000);
  return std::string("rtspsrc name=source location=\"") + options.url +
         "\" latency=0 protocols=" + to_string(options.transport) +
         " tcp-timeout=" + std::to_string(open_us) + " timeout=" + std::to_string(open_us) + " " +
         kStallGuardElement + " name=guard timeout=" + std::to_string(read_ms) +
         " ! appsink name=units sync=false enable-last-sample=false";
}

namespace {

int64_t now_us() {
  return std::chrono::duration_cast<std::chrono::microseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// The depayloader and parser of the codec rtspsrc announces (RTP caps' encoding-name), linked
// in when its pad appears. The capsfilter before the parser makes the depayloader hand on whole
// access units (it completes one at the RTP marker bit); left to choose, it sends single NAL
// units and the parser can close an access unit only when the next one starts: a frame late.
// config-interval=-1 repeats the parameter sets before every key frame, also when the pod sends
// them only in the SDP.
void on_rtp_pad(GstElement* rtspsrc, GstPad* pad, gpointer) {
  GstCaps* caps = gst_pad_get_current_caps(pad);
  if (!caps) caps = gst_pad_query_caps(pad, nullptr);
  const gchar* encoding =
      gst_structure_get_string(gst_caps_get_structure(caps, 0), "encoding-name");
  std::optional<Codec> codec;
  if (encoding && std::strcmp(encoding, "H264") == 0) codec = Codec::kH264;
  if (encoding && std::strcmp(encoding, "H265") == 0) codec = Codec::kH265;
  gst_caps_unref(caps);
  if (!codec) return;  // audio or another stream: left unlinked
  const std::string name = *codec == Codec::kH265 ? "h265" : "h264";
  const std::string chain = "rtp" + name + "depay ! video/x-" + name + ",alignment=au ! " + name +
                            "parse config-interval=-1 ! capsfilter caps=\"" +
                            access_unit_caps(*codec) + "\"";
  GError* error = nullptr;
  GstElement* bin = gst_parse_bin_from_description(chain.c_str(), TRUE, &error);
  if (error) g_error_free(error);
  if (!bin) return;  // the stall guard ends the stream: reported, retried
  GstBin* pipeline = GST_BIN(gst_element_get_parent(rtspsrc));
  GstElement* guard = gst_bin_get_by_name(pipeline, "guard");
  gst_bin_add(pipeline, bin);
  gst_element_link(bin, guard);
  gst_element_sync_state_with_parent(bin);
  GstPad* sink = gst_element_get_static_pad(bin, "sink");
  gst_pad_link(pad, sink);
  gst_object_unref(sink);
  gst_object_unref(guard);
  gst_object_unref(pipeline);
}

}  // namespace

struct AccessUnitSource::State : SourceState {
  CaptureOptions capture;
  transport::ReconnectPolicy reconnect;
  std::mutex sink_mutex;  // held while the sink runs: stop() waits for it, then drops the sink
  UnitSink sink;

  bool decoding_wanted = false;
  uint64_t sequence = 0;
  uint64_t decoded = 0;
  bool any_unit = false;  // since the current pipeline started
  bool ever_streamed = false;

  // Streaming thread only (and the run loop between pipelines).
  std::unique_ptr<VideoDecoder> decoder;
  // Received time and presentation time of the access units in the decoder, by sequence.
  std::deque<std::pair<uint64_t, std::pair<int64_t, std::optional<double>>>> in_decoder;

  static GstFlowReturn new_sample(GstAppSink* appsink, gpointer self) {
    GstSample* sample = gst_app_sink_pull_sample(appsink);
    if (!sample) return GST_FLOW_OK;
    static_cast<State*>(self)->on_unit(sample);
    gst_sample_unref(sample);
    return GST_FLOW_OK;
  }

  void on_unit(GstSample* sample) {
    AccessUnit unit;
    unit.received_us = now_us();
    GstCaps* caps = gst_sample_get_caps(sample);
    GstBuffer* buffer = gst_sample_get_buffer(sample);
    if (!caps || !buffer) return;
    const GstStructure* s = gst_caps_get_structure(caps, 0);
    unit.codec = gst_structure_has_name(s, "video/x-h265") ? Codec::kH265 : Codec::kH264;
    gst_structure_get_int(s, "width", &unit.width);
    gst_structure_get_int(s, "height", &unit.height);
    unit.key_frame = !GST_BUFFER_FLAG_IS_SET(buffer, GST_BUFFER_FLAG_DELTA_UNIT);
    if (GST_BUFFER_PTS_IS_VALID(buffer)) unit.pts_ms = GST_BUFFER_PTS(buffer) / 1e6;
    GstMapInfo map;
    if (!gst_buffer_map(buffer, &map, GST_MAP_READ)) return;
    unit.bytes.assign(map.data, map.data + map.size);
    gst_buffer_unmap(buffer, &map);
    bool wanted = false;
    {
      std::lock_guard<std::mutex> lock(mutex);
      unit.sequence = ++sequence;
      ++stats.frames;
      stats.streaming = true;
      stats.last_frame = Clock::now();
      if (!any_unit && ever_streamed) ++stats.reconnects;  // the first unit of a new stream
      ever_streamed = true;
      any_unit = true;
      wanted = decoding_wanted;
    }
    {
      std::lock_guard<std::mutex> lock(sink_mutex);
      if (sink) sink(unit);
    }
    decode(unit, wanted);
  }

  void decode(const AccessUnit& unit, bool wanted) {
    if (!wanted) {
      if (decoder) decoder->resync();  // what comes next refers to pictures it will not see
      return;
    }
    if (!decoder || decoder->codec() != unit.codec) {
      auto created = VideoDecoder::create(unit.codec);
      if (!created) return failed(true, created.error());
      decoder = std::move(created.value());
      decoder->on_frame([this](DecodedFrame frame) { on_decoded(std::move(frame)); });
    }
    {
      // Before the push: the decoder's thread may hand the picture on before push() returns.
      std::lock_guard<std::mutex> lock(mutex);
      in_decoder.emplace_back(unit.sequence, std::make_pair(unit.received_us, unit.pts_ms));
      while (in_decoder.size() > 64) in_decoder.pop_front();
    }
    Result<bool> pushed =
        decoder->push(unit.bytes.data(), unit.bytes.size(), unit.key_frame, unit.sequence);
    if (!pushed) {
      failed(true, "decoder: " + pushed.error());
      decoder.reset();  // a new one from the next key frame
    }
  }

  // On the decoder's thread.
  void on_decoded(DecodedFrame picture) {
    GrabbedFrame frame;
    frame.pixels = std::move(picture.i420);  // the decoder's buffer, held: no copy
    frame.memory = std::move(picture.memory);
    frame.i420 = true;
    frame.size = picture.size;
    frame.sequence = picture.tag;
    {
      std::lock_guard<std::mutex> lock(mutex);
      const auto times = std::find_if(in_decoder.begin(), in_decoder.end(), [&](const auto& entry) {
        return entry.first == picture.tag;
      });
      if (times == in_decoder.end()) return;  // not a picture of ours (cannot happen): no stamp
      frame.received_us = times->second.first;
      frame.pts_ms = times->second.second;
      if (latest && latest->sequence >= frame.sequence) return;
      ++decoded;
      latest = std::move(frame);
    }
    changed.notify_all();
  }

  // Plays one pipeline until it fails, a restart is asked for or the source stops.
  void stream(GstElement* pipeline) {
    GstBus* bus = gst_element_get_bus(pipeline);
    while (is_running()) {
      if (take_restart()) break;
      GstMessage* message = gst_bus_timed_pop_filtered(
          bus, 100 * GST_MSECOND, static_cast<GstMessageType>(GST_MESSAGE_ERROR | GST_MESSAGE_EOS));
      if (!message) continue;
      std::string error = "the stream ended or stalled (no frame within the read timeout)";
      if (GST_MESSAGE_TYPE(message) == GST_MESSAGE_ERROR) {
        GError* e = nullptr;
        gst_message_parse_error(message, &e, nullptr);
        if (e) error = e->message;
        if (e) g_error_free(e);
      }
      gst_message_unref(message);
      bool opened = false;
      {
        std::lock_guard<std::mutex> lock(mutex);
        opened = any_unit;
      }
      failed(opened, error);
      break;
    }
    gst_object_unref(bus);
  }

  Status play_once(bool& any) {
    if (Status s = probe_rtsp(capture.url, capture.open_timeout_s); !s) return s;
    if (Status s = register_stall_guard(); !s) return s;
    Result<GstElement*> launched = launch_pipeline(access_unit_pipeline(capture), "stream");
    if (!launched) return launched.status();
    GstElement* pipeline = launched.value();
    GstElement* rtspsrc = gst_bin_get_by_name(GST_BIN(pipeline), "source");
    g_signal_connect(rtspsrc, "pad-added", G_CALLBACK(on_rtp_pad), nullptr);
    gst_object_unref(rtspsrc);
    GstElement* appsink = gst_bin_get_by_name(GST_BIN(pipeline), "units");
    GstAppSinkCallbacks callbacks{};
    callbacks.new_sample = &State::new_sample;
    gst_app_sink_set_callbacks(GST_APP_SINK(appsink), &callbacks, this, nullptr);
    gst_object_unref(appsink);
    {
      std::lock_guard<std::mutex> lock(mutex);
      any_unit = false;
    }
    gst_element_set_state(pipeline, GST_STATE_PLAYING);
    stream(pipeline);
    gst_element_set_state(pipeline, GST_STATE_NULL);  // joins the streaming threads
    gst_object_unref(pipeline);
    if (decoder) decoder->resync();  // the next stream starts afresh
    std::lock_guard<std::mutex> lock(mutex);
    any = any_unit;
    return Status::ok();
  }

  void run() {
    transport::Backoff backoff(reconnect);
    while (is_running()) {
      bool any = false;
      if (Status s = play_once(any); !s) failed(false, s.message());
      if (any) backoff.reset();
      if (!pause(backoff.next())) break;
    }
    decoder.reset();
    finish_thread();
  }
};

AccessUnitSource::AccessUnitSource(const CaptureOptions& capture, UnitSink sink,
                                   const transport::ReconnectPolicy& reconnect)
    : state_(std::make_shared<State>()) {
  ensure_gstreamer();
  state_->capture = capture;
  state_->reconnect = reconnect;
  state_->sink = std::move(sink);
}

AccessUnitSource::~AccessUnitSource() {
  stop();
}

void AccessUnitSource::start() {
  start_source_thread(state_);
}

void AccessUnitSource::stop() {
  state_->stop(std::chrono::duration<double>(state_->capture.open_timeout_s +
                                             state_->capture.read_timeout_s + 1.0));
  // A pipeline still tearing down past the grace period must not call into its owner.
  std::lock_guard<std::mutex> sink_lock(state_->sink_mutex);
  state_->sink = nullptr;
}

void AccessUnitSource::restart() {
  state_->request_restart();
}

void AccessUnitSource::set_decoding(bool wanted) {
  std::lock_guard<std::mutex> lock(state_->mutex);
  state_->decoding_wanted = wanted;
}

std::optional<GrabbedFrame> AccessUnitSource::wait_newer(uint64_t after,
                                                         std::chrono::milliseconds timeout) {
  return state_->wait_newer(after, timeout);
}

GrabberStats AccessUnitSource::stats() const {
  return state_->stats_now();
}

uint64_t AccessUnitSource::decoded_frames() const {
  std::lock_guard<std::mutex> lock(state_->mutex);
  return state_->decoded;
}

}  // namespace k40t::video
