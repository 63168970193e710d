// The camera's long operations without ROS: zoom to a ratio, SD format, precise re-shoot and
// TF-card upgrade, each ended by the status frame the document gives it (section 3.2.4, the
// structs of protocol/messages/camera_status.h). Each class validates its goal into the request
// (nothing is sent for a bad goal), turns status frames into steps of its OperationTracker and
// keeps the figures its feedback reports.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "k40t_driver/operations/operation_tracker.h"
#include "k40t_driver/protocol/messages/camera_capture.h"
#include "k40t_driver/protocol/messages/camera_reports.h"
#include "k40t_driver/protocol/messages/camera_status.h"
#include "k40t_driver/protocol/messages/camera_system.h"
#include "k40t_driver/protocol/messages/visible.h"
#include "k40t_driver/protocol/result.h"

namespace k40t::operations {

// What each status frame says (unit-tested one state at a time).
Step zoom_step(const protocol::ZoomStatus& status);                 // 0x020304
Step sd_format_step(const protocol::SdFormatStatus& status);        // 0x02030D
Step reshoot_step(const protocol::PreciseReshootStatus& status);    // 0x020307
Step tf_upgrade_step(const protocol::TfCardUpgradeStatus& status);  // 0x02030C

// 0x000304. It has arrived when 0x000005 (5 Hz) reports the ratio asked for, whether or not a
// 0x020304 "done" came: the document does not say that one comes for a zoom to the ratio the pod
// is at (decisions.md#periodic-reports). A "done" at another ratio (a pod that clamps, or
// supports fewer ratios, section 3.2.4.5: "倍率为相机实际支持倍率") fails once kReportsAfterDone
// reports after it still show another ratio (the first may predate the end), naming both.
class ZoomTo : public TrackedOperation {
 public:
  static constexpr double kDefaultTimeoutS = 15;  // 1x -> 160x takes about 4 s
  static constexpr int kReportsAfterDone = 3;     // 0.6 s of 0x000005

  static Result<ZoomTo> create(double ratio_x, double timeout_s, double now_s);
  const protocol::ZoomRatioRequest& request() const { return request_; }
  void on_status(const protocol::ZoomStatus& status);
  void on_visible(const protocol::VisibleStatus& status);
  std::optional<double> ratio_x() const { return ratio_x_; }

 private:
  ZoomTo(const protocol::ZoomRatioRequest& request, double timeout_s, double now_s);
  bool arrived() const;  // the latest 0x000005 shows the ratio sent (0.1x steps)
  protocol::ZoomRatioRequest request_;
  std::optional<double> ratio_x_;
  int reports_after_done_ = -1;  // -1: no "done" yet
};

// 0x00030D, ended by 0x02030D "done" (5 Hz while formatting). The frame carries no percentage:
// progress is the state, the frames seen and the time.
class SdFormat : public TrackedOperation {
 public:
  static constexpr double kDefaultTimeoutS = 60;

  static Result<SdFormat> create(double timeout_s, double now_s);
  void on_status(const protocol::SdFormatStatus& status) {
    tracker().report(sd_format_step(status));
  }

 private:
  SdFormat(double timeout_s, double now_s);
};

// A precise re-shoot in physical units, shared by the precise_reshoot service and action. 0 for
// the zoom or the focal value means "the current one": the latest visible report (0x000005).
struct ReshootArgs {
  uint8_t lens = 0;            // PhotoLensMode code 0..3
  uint8_t resolution = 0;      // ReshootResolution code 0x14..0x17
  double zoom_ratio = 0;       // 1..160; 0: the latest 0x000005's
  double focal_length_mm = 0;  // 0..655.35; 0: the latest 0x000005's "accurate shoot focal length"
  std::string folder;
  std::string name;
};
// The focal value of 0x000307 bytes 5-6 is what 0x000005 bytes 13-14 report (the document gives
// neither a unit; both are read as 0.01 mm, docs/protocol/camera.md), so a value copied from
// visible/status goes back to the pod as the very same uint16.
constexpr double kReshootFocalUnitsPerMm = 100.0;
// -> 0x000307; `latest` is the newest visible report. Fails naming the field and its range.
Result<protocol::PreciseReshootRequest> reshoot_request(
    const ReshootArgs& args, const std::optional<protocol::VisibleStatus>& latest);

struct PreciseReshootGoal {
  ReshootArgs args;
  double timeout_s = 0;
};

// 0x000307, ended by 0x020307 "done" (state 0) or a failure state.
class PreciseReshoot : public TrackedOperation {
 public:
  static constexpr double kDefaultTimeoutS = 30;  // waits for the zoom, then one photo

  // `latest_visible`: the last 0x000005 received, if any (needed when focal_length_mm is 0).
  static Result<PreciseReshoot> create(const PreciseReshootGoal& goal,
                                       const std::optional<protocol::VisibleStatus>& latest_visible,
                                       double now_s);
  const protocol::PreciseReshootRequest& request() const { return request_; }
  void on_status(const protocol::PreciseReshootStatus& status) {
    tracker().report(reshoot_step(status));
  }

 private:
  PreciseReshoot(const protocol::PreciseReshootRequest& request, double timeout_s, double now_s);
  protocol::PreciseReshootRequest request_;
};

// 0x00030C, ended by 0x02030C "succeeded"/"failed"; the percentage comes from 0x000008
// "upgrading" (1 Hz).
class TfUpgrade : public TrackedOperation {
 public:
  static constexpr double kDefaultTimeoutS = 600;  // a firmware upgrade may take minutes

  static Result<TfUpgrade> create(double timeout_s, double now_s);
  void on_status(const protocol::TfCardUpgradeStatus& status) {
    tracker().report(tf_upgrade_step(status));
  }
  void on_progress(const protocol::CameraUpgradeStatus& status);
  int progress_percent() const { return progress_percent_; }  // -1: none reported yet

 private:
  TfUpgrade(double timeout_s, double now_s);
  int progress_percent_ = -1;
};

}  // namespace k40t::operations
