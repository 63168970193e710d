#include "k40t_driver/ros/job_services.h"

#include <std_srvs/Trigger.h>

#include "k40t_driver/PreciseReshoot.h"
#include "k40t_driver/protocol/messages/camera_system.h"
#include "k40t_driver/ros/service_support.h"

namespace k40t::driver {

namespace p = protocol;

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
        res.focal_length_mm = request->focal_length_raw / operations::kReshootFocalUnitsPerMm;
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
