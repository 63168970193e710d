#include "k40t_driver/sim/control_commands.h"

#include "k40t_driver/sim/lens.h"
#include "k40t_driver/sim/number_text.h"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace k40t::sim {

namespace {

using Args = std::vector<std::string>;
using Numbers = std::vector<double>;

// A number a command takes: its name in errors, its range, and its value when it is optional and
// not given.
struct NumberArg {
  const char* what;
  double lo;
  double hi;
  double absent = 0;
};

// The usage's first word is the command's name; `numbers` are its leading arguments, checked
// before `run` sees them (as `n`).
struct Command {
  const char* usage;
  size_t min_args;
  size_t max_args;
  std::string (*run)(const Args& args, const Numbers& n, ControlTarget& target);
  std::vector<NumberArg> numbers = {};
};

std::string error(const std::string& why) {
  return "error: " + why;
}

std::chrono::milliseconds millis(double seconds) {
  return std::chrono::milliseconds(static_cast<int64_t>(std::llround(seconds * 1000)));
}

// Changes fault settings (their arguments are checked already).
template <class Change>
std::string change_faults(ControlTarget& target, Change change) {
  FaultSettings settings = target.faults().settings();
  change(settings);
  target.faults().set_settings(settings);
  return "ok " + target.faults().describe();
}

std::string run_refuse(const Args&, const Numbers& n, ControlTarget& target) {
  return change_faults(target, [&](FaultSettings& s) {
    s.refuse_id = static_cast<uint32_t>(n[0]);
    s.refuse_code = static_cast<uint16_t>(n[1]);
  });
}

std::string run_help(const Args&, const Numbers&, ControlTarget&) {
  return "ok " + control_help();
}
std::string run_status(const Args&, const Numbers&, ControlTarget& target) {
  return "ok " + target.status();
}
std::string run_clear(const Args&, const Numbers&, ControlTarget& target) {
  target.faults().clear();
  return "ok " + target.faults().describe();
}

// "RATE", a probability, becomes the fault setting kRate (corrupt, drop-acks).
template <double FaultSettings::*kRate>
std::string run_rate(const Args&, const Numbers& n, ControlTarget& target) {
  return change_faults(target, [&](FaultSettings& s) { s.*kRate = n[0]; });
}

std::string run_garbage(const Args&, const Numbers& n, ControlTarget& target) {
  return change_faults(target, [&](FaultSettings& s) {
    s.garbage_rate = n[0];
    s.garbage_max_bytes = static_cast<size_t>(n[1]);
  });
}

std::string run_delay_acks(const Args&, const Numbers& n, ControlTarget& target) {
  return change_faults(target, [&](FaultSettings& s) {
    s.delay_ack_ms = n[0];
    s.delay_ack_rate = n[1];
  });
}

std::string run_silence(const Args& args, const Numbers& n, ControlTarget& target) {
  target.faults().silence_for(millis(n[0]));
  return "ok silent for " + args[0] + " s";
}

std::string run_disconnect(const Args& args, const Numbers& n, ControlTarget& target) {
  target.disconnect_for(millis(n[0]));
  return "ok disconnected for " + args[0] + " s";
}

std::string run_seq_jump(const Args&, const Numbers& n, ControlTarget& target) {
  target.faults().jump_sequence(static_cast<int>(n[0]));
  return "ok " + target.faults().describe();
}

std::string run_sd(const Args& args, const Numbers&, ControlTarget& target) {
  bool known = false;
  std::string state;
  target.with_model([&](PodModel& pod) {
    known = set_sd_condition(pod.camera().sd(), args[0]);
    state = to_string(pod.camera().sd().state());
  });
  if (!known)
    return error("sd: unknown condition '" + args[0] + "' (" + sd_condition_names() + ")");
  return "ok sd " + state;
}

// The photo resolution the camera holds and reports (0x010200 byte 3): 0x16 (5160x3870) is one
// the document lists in the ACK but 0x000202 cannot set, so only this reaches it.
std::string run_photo_resolution(const Args& args, const Numbers& n, ControlTarget& target) {
  target.with_model([&](PodModel& pod) {
    pod.camera().visible().photo_resolution = static_cast<protocol::PhotoResolution>(n[0]);
  });
  return "ok photo-resolution " + args[0];
}

std::string run_self_test(const Args& args, const Numbers&, ControlTarget& target) {
  char* end = nullptr;
  const unsigned long mask = std::strtoul(args[0].c_str(), &end, 0);
  if (args[0].empty() || *end != '\0' || mask > 0x0F)
    return error("MASK must be 0..0x0F, got '" + args[0] + "'");
  target.with_model([&](PodModel& pod) { pod.set_self_test(static_cast<uint8_t>(mask)); });
  return "ok self-test " + args[0];
}

std::string run_ground_height(const Args& args, const Numbers& n, ControlTarget& target) {
  target.with_model([&](PodModel& pod) { pod.world().set_ground_height(n[0]); });
  return "ok ground " + args[0] + " m below the pod";
}

std::string run_hot_object(const Args& args, const Numbers& n, ControlTarget& target) {
  target.with_model([&](PodModel& pod) { pod.world().set_hot_object(n[0], n[1]); });
  return "ok hot object " + args[0] + " m north, " + args[1] + " m east of the take-off point";
}

// The vehicle's motion from now on (vehicle_motion.h), from where it is.
std::string run_fly(const Args& args, const Numbers& n, ControlTarget& target) {
  target.with_model(
      [&](PodModel& pod) { pod.ground_truth().motion().fly(pod.now_s(), n[0], n[1]); });
  return "ok flying " + args[0] + " m/s north, " + args[1] + " m/s east";
}

std::string run_orbit(const Args& args, const Numbers& n, ControlTarget& target) {
  bool started = false;
  target.with_model([&](PodModel& pod) {
    started = pod.ground_truth().motion().orbit(pod.now_s(), n[0], n[1], n[2]);
  });
  if (!started) return "error: the vehicle is at the orbit's centre";
  return "ok orbiting " + args[0] + " m north, " + args[1] + " m east at " + args[2] + " m/s";
}

std::string run_photos(const Args&, const Numbers&, ControlTarget& target) {
  std::ostringstream out;
  out << "ok";
  target.with_model([&](PodModel& pod) {
    out << " " << pod.camera().photos().size() << " photos";
    for (const PhotoRecord& photo : pod.camera().photos()) {
      out << "; " << photo.path;
      if (photo.width_px > 0) out << " " << photo.width_px << "x" << photo.height_px;
      if (photo.gps) {
        const GeoPoint& at = photo.gps->position;
        out << " lat " << at.latitude_deg << " lon " << at.longitude_deg << " alt "
            << at.altitude_m;
      } else {
        out << " no gps";
      }
    }
  });
  return out.str();
}

// "P LAT LON H_ELLIPSOID H_MSL" of a truth-frame point, or "P none".
void put_point(std::ostream& out, const char* name, const std::optional<Vec3>& point,
               const GroundTruth& truth) {
  out << " " << name;
  const auto earth = point ? truth.to_earth(*point) : Result<TruePoint>::fail("none");
  if (!earth) {
    out << " none";
    return;
  }
  out << " " << earth->geodetic.latitude_deg << " " << earth->geodetic.longitude_deg << " "
      << earth->geodetic.height_ellipsoid_m << " " << earth->msl_m;
}

// The true state now: Unix time of the model's now, the pod's position and velocity, the
// vehicle heading the pod uses, the boresight (yaw clockwise from north, pitch up, degrees: where
// every camera and the laser point), the hot object's centre, the laser spot and its range.
std::string run_truth(const Args&, const Numbers&, ControlTarget& target) {
  std::ostringstream out;
  out.precision(12);
  out << "ok";
  target.with_model([&](PodModel& pod) {
    const GroundTruth& truth = pod.ground_truth();
    const Vec3 v = truth.velocity(pod.now_s());
    out << " unix " << pod.unix_time_s();
    put_point(out, "pod", pod.pod_position(), truth);
    out << " pod_ne " << pod.pod_position().x << " " << pod.pod_position().y;
    out << " velocity_ne " << v.x << " " << v.y << " heading " << pod.vehicle_attitude_deg().yaw;
    out << " boresight " << pod.boresight_yaw_deg() << " " << pod.boresight_pitch_deg();
    put_point(out, "hot", pod.hot_object_position(), truth);
    put_point(out, "laser", pod.laser_spot(), truth);
    const std::optional<double> range = pod.laser_range();
    out << " range " << (range ? *range : 0.0);
    const double zoom = pod.zoom().zoom();
    out << " zoom " << zoom << " hfov " << field_of_view(Lens::kTele, zoom).horizontal_deg;
  });
  return out.str();
}

std::string run_geotags(const Args&, const Numbers&, ControlTarget& target) {
  std::string text;
  target.with_model([&](PodModel& pod) { text = pod.ground_truth().describe_geotags(); });
  return "ok " + text;
}

// What the host last sent in 0x000320 (ground_truth.h).
std::string run_flight_data(const Args&, const Numbers&, ControlTarget& target) {
  std::ostringstream out;
  out.precision(9);
  target.with_model([&](PodModel& pod) {
    const ReceivedFlightData& d = pod.ground_truth().received_flight_data();
    out << "ok requests " << d.requests << " ground_speed " << d.ground_speed_m_s << " climb "
        << d.climb_rate_m_s << " heading " << d.heading_deg << " airspeed " << d.airspeed_m_s
        << " throttle " << d.throttle_percent;
  });
  return out.str();
}

const std::vector<Command>& commands() {
  static const NumberArg kRate{"RATE", 0, 1};
  static const NumberArg kSeconds{"SECONDS", 0, 3600};
  static const std::vector<Command> kCommands = {
      {"help", 0, 0, run_help},
      {"status", 0, 0, run_status},
      {"clear", 0, 0, run_clear},
      {"corrupt RATE", 1, 1, run_rate<&FaultSettings::corrupt_rate>, {kRate}},
      {"garbage RATE [MAX]", 1, 2, run_garbage, {kRate, {"MAX", 1, 64, 16}}},
      {"drop-acks RATE", 1, 1, run_rate<&FaultSettings::drop_ack_rate>, {kRate}},
      {"delay-acks MS [RATE]", 1, 2, run_delay_acks, {{"MS", 0, 60000}, {"RATE", 0, 1, 1}}},
      {"refuse ID [CODE]", 1, 2, run_refuse, {{"ID", 0, 0xFFFF}, {"CODE", 1, 0xFFFF, 1}}},
      {"silence SECONDS", 1, 1, run_silence, {kSeconds}},
      {"disconnect SECONDS", 1, 1, run_disconnect, {kSeconds}},
      {"seq-jump N", 1, 1, run_seq_jump, {{"N", 1, 255}}},
      {"sd absent|insert|fill|normal|abnormal|slow|format-error", 1, 1, run_sd},
      {"self-test MASK", 1, 1, run_self_test},
      {"photo-resolution 0x14|0x15|0x16", 1, 1, run_photo_resolution, {{"CODE", 0x14, 0x16}}},
      {"ground-height METRES", 1, 1, run_ground_height, {{"METRES", 1, 10000}}},
      {"photos", 0, 0, run_photos},
      {"truth", 0, 0, run_truth},
      {"hot-object NORTH EAST", 2, 2, run_hot_object, {{"NORTH", -1e5, 1e5}, {"EAST", -1e5, 1e5}}},
      {"fly NORTH EAST", 2, 2, run_fly, {{"NORTH", -100, 100}, {"EAST", -100, 100}}},
      {"orbit NORTH EAST SPEED",
       3,
       3,
       run_orbit,
       {{"NORTH", -1e5, 1e5}, {"EAST", -1e5, 1e5}, {"SPEED", -100, 100}}},
      {"geotags", 0, 0, run_geotags},
      {"flight-data", 0, 0, run_flight_data},
  };
  return kCommands;
}

}  // namespace

std::string control_help() {
  std::string text = "commands:";
  for (const Command& c : commands()) text += std::string(" | ") + c.usage;
  return text;
}

std::string execute_control_command(const std::string& line, ControlTarget& target) {
  std::istringstream in(line);
  std::string name;
  in >> name;
  if (name.empty()) return error("empty command; try 'help'");
  Args args;
  for (std::string word; in >> word;) args.push_back(word);
  for (const Command& c : commands()) {
    const std::string usage = c.usage;
    if (usage.substr(0, usage.find(' ')) != name) continue;
    if (args.size() < c.min_args || args.size() > c.max_args) return error("usage: " + usage);
    Numbers n;
    for (const NumberArg& spec : c.numbers) {
      const size_t i = n.size();
      const auto v = i < args.size() ? parse_number_in(args[i], spec.what, spec.lo, spec.hi)
                                     : Result<double>(spec.absent);
      if (!v) return error(v.error());
      n.push_back(*v);
    }
    return c.run(args, n, target);
  }
  return error("unknown command '" + name + "'; try 'help'");
}

}  // namespace k40t::sim
