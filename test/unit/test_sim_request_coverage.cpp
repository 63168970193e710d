// Every request of NOTES.md's catalogue has a handler in the simulated pod, and every handler
// checks the payload length first. The requests are the catalogue's host-to-pod requests (the
// catalogue itself is checked against NOTES.md by test_catalogue_completeness.cpp).
#include <gtest/gtest.h>

#include <vector>

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
  // 12 gimbal, 15 thermal, 12 visible, 23 common camera, 2 laser, 3 SBUS, and 0x000320.
  EXPECT_EQ(requests.size(), 68u);
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

}  // namespace
}  // namespace k40t::sim
