// Every command the SKYPORT bridge's dispatch table handles has a golden frame written by hand
// (test/data/psdk_golden/*.txt), and so has its ACK when the document gives it one. The list comes
// from the table itself (Session::handled_commands() after the bridge registered), not from a
// count kept by hand. The pushes and transparent data SkyportRos registers are checked the same
// way by the rostest (test_skyport.py, the nodelet's ~handled_commands parameter).
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>

#include "k40t_driver/psdk/catalogue.h"
#include "psdk_fake_transport.h"
#include "psdk_golden_frames.h"
#include "skyport_bridge_rig.h"

namespace k40t::driver::skyport {
namespace {

using namespace bridge_testing;

std::string key_text(CommandKey key, PacketType packet) {
  char text[32];
  std::snprintf(text, sizeof(text), "0x%02X/0x%02X%s", key.set, key.id,
                packet == PacketType::kAck ? " ACK" : "");
  return text;
}

TEST(SkyportGoldenCoverage, EveryHandledCommandAndItsAckHasAGoldenFrame) {
  auto link = std::make_unique<FakeLink>();
  Session session(std::move(link), SessionOptions{});
  FakePod pod;
  BridgeOptions options;
  options.app_key = kCredentials.app_key;
  SkyportBridge bridge(session, pod, options, nullptr, nullptr);

  const std::vector<CommandKey> handled = session.handled_commands();
  ASSERT_GT(handled.size(), 40u) << "the bridge registered (almost) nothing";
  const std::set<psdk::test::GoldenKey> golden = psdk::test::psdk_golden_keys();
  for (const CommandKey key : handled) {
    const CommandInfo* command = find_command(key, PacketType::kCommand);
    ASSERT_NE(command, nullptr) << key_text(key, PacketType::kCommand)
                                << " is not in the catalogue";
    EXPECT_TRUE(golden.count({key.set, key.id, 0}))
        << command->name << " (" << key_text(key, PacketType::kCommand)
        << ") is handled but has no golden frame in test/data/psdk_golden";
    if (command->acked) {
      EXPECT_TRUE(golden.count({key.set, key.id, 1}))
          << command->name << " ACK (" << key_text(key, PacketType::kAck)
          << ") is sent but has no golden frame in test/data/psdk_golden";
    }
  }
}

}  // namespace
}  // namespace k40t::driver::skyport
