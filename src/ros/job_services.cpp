#include "k40t_driver/ros/job_services.h"

#include <cmath>

#include <std_srvs/Trigger.h>

#include "k40t_driver/PreciseReshoot.h"
#include "k40t_driver/protocol/messages/camera_system.h"
#include "k40t_driver/ros/service_support.h"

namespace k40t::driver {

namespace p = protocol;

namespace {
// The focal value of 0x000307 bytes 5-6 is what 0x000005 bytes 13-14 report (the document gives
// neither a unit; both are read as 0.01 mm, docs/protocol/camera.md), so a value copied from
// visible/status goes back to the pod as the very same uint16.
constexpr double kFocalUnitsPerMm = 100.0;
constexpr double kMaxFocalMm = 65535 / kFocalUnitsPerMm;
}  // namespace

Result<p::PreciseReshootRequest> reshoot_request(const ReshootArgs& args,
                                                 const std::optional<p::VisibleStatus>& latest) {
  using R = Result<p::PreciseReshootRequest>;
  const bool current_zoom = args.zoom_ratio == 0;
  const bool current_focal = args.focal_length_mm == 0;
  if ((current_zoom || current_focal) && !latest) {
    return R::fail(std::string("field '") + (current_zoom ? "zoom_ratio" : "focal_length_mm") +
                   "' is 0 (the current value) but no visible/status report (0x000005) has come "
                   "yet: give it explicitly");
  }
  const double focal_mm =
      current_focal ? latest->precise_shot_focal_length_mm : args.focal_length_mm;
  const double zoom = current_zoom ? latest->zoom_x : args.zoom_ratio;
  const Status range =
      p::first_failure(p::check_range("zoom_ratio", zoom, 1.0, 160.0, "x"),
                       p::check_range("focal_length_mm", focal_mm, 0.0, kMaxFocalMm, "mm"));
  if (!range) return R::fail(range.message());
  p::PreciseReshootRequest r;
  r.lens = static_cast<p::PhotoLensMode>(args.lens);
  r.resolution = static_cast<p::ReshootResolution>(args.resolution);
  r.zoom_x = zoom;
  r.focal_length_raw = static_cast<uint16_t>(std::lround(focal_mm * kFocalUnitsPerMm));
  r.folder = args.folder;
  r.name = args.name;
  const Status valid = r.validate();  // lens, resolution, zoom, folder and name
  if (!valid) return R::fail(valid.message());
  return r;
}

JobServices::JobServices(ros::NodeHandle nh, PodDriver& driver) : nh_(nh), driver_(driver) {
  driver_.on<p::VisibleStatus>([this](const p::VisibleStatus& status, StampNs) {
    std::lock_guard<std::mutex> lock(mutex_);
    visible_ = status;
  });
  advertise_service<k40t_driver::PreciseReshoot>(
      nh_, servers_, "precise_reshoot", [this](auto& req, auto& res) {
        ReshootArgs args;
        args.lens = req.lens;
        args.resolution = req.resolution;
        args.zoom_ratio = req.zoom_ratio;
        args.focal_length_mm = req.focal_length_mm;
        args.folder = req.folder;
        args.name = req.name;
        const Result<p::PreciseReshootRequest> request = reshoot_request(args, latest_visible());
        if (!request) return fail(res, request.error());
        res.zoom_ratio = request->zoom_x;
        res.focal_length_mm = request->focal_length_raw / kFocalUnitsPerMm;
        fill(res, driver_.request(request.value()));
      });
  advertise_service<std_srvs::Trigger>(nh_, servers_, "tf_upgrade",
                                       [this](auto&, std_srvs::Trigger::Response& res) {
                                         fill(res, driver_.request(p::TfCardUpgradeRequest{}));
                                       });
}

std::optional<p::VisibleStatus> JobServices::latest_visible() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return visible_;
}

}  // namespace k40t::driver
