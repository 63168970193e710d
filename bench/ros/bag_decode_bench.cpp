// `k40t bag` speed: decodes a synthetic hour of full-rate pod traffic (figures printed, nothing
// asserted; target: under 10 s on the development machine).
//
// The hour is built with the simulator's report schedule and encoders (sim/pod_reports.h: every
// periodic report at the document's rate, periodic ranging on) plus the laser target ACK at 1 Hz
// (laser_target_period), framed as the pod frames them and written as <ns>/raw/rx like a
// recording of the live driver. Then the bag is decoded exactly as `k40t bag` does (decode_bag),
// once plain and once with the JSON-lines export.
//
//   k40t_bag_decode_bench [SECONDS=3600] [DIR=/tmp]
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

#include <rosbag/bag.h>

#include "k40t_driver/protocol/messages/flight_controller.h"
#include "k40t_driver/ros/bag/bag_decoder.h"
#include "k40t_driver/ros/conversions.h"
#include "k40t_driver/sim/pod_reports.h"

namespace {

using namespace k40t;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Gimbal reports come from the gimbal's address, the rest from the camera's (NOTES A3).
protocol::Address source_of(protocol::MessageId id, const protocol::CodecOptions& codec) {
  return id == 0x000001 || id == 0x000002 ? codec.gimbal_address : codec.camera_address;
}

// Writes `seconds` of traffic; returns the number of frames.
uint64_t write_traffic(const std::string& path, double seconds) {
  const protocol::CodecOptions codec;
  sim::PodModel pod;
  pod.laser().set_periodic(true);
  sim::ReportScheduler scheduler;
  std::map<uint8_t, uint8_t> sequence;  // per source system
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  const int64_t start_ns = 1'700'000'000'000'000'000;
  uint64_t frames = 0;
  auto write = [&](protocol::MessageId id, const protocol::Payload& payload, double t) {
    protocol::FrameHeader header;
    header.source = source_of(id, codec);
    header.destination = protocol::kHostAddress;
    header.sequence = sequence[header.source.system]++;
    header.message_id = id;
    Result<protocol::EncodedFrame> frame = protocol::encode_frame(
        header, payload.data(), payload.size, protocol::CrcCoverage::kHeaderExcluded);
    if (!frame) return;
    ros::Time stamp;
    stamp.fromNSec(static_cast<uint64_t>(start_ns + static_cast<int64_t>(t * 1e9)));
    const k40t_driver::Frame msg =
        driver::to_frame_msg(frame->data(), frame->size(), stamp, k40t_driver::Frame::RX);
    bag.write("/k40t/raw/rx", stamp + ros::Duration(0.001), msg);
    ++frames;
  };
  constexpr double kStep = 0.01;
  double next_target = 0;
  for (int i = 0; i * kStep < seconds; ++i) {
    const double t = i * kStep;
    pod.step(kStep);
    for (const sim::PeriodicReport* report : scheduler.due(pod, pod.now_s())) {
      Result<protocol::Payload> payload = report->encode(pod, codec);
      if (payload) write(report->id, payload.value(), t);
    }
    if (t >= next_target) {  // the answer to the driver's 1 Hz laser target request
      protocol::TargetGpsAck ack;
      ack.utc_time_ms =
          static_cast<uint64_t>(start_ns / 1'000'000) + static_cast<uint64_t>(t * 1000);
      ack.longitude_deg = 8.5456;
      ack.latitude_deg = 47.3977;
      ack.altitude_m = 420.0;
      Result<protocol::Payload> payload = protocol::encode_payload(ack, codec);
      if (payload) write(protocol::TargetGpsAck::kId, payload.value(), t);
      next_target += 1.0;
    }
  }
  return frames;
}

void decode(const std::string& input, const std::string& output, const char* label,
            std::vector<driver::FrameExport*> exports, double bag_seconds) {
  driver::BagDecodeOptions options;
  options.exports = std::move(exports);
  const Clock::time_point start = Clock::now();
  rosbag::Bag out(output, rosbag::bagmode::Write);
  Result<driver::BagDecodeSummary> summary = driver::decode_bag(input, out, options);
  out.close();
  const double elapsed = seconds_since(start);
  if (!summary) {
    std::printf("%s: failed: %s\n", label, summary.error().c_str());
    return;
  }
  std::printf("%s: %.2f s for %llu frames -> %llu messages (%.0f frames/s, %.0fx real time)\n",
              label, elapsed, static_cast<unsigned long long>(summary->rx_frames),
              static_cast<unsigned long long>(summary->messages_written),
              static_cast<double>(summary->rx_frames) / elapsed, bag_seconds / elapsed);
}

}  // namespace

int main(int argc, char** argv) {
  const double seconds = argc > 1 ? std::atof(argv[1]) : 3600.0;
  const std::string dir = argc > 2 ? argv[2] : "/tmp";
  const std::string stem = dir + "/k40t_bag_bench_" + std::to_string(::getpid());
  const std::string input = stem + ".bag";

  const Clock::time_point start = Clock::now();
  const uint64_t frames = write_traffic(input, seconds);
  std::printf(
      "synthetic traffic: %.0f s of pod time, %llu frames (%.1f frames/s), written in %.2f s\n",
      seconds, static_cast<unsigned long long>(frames), static_cast<double>(frames) / seconds,
      seconds_since(start));

  decode(input, stem + ".decoded.bag", "decode", {}, seconds);
  Result<std::unique_ptr<driver::FrameExport>> jsonl = driver::open_jsonl_export(stem + ".jsonl");
  if (jsonl) decode(input, stem + ".decoded.bag", "decode + --jsonl", {jsonl->get()}, seconds);

  for (const char* suffix : {".bag", ".decoded.bag", ".jsonl"}) ::unlink((stem + suffix).c_str());
  return 0;
}
