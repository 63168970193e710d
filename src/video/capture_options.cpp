#include "k40t_driver/video/capture_options.h"

#include <cmath>

#include "k40t_driver/video/stall_guard.h"

namespace k40t::video {

Result<Backend> parse_backend(const std::string& name) {
  if (name == "gstreamer") return Backend::kGStreamer;
  if (name == "ffmpeg") return Backend::kFFmpeg;
  return Result<Backend>::fail("video backend '" + name + "' is not one of: gstreamer, ffmpeg");
}

Result<RtspTransport> parse_transport(const std::string& name) {
  if (name == "tcp") return RtspTransport::kTcp;
  if (name == "udp") return RtspTransport::kUdp;
  return Result<RtspTransport>::fail("RTSP transport '" + name + "' is not one of: tcp, udp");
}

const char* to_string(Backend backend) {
  return backend == Backend::kFFmpeg ? "ffmpeg" : "gstreamer";
}

const char* to_string(RtspTransport transport) {
  return transport == RtspTransport::kUdp ? "udp" : "tcp";
}

namespace {
Status check_timeout(const char* name, double seconds) {
  if (!std::isfinite(seconds) || seconds < 0.1 || seconds > 60) {
    return Status::fail(std::string(name) + " " + std::to_string(seconds) +
                        " s is out of range 0.1..60 s");
  }
  return Status::ok();
}

long long microseconds(double seconds) {
  return std::llround(seconds * 1e6);
}
}  // namespace

Status validate(const CaptureOptions& options) {
  const std::string& url = options.url;
  const bool rtsp = url.rfind("rtsp://", 0) == 0 || url.rfind("rtsps://", 0) == 0;
  const size_t host = url.find("://") + 3;
  if (!rtsp || url.size() <= host || url[host] == '/') {
    return Status::fail("video URL '" + url + "' is not rtsp://HOST[:PORT]/PATH");
  }
  if (url.find_first_of(" \t\"'!\\") != std::string::npos) {
    return Status::fail("video URL '" + url + "' contains a space, quote, '!' or backslash");
  }
  if (Status s = check_timeout("open_timeout", options.open_timeout_s); !s) return s;
  return check_timeout("read_timeout", options.read_timeout_s);
}

std::string gstreamer_pipeline(const CaptureOptions& options) {
  const long long open_us = microseconds(options.open_timeout_s);
  const long long read_ms = std::llround(options.read_timeout_s * 1000);
  return std::string("rtspsrc location=\"") + options.url +
         "\" latency=0 protocols=" + to_string(options.transport) +
         " tcp-timeout=" + std::to_string(open_us) + " timeout=" + std::to_string(open_us) +
         " ! decodebin ! " + kStallGuardElement + " timeout=" + std::to_string(read_ms) +
         " ! videoconvert ! video/x-raw,format=I420 ! appsink max-buffers=1 drop=true sync=false";
}

std::string ffmpeg_capture_options(const CaptureOptions& options) {
  return std::string("rtsp_transport;") + to_string(options.transport) +
         "|fflags;nobuffer|flags;low_delay|max_delay;0";
}

}  // namespace k40t::video
