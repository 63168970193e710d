// A request with one field set, for tests that send many one-value requests:
//   link.send(request_with(&p::ThermalZoomRequest::zoom_x, 2))
// A field the request inherits (SwitchRequest<>'s `on`) names the request explicitly:
//   request_with<p::GimbalStabilisationRequest>(&p::GimbalStabilisationRequest::on, true)
#pragma once

#include <type_traits>

namespace k40t::testing {

template <class Request = void, class Owner, class Field, class Value>
auto request_with(Field Owner::*field, const Value& value) {
  std::conditional_t<std::is_void_v<Request>, Owner, Request> request;
  request.*field = value;
  return request;
}

}  // namespace k40t::testing
