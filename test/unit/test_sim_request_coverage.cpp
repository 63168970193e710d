// Every request of the catalogue has a handler in the simulated pod, and every handler
// checks the payload length first. The requests are the catalogue's host-to-pod requests (the
// catalogue itself is checked against the docs/protocol/ message tables by
// test_catalogue_completeness.cpp).
#include <gtest/gtest.h>

#include <random>
#include <set>
#include <vector>

#include "docs_message_tables.h"
#include "k40t_driver/protocol/catalogue.h"
#include "sim_pod_harness.h"

namespace k40t::sim {
namespace {

namespace p = protocol;

std::vector<p::MessageId> host_requests() {
  std::vector<p::MessageId> ids;
  for (const p::MessageInfo& info : p::catalogue()) {
    if (p::kind_of(info.id) == p::MessageKind::kRequestOrReport &&
        !p::is_periodic_report(info.id) && info.direction == p::Direction::kHostToPod) {
      ids.push_back(info.id);
    }
  }
  return ids;
}

TEST(SimRequestCoverage, EveryNotesRequestHasAHandler) {
  const auto requests = host_requests();
  // Exactly the docs tables' requests to the pod: all of them but the pod's own GPS request.
  const std::vector<p::MessageId> documented =
      k40t::testing::docs_request_ids(k40t::testing::load_docs_messages());
  std::set<p::MessageId> expected(documented.begin(), documented.end());
  expected.erase(0x000310);
  EXPECT_EQ(std::set<p::MessageId>(requests.begin(), requests.end()), expected);
  for (p::MessageId id : requests) EXPECT_NE(find_request_handler(id), nullptr) << std::hex << id;
  EXPECT_EQ(request_handlers().size(), requests.size());  // and nothing the document lacks
  // The pod's own GPS request goes the other way: the pod never answers it.
  EXPECT_EQ(find_request_handler(0x000310), nullptr);
}

TEST(SimRequestCoverage, AnEmptyPayloadIsALengthMismatchForEveryRequest) {
  testing::PodHarness h;
  for (p::MessageId id : host_requests()) {
    const auto ack = h.raw(id, {});
    ASSERT_TRUE(ack) << std::hex << id;
    EXPECT_EQ(p::ack_response_code(ack->data(), ack->size, h.codec),
              p::ResponseCode::kLengthMismatch)
        << std::hex << id;
  }
}

TEST(SimRequestCoverage, RandomPayloadsAlwaysGetAnAckAndNeverBreakTheModel) {
  testing::PodHarness h;
  std::mt19937 rng(2024);
  const auto requests = host_requests();
  for (int round = 0; round < 3000; ++round) {
    const p::MessageId id = requests[rng() % requests.size()];
    std::vector<uint8_t> payload(rng() % 64);
    for (auto& b : payload) b = static_cast<uint8_t>(rng());
    // Section 3.2.4.1 note: no answer to a photo request in video mode, a record one in photo mode.
    const CaptureMode mode = h.pod.camera().settings().capture_mode;
    const bool other_mode = (id == 0x000303 && mode == CaptureMode::kPhoto) ||
                            ((id == 0x000302 || id == 0x000307) && mode == CaptureMode::kVideo);
    const auto ack = h.raw(id, payload);
    if (!h.pod.camera_available() && id > 0x0000FF) {
      EXPECT_FALSE(ack) << std::hex << id;  // shut down or rebooting: silence
    } else if (other_mode && !ack) {
      // silence, as documented (a payload too short still gets its length mismatch)
    } else {
      ASSERT_TRUE(ack) << std::hex << id;
      EXPECT_GE(ack->size, 2u);
    }
    h.run(0.02);
  }
  // Whatever happened, the pod still reports sensible numbers.
  const GimbalPose pose = h.pod.gimbal().pose();
  EXPECT_GE(pose.joint_deg.pitch, -90);
  EXPECT_LE(pose.joint_deg.pitch, 30);
  EXPECT_GE(h.pod.zoom().zoom(), 1);
  EXPECT_LE(h.pod.zoom().zoom(), 160);
  EXPECT_LE(h.pod.camera().sd().used_mb(), h.pod.camera().sd().capacity_mb());
}

}  // namespace
}  // namespace k40t::sim
