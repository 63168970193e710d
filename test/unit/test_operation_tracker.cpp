// OperationTracker: the decisions every action shares (ACK, status steps, timeout, cancel).
#include <gtest/gtest.h>

#include <chrono>
#include <limits>
#include <thread>

#include "k40t_driver/operations/operation_tracker.h"
#include "k40t_driver/operations/shared_operation.h"

namespace k40t::operations {
namespace {

Step running(const char* text) {
  return Step{Phase::kRunning, text};
}
Step succeeded(const char* text) {
  return Step{Phase::kSucceeded, text};
}
Step failed(const char* text) {
  return Step{Phase::kFailed, text};
}

TEST(OperationTracker, SucceedsOnTheEndStatusAfterTheAck) {
  OperationTracker t("SD format", "0x02030D 'done'", 10, 100);
  t.acknowledged(true, "ok");
  t.report(running("formatting"));
  EXPECT_EQ(t.check(101), Phase::kRunning);
  EXPECT_EQ(t.status_text(), "formatting");
  t.report(succeeded("format done"));
  EXPECT_EQ(t.check(102), Phase::kSucceeded);
  EXPECT_EQ(t.reason(), "SD format: format done");
  EXPECT_EQ(t.reports(), 2);
}

TEST(OperationTracker, AnEndBeforeTheAckWaitsForTheAck) {
  OperationTracker t("zoom", "0x020304 'done'", 10, 0);
  t.report(succeeded("done"));
  EXPECT_EQ(t.phase(), Phase::kRunning);
  t.acknowledged(true, "ok");
  EXPECT_EQ(t.phase(), Phase::kSucceeded);
}

TEST(OperationTracker, AnEndBeforeARefusalIsAFailure) {
  OperationTracker t("zoom", "0x020304 'done'", 10, 0);
  t.report(succeeded("done"));
  t.acknowledged(false, "busy (0x0008)");
  EXPECT_EQ(t.phase(), Phase::kFailed);
  EXPECT_EQ(t.reason(), "zoom refused or not acknowledged: busy (0x0008)");
}

TEST(OperationTracker, AFailureStateEndsIt) {
  OperationTracker t("SD format", "x", 10, 0);
  t.acknowledged(true, "ok");
  t.report(failed("SD card unavailable"));
  EXPECT_EQ(t.phase(), Phase::kFailed);
  EXPECT_EQ(t.reason(), "SD format failed: SD card unavailable");
}

TEST(OperationTracker, TimesOutNamingWhatWasAwaitedAndTheLastStatus) {
  OperationTracker t("SD format", "SD format status 0x02030D 'done'", 2, 50);
  t.acknowledged(true, "ok");
  t.report(running("formatting"));
  EXPECT_EQ(t.check(51.99), Phase::kRunning);
  EXPECT_EQ(t.check(52.0), Phase::kTimedOut);
  EXPECT_EQ(t.reason(),
            "SD format timed out after 2.0 s waiting for SD format status 0x02030D 'done' (last "
            "status 'formatting')");
}

TEST(OperationTracker, TimeoutSaysWhenNothingCameBack) {
  OperationTracker no_ack("zoom", "done", 1, 0);
  no_ack.check(1);
  EXPECT_NE(no_ack.reason().find("the request was not acknowledged yet"), std::string::npos);
  OperationTracker no_status("zoom", "done", 1, 0);
  no_status.acknowledged(true, "ok");
  no_status.check(1);
  EXPECT_NE(no_status.reason().find("no status frame received"), std::string::npos);
}

TEST(OperationTracker, NothingChangesAfterTheEnd) {
  OperationTracker t("zoom", "done", 1, 0);
  t.cancel("zoom stopped");
  EXPECT_EQ(t.phase(), Phase::kCancelled);
  EXPECT_EQ(t.reason(), "zoom cancelled: zoom stopped");
  t.acknowledged(true, "ok");
  t.report(succeeded("done"));
  EXPECT_EQ(t.check(5), Phase::kCancelled);
  EXPECT_EQ(t.reason(), "zoom cancelled: zoom stopped");
  EXPECT_EQ(t.reports(), 0);
}

TEST(ChooseTimeout, ZeroIsTheDefaultNegativeAndNanAreErrors) {
  EXPECT_TRUE(choose_timeout(0, 30).ok);
  EXPECT_EQ(choose_timeout(0, 30).seconds, 30);
  EXPECT_EQ(choose_timeout(2.5, 30).seconds, 2.5);
  const TimeoutChoice negative = choose_timeout(-1, 30);
  EXPECT_FALSE(negative.ok);
  EXPECT_NE(negative.error.find("field 'timeout'"), std::string::npos);
  EXPECT_NE(negative.error.find("30.0 s"), std::string::npos);
  EXPECT_FALSE(choose_timeout(std::numeric_limits<double>::quiet_NaN(), 30).ok);
  EXPECT_FALSE(choose_timeout(std::numeric_limits<double>::infinity(), 30).ok);
}

TEST(SharedOperation, AnUpdateWakesTheWaiterAtOnce) {
  SharedOperation<OperationTracker> shared(OperationTracker("zoom", "done", 10, 0));
  std::thread feeder([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    shared.update([](OperationTracker& t) {
      t.report(Step{Phase::kRunning, "zooming"});
      return 0;
    });
  });
  // A wait of 10 s returns with the update, not after 10 s (the test would hit its own limit).
  const uint64_t changes = shared.wait_for_change(0, std::chrono::seconds(10));
  feeder.join();
  EXPECT_EQ(changes, 1u);
  EXPECT_EQ(shared.read([](const OperationTracker& t) { return t.status_text(); }), "zooming");
}

TEST(SharedOperation, InspectDoesNotWakeTheWaiter) {
  SharedOperation<OperationTracker> shared(OperationTracker("zoom", "done", 10, 0));
  shared.inspect([](OperationTracker& t) { return t.check(1); });
  EXPECT_EQ(shared.wait_for_change(0, std::chrono::milliseconds(10)), 0u);
}

}  // namespace
}  // namespace k40t::operations
