// The driver's services (srv/ documents each): every call validates its arguments with the
// message structs' validate() before anything is written (out of range: success=false and a
// message naming the field and its range, zero bytes sent), then waits for the ACK and turns a
// NACK or timeout into success=false with the pod's response text.
#pragma once

#include <string>
#include <vector>

#include <ros/node_handle.h>
#include <ros/service_server.h>

#include "k40t_driver/driver/pod_driver.h"
#include "k40t_driver/operations/capture_mode_guard.h"

namespace k40t::driver {

class PodServices {
 public:
  PodServices(ros::NodeHandle nh, PodDriver& driver);

 private:
  // Advertises `name`; `handler(request, response)` fills the response, the service call always
  // "succeeds" at the ROS level so the caller gets the message.
  template <class Srv, class Handler>
  void serve(const std::string& name, Handler handler);
  // A service that sends one pod request: `build(request, r)` fills the Req r from the service's
  // request; the response gets the ACK.
  template <class Srv, class Req, class Build>
  void serve_request(const std::string& name, Build build);
  // A service that asks the pod one argument-less Req: `answer(ack, response)` fills the response
  // from the typed ACK, when the pod answered and the answer reads (typed_ack() says why not).
  template <class Srv, class Req, class Answer>
  void serve_answer(const std::string& name, Answer answer);
  // The same for a std_srvs/Trigger service that sends one argument-less request.
  template <class Req>
  void serve_trigger(const std::string& name, Req request);

  // take_photo, record: `request` sent only in capture `mode` (the pod ignores it in the other,
  // section 3.2.4.1); `what` names it in the refusal.
  template <class Req>
  session::AckResult in_mode(protocol::CaptureMode mode, const char* what, const Req& request);

  void advertise_camera();
  void advertise_gimbal();
  void advertise_thermal_and_laser();
  void advertise_system();

  ros::NodeHandle nh_;
  PodDriver& driver_;
  operations::CaptureModeGuard mode_;  // take_photo and record need the matching mode
  std::vector<ros::ServiceServer> servers_;
};

}  // namespace k40t::driver
