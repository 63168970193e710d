#include "control.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <vector>

#include "k40t_driver/psdk/sim/adapter_table.h"
#include "k40t_driver/sim/number_text.h"

namespace k40t::skyport_sim {

namespace {

using psdk::AckResult;
using psdk::CommandKey;
using psdk::Data;
using psdk::sim::AdapterSimulator;
using psdk::sim::table::Request;

std::string hex(const uint8_t* bytes, size_t size) {
  std::string out;
  char digits[4];
  for (size_t i = 0; i < size; ++i) {
    std::snprintf(digits, sizeof digits, "%s%02X", i ? " " : "", bytes[i]);
    out += digits;
  }
  return out;
}

// "ok code=0x00 data=AA BB" (code first, then the rest of the ACK's DATA), or why none came.
std::string ack_reply(const AckResult& r) {
  if (!r.received) return "error no ACK: " + r.message;
  if (r.data.size == 0) return "error empty ACK";
  char code[8];
  std::snprintf(code, sizeof code, "0x%02X", r.code());
  return std::string("ok code=") + code + " data=" + hex(r.data.data() + 1, r.data.size - 1);
}

// Command `key` with DATA written by the adapter's own writer (adapter_table.h, from the document).
std::string request(AdapterSimulator& adapter, CommandKey key,
                    const psdk::sim::table::Request& data = {}) {
  const std::vector<uint8_t>& bytes = data.bytes();
  return ack_reply(adapter.session().request_raw(key, bytes.data(), bytes.size()));
}

std::string report_reply(const psdk::sim::CheckReport& report) {
  std::string joined = report.summary();
  for (char& c : joined) {
    if (c == '\n') c = '|';
  }
  if (!joined.empty() && joined.back() == '|') joined.pop_back();
  return std::string("ok ") + (report.passed() ? "passed" : "failed") + " | " + joined;
}

Result<double> number(std::istringstream& in, const std::string& what, double lo, double hi) {
  std::string text;
  if (!(in >> text)) return Status::fail("missing " + what);
  return sim::parse_number_in(text, what, lo, hi);
}

std::string status_reply(AdapterSimulator& adapter) {
  const psdk::sim::AdapterStats s = adapter.stats();
  std::ostringstream out;
  out << "ok identity_passed=" << s.identity_passed << " identity_failed=" << s.identity_failed
      << " battery_acks=" << s.battery_acks
      << " power_off_ready=" << (s.last_power_off_ready ? 1 : 0)
      << " positions_answered=" << s.positions_answered
      << " transparent_to_mobile_bytes=" << s.transparent_to_mobile_bytes
      << " commands_sent=" << s.session.commands_sent
      << " acks_received=" << s.session.acks_received << " timeouts=" << s.session.ack_timeouts
      << " commands_received=" << s.session.commands_received
      << " link=" << transport::to_string(adapter.session().link_state());
  uint64_t pushes = 0;
  for (const auto& [name, count] : s.pushes_sent) pushes += count;
  out << " pushes=" << pushes;
  return out.str();
}

std::string fault(AdapterSimulator& adapter, const std::string& name, std::istringstream& in) {
  if (name == "clear") {  // every fault off; the seed stays, so runs remain reproducible
    psdk::sim::ByteFaults none;
    none.seed = adapter.byte_faults().seed;
    adapter.set_byte_faults(none);
    adapter.set_protocol_faults({});
    return "ok faults cleared";
  }
  if (name == "silence" || name == "disconnect") {
    const auto s = number(in, name + " seconds", 0, 3600);
    if (!s) return "error " + s.error();
    const auto duration = std::chrono::milliseconds(static_cast<int64_t>(*s * 1000));
    if (name == "silence") {
      adapter.silence_for(duration);
    } else {
      adapter.disconnect_for(duration);
    }
    return "ok " + name;
  }
  if (name == "utc_late") {
    const auto ms = number(in, "utc_late milliseconds", 1, 5000);
    if (!ms) return "error " + ms.error();
    adapter.delay_next_utc_push(std::chrono::milliseconds(static_cast<int64_t>(*ms)));
    return "ok utc_late";
  }
  if (name == "seq_jump") {
    const auto n = number(in, "seq_jump count", 1, 65535);
    if (!n) return "error " + n.error();
    adapter.jump_sequence(static_cast<uint16_t>(*n));
    return "ok seq_jump";
  }
  const auto p = number(in, name + " probability", 0, 1);
  if (!p) return "error " + p.error();
  // One fault changes; the others (and the command line's seed and limits) stay as they are.
  psdk::sim::ByteFaults bytes = adapter.byte_faults();
  psdk::sim::ProtocolFaults protocol = adapter.protocol_faults();
  if (name == "corrupt") bytes.corrupt_rate = *p;
  if (name == "garbage") bytes.garbage_rate = *p;
  if (name == "drop_ack") protocol.drop_ack_rate = *p;
  adapter.set_byte_faults(bytes);
  adapter.set_protocol_faults(protocol);
  return "ok " + name;
}

}  // namespace

std::string control_help() {
  return "ok commands: status | identity | check payload|camera|gimbal|unsupported | "
         "photo [stop] | record start|stop | record_state | work_mode photo|video | "
         "zoom FACTOR (digital) | focal MM (optical) | gimbal PITCH ROLL YAW (deg) | "
         "gimbal_state | gimbal_return | power_off | unknown | send SET ID [HEX..] | "
         "transparent TEXT | floating | corrupt P | garbage P | drop_ack P | silence S | "
         "disconnect S | seq_jump N | utc_late MS | clear";
}

std::string handle_control(AdapterSimulator& adapter, const std::string& line) {
  std::istringstream in(line);
  std::string command;
  in >> command;
  if (command.empty() || command == "help") return control_help();
  if (command == "status") return status_reply(adapter);
  if (command == "identity") {
    const psdk::sim::IdentityResult r = adapter.verify_identity();
    return std::string("ok ") + (r.passed ? "passed" : "failed") + " " + r.detail;
  }
  if (command == "check") {
    std::string what;
    in >> what;
    if (what == "payload") return report_reply(adapter.check_payload_state());
    if (what == "camera") return report_reply(adapter.check_camera());
    if (what == "gimbal") return report_reply(adapter.check_gimbal());
    if (what == "unsupported") return report_reply(adapter.check_unsupported());
    return "error check: expected payload, camera, gimbal or unsupported";
  }
  if (command == "photo") {
    std::string stop;
    in >> stop;
    // 3.4.3: 1 start, 0 stop.
    return request(adapter, {0x04, 0x03}, Request().u8(stop == "stop" ? 0 : 1));
  }
  if (command == "record") {
    std::string action;
    in >> action;
    if (action != "start" && action != "stop") return "error record: expected start or stop";
    // 3.4.7: 1 start, 0 stop.
    return request(adapter, {0x04, 0x07}, Request().u8(action == "start" ? 1 : 0));
  }
  if (command == "record_state") return request(adapter, {0x04, 0x08});
  if (command == "work_mode") {
    std::string mode;
    in >> mode;
    if (mode != "photo" && mode != "video") return "error work_mode: expected photo or video";
    // 3.4.1: 0 shoot photo, 1 record video.
    return request(adapter, {0x04, 0x01}, Request().u8(mode == "photo" ? 0 : 1));
  }
  if (command == "zoom") {
    const auto factor = number(in, "zoom factor", 1, 1000);
    if (!factor) return "error " + factor.error();
    // 3.4.19: float factor.
    return request(adapter, {0x04, 0x34}, Request().f32(static_cast<float>(*factor)));
  }
  if (command == "focal") {
    const auto mm = number(in, "focal length (mm)", 0.1, 6000);
    if (!mm) return "error " + mm.error();
    // 3.4.22: uint16 in 0.1 mm (P13).
    return request(adapter, {0x04, 0x37},
                   Request().u16(static_cast<uint16_t>(std::lround(*mm * 10.0))));
  }
  if (command == "gimbal") {
    const auto pitch = number(in, "pitch (deg)", -360, 360);
    const auto roll = number(in, "roll (deg)", -360, 360);
    const auto yaw = number(in, "yaw (deg)", -360, 360);
    if (!pitch || !roll || !yaw)
      return "error gimbal: expected PITCH ROLL YAW in degrees (DJI signs: pitch up, yaw right)";
    // 3.5.5: floats in degrees, pitch, roll, yaw.
    return request(adapter, {0x05, 0x05},
                   Request()
                       .f32(static_cast<float>(*pitch))
                       .f32(static_cast<float>(*roll))
                       .f32(static_cast<float>(*yaw)));
  }
  if (command == "gimbal_state") return request(adapter, {0x05, 0x01});
  if (command == "gimbal_return") return request(adapter, {0x05, 0x03});
  if (command == "power_off") {
    adapter.announce_power_off();
    return "ok power-off announced in the next battery push";
  }
  if (command == "unknown") {
    // 0x04/0x50: a camera command the document does not define.
    return ack_reply(adapter.session().request_raw(CommandKey{0x04, 0x50}, nullptr, 0));
  }
  if (command == "send") {
    const auto set = number(in, "SET", 0, 255);
    const auto id = number(in, "ID", 0, 255);
    if (!set || !id) return "error send: expected SET ID [HEX..]";
    std::vector<uint8_t> bytes;
    for (std::string byte; in >> byte;) {
      char* end = nullptr;
      const unsigned long value = std::strtoul(byte.c_str(), &end, 16);
      if (byte.size() > 2 || *end != '\0') return "error send: '" + byte + "' is not a hex byte";
      bytes.push_back(static_cast<uint8_t>(value));
    }
    return ack_reply(adapter.session().request_raw(
        CommandKey{static_cast<uint8_t>(*set), static_cast<uint8_t>(*id)}, bytes.data(),
        bytes.size()));
  }
  if (command == "transparent") {
    std::string text;
    std::getline(in >> std::ws, text);
    if (text.empty() || text.size() > 32) return "error transparent: 1..32 bytes of text";
    const Status sent =
        adapter.session().send_raw(psdk::TransparentFromMobile::key(),
                                   reinterpret_cast<const uint8_t*>(text.data()), text.size());
    return sent ? "ok sent" : "error " + sent.message();
  }
  if (command == "floating") {
    std::string out = "ok";
    for (const std::string& m : adapter.floating_window_messages()) out += " | " + m;
    return out;
  }
  if (command == "corrupt" || command == "garbage" || command == "drop_ack" ||
      command == "silence" || command == "disconnect" || command == "seq_jump" ||
      command == "utc_late" || command == "clear") {
    return fault(adapter, command, in);
  }
  return "error unknown command '" + command + "' (try help)";
}

}  // namespace k40t::skyport_sim
