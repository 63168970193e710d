// calibration_end end to end (docs/protocol/decisions.md#conventions): a gimbal calibration goal
// (the ROS-free operation the gimbal/calibrate action runs, fed as the action feeds it) against a
// simulator that reports calibrations in 0x000008 (status) or ends them with the ACK (ack).
#include <gtest/gtest.h>

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
  operations::OperationTracker run(PodDriver& driver) {
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
  operations::OperationTracker calibrate() { return goal.run(rig.driver()); }
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

TEST(ConventionsCalibration, StatusAgainstAPodThatOnlyAcksIsNamed) {
  ConventionsRig rig({"calibration_end=ack"}, {"calibration_end=status"});
  rig.driver().request_async(p::GimbalDriftCalibrationRequest{}, [](const session::AckResult&) {});
  ASSERT_TRUE(rig.contradicts("calibration_end"));
  EXPECT_NE(rig.reading("calibration_end").contradiction.find("no 0x000008 'repairing'"),
            std::string::npos);
}

}  // namespace
}  // namespace k40t::driver::testing
