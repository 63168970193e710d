// The simulator's run-time control language: one command per line, one reply line ("ok ..." or
// "error: ..."). Sent over the control socket (control_server.h), e.g.
//   echo "drop-acks 0.5" | socat - TCP:127.0.0.1:5761
// Commands (also listed by "help"):
//   help | status | clear
//   corrupt RATE            bit flips per byte sent, 0..1
//   garbage RATE [MAX]      random bytes before a frame, per frame, 0..1 (up to MAX bytes, 1..64)
//   drop-acks RATE          requests left without ACK, 0..1
//   delay-acks MS [RATE]    ACKs sent MS late (0 = off), with probability RATE (default 1)
//   refuse ID [CODE]        refuse requests with id ID (e.g. 0x000501; 0 = off) with CODE
//                           (default 0x0001 failure) and do not carry them out
//   silence SECONDS         send nothing for that long
//   disconnect SECONDS      close the link, reopen it after that long
//   seq-jump N              skip N sequence numbers (1..255)
//   sd absent|insert|fill|normal|abnormal|slow|format-error
//   self-test MASK          0x000001 self-test bits (IR 1, tele 2, wide 4, laser 8)
//   ground-height METRES    the flat ground below the pod
//   photos                  the photos on the card, with their GPS answers
//   photo-resolution CODE   the visible photo resolution held and reported (0x14..0x16)
//   truth                   true positions now (sim/ground_truth.h): Unix time, pod (and its
//                           metres north, east of the take-off point), velocity, heading, hot
//                           object, laser spot (lat lon h_ellipsoid h_msl), range, the tele's
//                           zoom and horizontal field of view (deg)
//   fly NORTH EAST          the vehicle flies at this velocity (m/s) from where it is; 0 0 hovers
//   orbit NORTH EAST SPEED  the vehicle circles the point (metres from the take-off point)
//                           through where it is, at SPEED m/s (positive clockwise from above)
//   hot-object NORTH EAST   move the hot object (metres from the take-off point)
//   geotags                 per photo: geotag error against the truth, distance moved by the
//                           time the answer arrived
#pragma once

#include <chrono>
#include <functional>
#include <string>

#include "k40t_driver/sim/fault_injector.h"
#include "k40t_driver/sim/pod_model.h"

namespace k40t::sim {

// What the commands act on; the front-end implements it (tests use a fake).
class ControlTarget {
 public:
  virtual ~ControlTarget() = default;
  virtual FaultInjector& faults() = 0;
  virtual void disconnect_for(std::chrono::milliseconds duration) = 0;
  // Runs `change` with the model locked against the simulation thread.
  virtual void with_model(const std::function<void(PodModel&)>& change) = 0;
  virtual std::string status() = 0;
};

std::string execute_control_command(const std::string& line, ControlTarget& target);
std::string control_help();

}  // namespace k40t::sim
