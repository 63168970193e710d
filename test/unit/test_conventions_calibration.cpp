// calibration_end end to end (docs/protocol/decisions.md#conventions): a gimbal calibration goal
// (the ROS-free operation the gimbal/calibrate action runs, fed as the action feeds it) against a
// simulator that reports calibrations in 0x000008 (status) or ends them with the ACK (ack).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "conventions_rig.h"
#include "k40t_driver/operations/gimbal_operations.h"

namespace k40t::driver::testing {
namespace {

namespace p = protocol;
using operations::GimbalCalibration;
using operations::Phase;

// One calibration goal, fed as the gimbal/calibrate action feeds it.
class CalibrationGoal {
 public:
  // Registers the status handler (before the driver starts).
  void attach(PodDriver& driver) {
    driver.on<p::CameraUpgradeStatus>([this](const p::CameraUpgradeStatus& m, StampNs) {
      std::lock_guard<std::mutex> lock(mutex_);
      if (op_) op_->on_status(m);
    });
  }
  // Runs one drift calibration with the driver's calibration_end; returns how it ended.
  // `poll` runs at every look at the goal (every few ms) until it ends.
  operations::OperationTracker run(PodDriver& driver, const std::function<void()>& poll = {}) {
    Result<GimbalCalibration> created =
        GimbalCalibration::create(0, 0, ConventionTracker::steady_now_s(),
                                  driver.conventions().conventions().calibration_end);
    EXPECT_TRUE(created);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      op_ = std::move(created.value());
    }
    driver.request_async(p::GimbalDriftCalibrationRequest{}, [this](const session::AckResult& a) {
      std::lock_guard<std::mutex> lock(mutex_);
      op_->tracker().acknowledged(a.ok(), a.message);
    });
    EXPECT_TRUE(test::eventually([&] {
      if (poll) poll();
      std::lock_guard<std::mutex> lock(mutex_);
      return op_->tracker().check(ConventionTracker::steady_now_s()) != Phase::kRunning;
    }));
    std::lock_guard<std::mutex> lock(mutex_);
    return op_->tracker();
  }

 private:
  std::mutex mutex_;
  std::optional<GimbalCalibration> op_;
};

struct CalibrationRig {
  CalibrationRig(const std::vector<std::string>& pod, const std::vector<std::string>& driver)
      : rig(pod, driver, {}, [this](PodDriver& d) { goal.attach(d); }) {}
  operations::OperationTracker calibrate(const std::function<void()>& poll = {}) {
    return goal.run(rig.driver(), poll);
  }
  CalibrationGoal goal;  // before rig: the driver's handler uses it
  ConventionsRig rig;
};

TEST(ConventionsCalibration, AutoEndsWithAPodThatOnlyAcks) {
  CalibrationRig c({"calibration_end=ack"}, {});
  const operations::OperationTracker done = c.calibrate();
  EXPECT_EQ(done.phase(), Phase::kSucceeded) << done.reason();
  EXPECT_NE(done.reason().find("calibration_end: auto"), std::string::npos) << done.reason();
  EXPECT_TRUE(test::eventually([&] {
    return c.rig.reading("calibration_end").source.find("the pod's reading: ack") !=
           std::string::npos;
  })) << c.rig.reading("calibration_end").source;
}

TEST(ConventionsCalibration, AckEndsAtTheAck) {
  CalibrationRig c({"calibration_end=ack"}, {"calibration_end=ack"});
  const operations::OperationTracker done = c.calibrate();
  EXPECT_EQ(done.phase(), Phase::kSucceeded) << done.reason();
  EXPECT_EQ(done.status_text(), "");  // no 0x000008 came
}

TEST(ConventionsCalibration, AutoFollows0x000008WhenThePodSendsIt) {
  CalibrationRig c({"calibration_end=status"}, {});
  const operations::OperationTracker done = c.calibrate();
  EXPECT_EQ(done.phase(), Phase::kSucceeded) << done.reason();
  EXPECT_GT(done.reports(), 1);  // "repairing" frames, then "succeeded" ended it
  EXPECT_EQ(done.reason(), "gimbal drift calibration: done");
}

// Issue 21's "Done when": the driver with the pod's reading (what `k40t probe --calibration`
// writes) ends the goal within 2 s of the end of the calibration in the simulated pod (its model:
// the truth). A pod whose calibrations end with their ACK sends that ACK when it is done.
TEST(ConventionsCalibration, TheGoalEndsWithin2SOfThePodsEndUnderEachReading) {
  using Clock = std::chrono::steady_clock;
  for (const char* reading : {"ack", "status"}) {
    const std::string c = std::string("calibration_end=") + reading;
    CalibrationRig rig({c}, {c});
    std::optional<Clock::time_point> pod_end;
    bool pod_started = false;
    const operations::OperationTracker done = rig.calibrate([&] {
      bool calibrating = false;
      rig.rig.pod().with_model([&](sim::PodModel& m) { calibrating = m.gimbal().calibrating(); });
      pod_started = pod_started || calibrating;
      if (pod_started && !calibrating && !pod_end) pod_end = Clock::now();
    });
    const Clock::time_point goal_end = Clock::now();
    EXPECT_EQ(done.phase(), Phase::kSucceeded) << reading << ": " << done.reason();
    ASSERT_TRUE(pod_started) << reading;
    // The goal may end before the poll sees the pod's end (the ACK left in the same step): then
    // the pod's end is now.
    const Clock::time_point end = pod_end.value_or(goal_end);
    const double apart_s = std::chrono::duration<double>(goal_end - end).count();
    EXPECT_LT(std::abs(apart_s), 2.0)
        << reading << ": the goal ended " << apart_s << " s after the pod's calibration";
    if (!pod_end) {
      bool calibrating = true;
      rig.rig.pod().with_model([&](sim::PodModel& m) { calibrating = m.gimbal().calibrating(); });
      EXPECT_FALSE(calibrating) << reading << ": the goal ended while the pod still calibrates";
    }
  }
}

TEST(ConventionsCalibration, StatusAgainstAPodThatOnlyAcksIsNamed) {
  ConventionsRig rig({"calibration_end=ack"}, {"calibration_end=status"});
  rig.driver().request_async(p::GimbalDriftCalibrationRequest{}, [](const session::AckResult&) {});
  ASSERT_TRUE(rig.contradicts("calibration_end"));
  EXPECT_NE(rig.reading("calibration_end").contradiction.find("no 0x000008 'repairing'"),
            std::string::npos);
}

}  // namespace
}  // namespace k40t::driver::testing
