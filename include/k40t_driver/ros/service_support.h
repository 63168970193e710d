// What every service of the driver shares: a handler fills the response and the call always
// "succeeds" at the ROS level, so the caller gets success=false and the message instead of an
// exception; fill() turns a request's outcome into success/message.
#pragma once

#include <string>
#include <vector>

#include <ros/node_handle.h>
#include <ros/service_server.h>
#include <boost/function.hpp>

#include "k40t_driver/session/session.h"

namespace k40t::driver {

template <class Srv, class Handler>
void advertise_service(ros::NodeHandle& nh, std::vector<ros::ServiceServer>& servers,
                       const std::string& name, Handler handler) {
  using Req = typename Srv::Request;
  using Res = typename Srv::Response;
  boost::function<bool(Req&, Res&)> callback = [handler](Req& req, Res& res) {
    handler(req, res);
    return true;
  };
  servers.push_back(nh.advertiseService<Req, Res>(name, callback));
}

template <class Res>
void fill(Res& res, const session::AckResult& result) {
  res.success = result.ok();
  res.message = result.ok() ? "ok" : result.message;
}

template <class Res>
void fail(Res& res, const std::string& message) {
  res.success = false;
  res.message = message;
}

}  // namespace k40t::driver
