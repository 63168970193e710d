// The pod's stream kept encoded: native GStreamer (rtspsrc ! rtph264depay|rtph265depay !
// h264parse|h265parse ! k40tstallguard ! appsink, the codec's elements linked in for the stream
// rtspsrc announces) delivers one access unit per coded picture as soon as its last RTP packet
// is in, in Annex B form with the parameter sets repeated before every key frame (the parser's
// config-interval=-1: a pod that sends SPS/PPS only in the SDP still gives a decodable key
// frame). Each access unit goes to the sink at once (the passthrough topic); it is
// decoded only while someone wants pixels (set_decoding), from the next key frame on, and the
// newest decoded frame waits for the consumer as with the OpenCV grabber (frames it was too slow
// for are replaced, never queued). Reconnects as frame_grabber.h does: stall guard, RTSP probe,
// back-off.
#pragma once

#include <functional>
#include <memory>

#include "k40t_driver/transport/transport.h"
#include "k40t_driver/video/capture_options.h"
#include "k40t_driver/video/frame_grabber.h"
#include "k40t_driver/video/frame_source.h"
#include "k40t_driver/video/video_codec.h"

namespace k40t::video {

// The pipeline description (rtspsrc name=source ..., guard ! appsink name=units); the codec's
// depayloader and parser are linked in between when rtspsrc has announced the stream.
std::string access_unit_pipeline(const CaptureOptions& options);

class AccessUnitSource : public FrameSource {
 public:
  // Called on GStreamer's streaming thread for every access unit; keep it short.
  using UnitSink = std::function<void(const AccessUnit&)>;

  AccessUnitSource(const CaptureOptions& capture, UnitSink sink,
                   const transport::ReconnectPolicy& reconnect = default_video_reconnect_policy());
  ~AccessUnitSource() override;  // stop()
  AccessUnitSource(const AccessUnitSource&) = delete;
  AccessUnitSource& operator=(const AccessUnitSource&) = delete;

  void start() override;
  // Ends the thread; the sink is not called after it returns (not even by a pipeline still
  // tearing down), so stop() is final.
  void stop() override;
  void restart() override;
  // Whether access units are decoded; turned on, the first picture comes from the next key frame.
  void set_decoding(bool wanted);
  // Decoded frames (I420); their sequence and times are those of their access unit.
  std::optional<GrabbedFrame> wait_newer(uint64_t after,
                                         std::chrono::milliseconds timeout) override;
  GrabberStats stats() const override;
  uint64_t decoded_frames() const;

  struct State;

 private:
  std::shared_ptr<State> state_;
};

}  // namespace k40t::video
