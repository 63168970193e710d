#include "k40t_driver/driver/sbus_write.h"

namespace k40t::driver {

namespace {
constexpr const char* kPowerCycle =
    "; it takes effect after the pod is powered off and on again (section 3.2.6)";

std::string range_text(const protocol::SbusRangeRequest& range) {
  return std::to_string(range.min_value) + ".." + std::to_string(range.max_value);
}
}  // namespace

SbusWriteOutcome write_sbus(PodDriver& driver, const protocol::SbusRangeRequest& range,
                            const protocol::SbusChannelsRequest& channels) {
  SbusWriteOutcome out;
  // Both are checked before either is sent: half a configuration is worse than none.
  const Status valid = protocol::first_failure(range.validate(), channels.validate());
  if (!valid) {
    out.message = valid.message();
    return out;
  }
  // The range the pod holds now, to put back should the channels be refused.
  const Result<protocol::SbusConfigAck> before =
      driver.request_typed(protocol::SbusConfigRequest{});

  const session::AckResult range_result = driver.request(range);
  if (!range_result.ok()) {
    out.message =
        "nothing changed: the value range (0x000500) was refused: " + range_result.message +
        "; the channels (0x000501) were not sent";
    return out;
  }
  const session::AckResult channels_result = driver.request(channels);
  if (channels_result.ok()) {
    out.success = out.range_applied = out.channels_applied = out.power_cycle_needed = true;
    out.message = "ok: value range " + range_text(range) + " and channels set" + kPowerCycle;
    return out;
  }
  const std::string refused = "the channels (0x000501) were refused: " + channels_result.message;
  if (before) {
    const session::AckResult restored = driver.request(before->range);
    if (restored.ok()) {
      out.message = "nothing changed: " + refused + "; the value range was set back to " +
                    range_text(before->range);
      return out;
    }
  }
  out.range_applied = out.power_cycle_needed = true;
  out.message = "only the value range (0x000500) took effect (" + range_text(range) +
                "): " + refused + "; the previous range could not be restored" + kPowerCycle;
  return out;
}

}  // namespace k40t::driver
