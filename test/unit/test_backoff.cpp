// The reconnect delay sequence and the policy checks.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "k40t_driver/transport/backoff.h"

namespace k40t::transport {
namespace {

using std::chrono::milliseconds;

TEST(Backoff, GrowsByTheFactorUpToTheCapAndResets) {
  ReconnectPolicy policy;
  policy.initial_delay = milliseconds(100);
  policy.max_delay = milliseconds(1000);
  policy.factor = 3.0;
  Backoff backoff(policy);
  EXPECT_EQ(backoff.next(), milliseconds(100));
  EXPECT_EQ(backoff.next(), milliseconds(300));
  EXPECT_EQ(backoff.next(), milliseconds(900));
  EXPECT_EQ(backoff.next(), milliseconds(1000));
  EXPECT_EQ(backoff.next(), milliseconds(1000));
  backoff.reset();
  EXPECT_EQ(backoff.next(), milliseconds(100));
}

TEST(Backoff, FactorOneKeepsTheDelay) {
  ReconnectPolicy policy;
  policy.initial_delay = milliseconds(50);
  policy.factor = 1.0;
  Backoff backoff(policy);
  for (int i = 0; i < 5; ++i) EXPECT_EQ(backoff.next(), milliseconds(50));
}

TEST(Backoff, PolicyChecksNameTheBadField) {
  EXPECT_TRUE(check_policy(ReconnectPolicy{}));
  ReconnectPolicy zero;
  zero.initial_delay = milliseconds(0);
  EXPECT_THAT(check_policy(zero).message(), ::testing::HasSubstr("initial_delay"));
  ReconnectPolicy inverted;
  inverted.max_delay = milliseconds(10);
  EXPECT_THAT(check_policy(inverted).message(), ::testing::HasSubstr("max_delay"));
  ReconnectPolicy shrinking;
  shrinking.factor = 0.5;
  EXPECT_THAT(check_policy(shrinking).message(), ::testing::HasSubstr("factor"));
}

TEST(Backoff, OpenRefusesABadPolicy) {
  auto made = make_transport("udp://127.0.0.1:5000");
  ASSERT_TRUE(made) << made.error();
  ReconnectPolicy shrinking;
  shrinking.factor = 0.5;
  (*made)->set_reconnect_policy(shrinking);
  const Status opened = (*made)->open();
  ASSERT_FALSE(opened);
  EXPECT_THAT(opened.message(), ::testing::HasSubstr("udp://127.0.0.1:5000"));
  EXPECT_EQ((*made)->state(), LinkState::kClosed);
}

}  // namespace
}  // namespace k40t::transport
