// Laser (section 3.2.5) and SBUS (3.2.6) requests.
#include "handler_support.h"
#include "k40t_driver/protocol/messages/laser.h"
#include "k40t_driver/protocol/messages/sbus.h"

namespace k40t::sim {

namespace {

using namespace handlers;
namespace p = protocol;

p::LaserRangeAck single_range(RequestContext& ctx, const p::LaserRangeRequest& req) {
  p::LaserRangeAck ack;
  if (!req.enable) return ack;  // "0: disable": nothing measured
  // No return (sky, beyond range) is reported as distance 0, with an OK code ("no value: 0").
  ack.distance_m = ctx.pod.laser_range().value_or(0.0);
  return ack;
}

p::SbusConfigAck sbus_config(RequestContext& ctx, const p::SbusConfigRequest&) {
  const SbusSettings& s = ctx.pod.sbus();
  p::SbusConfigAck ack;
  ack.range.max_value = s.max_value;
  ack.range.min_value = s.min_value;
  // The model keeps the wire's 0..15; the struct holds channel numbers 1..16.
  int* channels[] = {&ack.channels.stream_channel, &ack.channels.zoom_channel,
                     &ack.channels.photo_channel,  &ack.channels.record_channel,
                     &ack.channels.pitch_channel,  &ack.channels.yaw_channel,
                     &ack.channels.centre_channel};
  for (size_t i = 0; i < s.channels.size(); ++i) *channels[i] = s.channels[i] + 1;
  return ack;
}

Outcome sbus_channels(PodModel& pod, const p::SbusChannelsRequest& req) {
  const int numbers[] = {req.stream_channel, req.zoom_channel,  req.photo_channel,
                         req.record_channel, req.pitch_channel, req.yaw_channel,
                         req.centre_channel};
  std::array<uint8_t, 7> channels{};
  for (size_t i = 0; i < channels.size(); ++i) channels[i] = static_cast<uint8_t>(numbers[i] - 1);
  return pod.set_sbus_channels(channels);
}

}  // namespace

void add_laser_sbus_handlers(std::vector<HandlerEntry>& out) {
  out.push_back(with_data<p::LaserRangeRequest>(single_range));
  out.push_back(store<p::LaserPeriodicRangeRequest>(
      [](PodModel& pod, const p::LaserPeriodicRangeRequest& req) {
        pod.laser().set_periodic(req.enable);
      }));
  out.push_back(plain<p::SbusRangeRequest>([](PodModel& pod, const p::SbusRangeRequest& req) {
    return pod.set_sbus_range(req.max_value, req.min_value);
  }));
  out.push_back(plain<p::SbusChannelsRequest>(sbus_channels));
  out.push_back(with_data<p::SbusConfigRequest>(sbus_config));
}

}  // namespace k40t::sim
