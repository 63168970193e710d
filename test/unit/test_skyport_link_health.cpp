// The SKYPORT bridge's diagnostic summary (link_health.h): each condition in its order, starting
// from a healthy bridge and breaking one thing at a time.
#include <gtest/gtest.h>

#include "k40t_driver/skyport/link_health.h"

namespace k40t::driver::skyport {
namespace {

LinkHealthInput healthy() {
  LinkHealthInput in;
  in.link = transport::LinkState::kConnected;
  in.silent_s = 0.2;
  in.silence_timeout_s = 1.0;
  in.bridge.identity_requests = 1;
  in.pod_age_s = 0.5;
  in.pod_stale_s = 3.0;
  return in;
}

TEST(LinkHealth, HealthyBridgeIsOk) {
  const LinkHealth h = link_health(healthy());
  EXPECT_EQ(h.level, HealthLevel::kOk);
  EXPECT_EQ(h.summary, "pushes arriving, identity answered");
  EXPECT_FALSE(h.pod_stale);
}

TEST(LinkHealth, LinkDownOrAdapterSilentIsAnError) {
  LinkHealthInput in = healthy();
  in.link = transport::LinkState::kReconnecting;
  EXPECT_EQ(link_health(in).level, HealthLevel::kError);
  EXPECT_EQ(link_health(in).summary,
            std::string("link ") + transport::to_string(transport::LinkState::kReconnecting));
  in = healthy();
  in.silent_s = 1.5;  // over the 1 s timeout
  EXPECT_EQ(link_health(in).summary, "the SKYPORT adapter is silent");
  EXPECT_EQ(link_health(in).level, HealthLevel::kError);
  in.silent_s = -1;  // no frame yet
  EXPECT_EQ(link_health(in).level, HealthLevel::kError);
  in.silent_s = 1.0;  // exactly the timeout: not yet silent
  EXPECT_EQ(link_health(in).level, HealthLevel::kOk);
}

TEST(LinkHealth, IdentityNotYetAskedWarnsAndAllRefusedIsAnError) {
  LinkHealthInput in = healthy();
  in.bridge.identity_requests = 0;
  EXPECT_EQ(link_health(in).level, HealthLevel::kWarn);
  EXPECT_EQ(link_health(in).summary, "no identity verification yet");
  in.bridge.identity_requests = 2;
  in.bridge.identity_refused = 2;
  EXPECT_EQ(link_health(in).level, HealthLevel::kError);
  EXPECT_EQ(link_health(in).summary, "identity verification refused");
  in.bridge.identity_refused = 1;  // one of two answered: fine
  EXPECT_EQ(link_health(in).level, HealthLevel::kOk);
}

TEST(LinkHealth, PowerOffThenStalePodWarn) {
  LinkHealthInput in = healthy();
  in.bridge.power_off_announced = true;
  in.pod_age_s = 10;  // stale too: power-off is told first
  const LinkHealth power_off = link_health(in);
  EXPECT_EQ(power_off.level, HealthLevel::kWarn);
  EXPECT_EQ(power_off.summary, "the aircraft announces power-off");
  EXPECT_TRUE(power_off.pod_stale);
  in.bridge.power_off_announced = false;
  EXPECT_EQ(link_health(in).summary,
            "the pod's state is stale: getters answer from the last known state");
  in.pod_age_s = -1;  // never heard from the pod
  EXPECT_TRUE(link_health(in).pod_stale);
  EXPECT_EQ(link_health(in).level, HealthLevel::kWarn);
}

TEST(LinkHealth, AnErrorHidesTheWarnings) {
  LinkHealthInput in = healthy();
  in.link = transport::LinkState::kClosed;
  in.bridge.identity_requests = 0;
  in.pod_age_s = -1;
  EXPECT_EQ(link_health(in).level, HealthLevel::kError);
  EXPECT_TRUE(link_health(in).pod_stale);
}

}  // namespace
}  // namespace k40t::driver::skyport
