#include "k40t_driver/skyport/link_health.h"

#include <utility>

namespace k40t::driver::skyport {

LinkHealth link_health(const LinkHealthInput& in) {
  LinkHealth out;
  out.pod_stale = in.pod_age_s < 0 || in.pod_age_s > in.pod_stale_s;
  const BridgeStats& b = in.bridge;
  const auto set = [&out](HealthLevel level, std::string summary) {
    out.level = level;
    out.summary = std::move(summary);
    return out;
  };
  if (in.link != transport::LinkState::kConnected)
    return set(HealthLevel::kError, std::string("link ") + transport::to_string(in.link));
  if (in.silent_s < 0 || in.silent_s > in.silence_timeout_s)
    return set(HealthLevel::kError, "the SKYPORT adapter is silent");
  if (b.identity_requests == 0) return set(HealthLevel::kWarn, "no identity verification yet");
  if (b.identity_refused > 0 && b.identity_refused == b.identity_requests)
    return set(HealthLevel::kError, "identity verification refused");
  if (b.power_off_announced) return set(HealthLevel::kWarn, "the aircraft announces power-off");
  if (out.pod_stale)
    return set(HealthLevel::kWarn,
               "the pod's state is stale: getters answer from the last known state");
  return set(HealthLevel::kOk, "pushes arriving, identity answered");
}

}  // namespace k40t::driver::skyport
