// k40t probe: the first minutes with a real pod. Listens, reads back every setting the document
// has a query for, and learns from the bytes the readings the document leaves open
// (docs/protocol/decisions.md#conventions); with --allow-motion it moves the gimbal a few degrees
// to learn the report's signs and the command's scale, with --calibration it runs one drift
// calibration to see how it ends. Prints a table and writes the driver's parameter file.
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <map>
#include <string>
#include <vector>

#include "command.h"
#include "frame_text.h"
#include "k40t_driver/protocol/catalogue.h"
#include "k40t_driver/protocol/conventions.h"
#include "k40t_driver/protocol/messages/camera.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/protocol/messages/sbus.h"
#include "k40t_driver/protocol/messages/thermal.h"
#include "k40t_driver/protocol/messages/visible.h"
#include "probe_learn.h"

namespace k40t::tool {

namespace {

using namespace std::chrono_literals;

// Why a reading is not learned when its learner did not run.
const std::map<std::string, std::string>& not_learned_why() {
  static const std::map<std::string, std::string> why = {
      {"angle_command_scale", "not learned: run with --allow-motion"},
      {"yaw_sign", "not learned: run with --allow-motion"},
      {"pitch_sign", "not learned: run with --allow-motion"},
      {"calibration_end", "not learned: run with --calibration"},
      {"roll_sign", "not learnable from traffic: default kept (roll cannot be commanded)"},
      {"attitude_order",
       "not learnable from traffic: default kept (the orders differ only with the roll)"},
      {"photo_mode_2", "not learnable from traffic: default kept (shows only while shooting)"},
      {"gps_request_time",
       "not learnable from traffic: default kept (0x000310 comes only with photos)"},
      {"gps_answer_byte_order",
       "not learnable from traffic: default kept (the host writes 0x010310)"},
      {"laser_target_zeros", "not learnable from traffic: default kept"},
      {"laser_status_byte_order",
       "not learnable from traffic: default kept (0x020406's code is 0 and its distance reads "
       "plausibly both ways)"},
      {"focus_plus", "not learnable from traffic: default kept (watch the picture)"},
  };
  return why;
}

// The report in the table's order, every reading present.
ProbeReport complete(const ProbeReport& found) {
  ProbeReport all;
  for (const protocol::ConventionInfo& info : protocol::convention_table()) {
    if (const Finding* f = found.find(info.name)) {
      if (f->learned) {
        all.learned(f->name, f->value, f->evidence);
      } else {
        all.kept(f->name, f->value, f->evidence);
      }
      continue;
    }
    const auto why = not_learned_why().find(info.name);
    all.kept(
        info.name, info.default_value,
        why != not_learned_why().end() ? why->second : "not learnable from traffic: default kept");
  }
  return all;
}

struct ReadBack {
  const char* what;
  protocol::MessageId request;
  session::AckResult result;
};

template <class Req>
ReadBack ask(ProbeLink& link, const char* what) {
  return {what, Req::kId, link.session().request(Req{})};
}

// The read-backs decoded with what was learned (an ACK byte order, above all), one per line.
std::string read_back_text(const std::vector<ReadBack>& answers,
                           const protocol::CodecOptions& codec) {
  std::string text;
  for (const ReadBack& a : answers) {
    text += std::string(a.what) + " (" + id_text(a.request) + "): ";
    const protocol::MessageId ack_id = protocol::ack_id_of(a.request);
    text += a.result.received
                ? payload_summary(ack_id, a.result.payload.data(), a.result.payload.size(), codec)
                : a.result.message;
    text += "\n";
  }
  return text;
}

// The codec the learned readings make; each value goes through the driver's own parser, so a
// value it would refuse shows here first.
protocol::CodecOptions learned_codec(const ProbeReport& report) {
  protocol::CrcCoverage coverage = protocol::CrcCoverage::kAuto;
  protocol::CodecOptions codec;
  for (const Finding& f : report.findings()) {
    if (!f.learned) continue;
    const Status set = protocol::set_convention({coverage, codec}, f.name, f.value);
    if (!set) std::fprintf(stderr, "k40t probe: internal: %s\n", set.message().c_str());
  }
  return codec;
}

std::string now_text() {
  const std::time_t now = std::time(nullptr);
  char text[32];
  std::strftime(text, sizeof(text), "%Y-%m-%d %H:%M:%S UTC", std::gmtime(&now));
  return text;
}

Result<double> option_real(const ParsedArgs& args, const std::string& option, double lo,
                           double hi) {
  const std::string& text = args.options.at(option);
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !(value >= lo && value <= hi))
    return Result<double>::fail(option + " must be a number " + std::to_string(int(lo)) + ".." +
                                std::to_string(int(hi)) + ", got '" + text + "'");
  return value;
}

// Fails early (before anything is sent) when the parameter file cannot be written.
Status check_writable(const std::string& path) {
  const std::string probe_path = path + ".part";
  std::FILE* file = std::fopen(probe_path.c_str(), "w");
  if (file == nullptr) return Status::fail("cannot write " + path + " (is its directory there?)");
  std::fclose(file);
  std::remove(probe_path.c_str());
  return Status::ok();
}

}  // namespace

// What the document has a query for: versions, settings, network, SBUS (nothing changes).
std::vector<ReadBack> read_back(ProbeLink& link) {
  return {ask<protocol::GimbalVersionRequest>(link, "gimbal version"),
          ask<protocol::CameraVersionRequest>(link, "camera version"),
          ask<protocol::ThermalReadSettingsRequest>(link, "thermal settings"),
          ask<protocol::VisibleReadSettingsRequest>(link, "visible settings"),
          ask<protocol::GetIpRequest>(link, "IP address"),
          ask<protocol::SbusConfigRequest>(link, "SBUS configuration")};
}

namespace {

int run_probe(const Command& self, const ParsedArgs& args) {
  if (args.positional.size() != 1) return usage_error(self, "give one link URL");
  const std::string& url = args.positional[0];
  Result<long> listen_s = option_integer(args, "--listen", 3, 1, 60);
  if (!listen_s) return usage_error(self, listen_s.error());
  Result<long> connect_ms = option_integer(args, "--connect-timeout", 3000, 1, 60000);
  if (!connect_ms) return usage_error(self, connect_ms.error());
  Result<long> ack_ms = option_integer(args, "--timeout", 1000, 1, 60000);
  if (!ack_ms) return usage_error(self, ack_ms.error());
  ProbeHints hints;
  if (args.options.count("--sd-card-gb") != 0) {
    Result<double> gb = option_real(args, "--sd-card-gb", 1, 4096);
    if (!gb) return usage_error(self, gb.error());
    hints.sd_card_gb = gb.value();
  }
  Result<std::unique_ptr<transport::Transport>> checked = transport::make_transport(url);
  if (!checked) return usage_error(self, checked.error());
  checked.value().reset();
  const auto out = args.options.find("--out");
  if (out != args.options.end()) {
    const Status writable = check_writable(out->second);
    if (!writable) return usage_error(self, writable.message());
  }

  Result<std::unique_ptr<ProbeLink>> opened =
      ProbeLink::open(url, std::chrono::milliseconds(connect_ms.value()),
                      std::chrono::milliseconds(ack_ms.value()));
  if (!opened) {
    std::fprintf(stderr, "k40t probe: %s\n", opened.error().c_str());
    return kExitFailed;
  }
  ProbeLink& link = *opened.value();
  const auto listen = std::chrono::seconds(listen_s.value());
  if (!link.wait_until([&] { return link.total_frames() > 0; }, listen)) {
    std::fprintf(stderr,
                 "k40t probe: %s: no frame from the pod in %ld s (check power, cabling, baud "
                 "rate and URL)\n",
                 url.c_str(), listen_s.value());
    return kExitFailed;
  }
  // Every periodic report is at least 1 Hz: the whole window sees each of them.
  link.wait_until([] { return false; }, listen);
  const std::vector<ReadBack> answers = read_back(link);

  ProbeReport found;
  learn_from_traffic(link, hints, found);
  std::printf("%s", read_back_text(answers, learned_codec(found)).c_str());
  std::string log;
  Status moved = Status::ok();
  if (args.has("--allow-motion")) {
    moved = learn_from_motion(link, found, log);
    // A yaw crossing zero in the motion is stronger evidence than the listening window.
  }
  Status calibrated = Status::ok();
  if (moved && args.has("--calibration")) calibrated = learn_calibration_end(link, found, log);
  if (!log.empty()) std::printf("\n%s", log.c_str());
  const ProbeReport report = complete(found);
  std::printf("\n%s", report.table().c_str());
  for (const Status& failed : {moved, calibrated}) {
    if (!failed) {
      std::fprintf(stderr, "k40t probe: stopped: %s\n", failed.message().c_str());
      return kExitFailed;
    }
  }
  if (out != args.options.end()) {
    const Status written = report.write_yaml(
        out->second, "k40t probe " + url + ", " + now_text() +
                         ". Load with: roslaunch k40t_driver k40t.launch conventions:=" +
                         out->second + " (docs/bring_up.md)");
    if (!written) {
      std::fprintf(stderr, "k40t probe: %s\n", written.message().c_str());
      return kExitFailed;
    }
    std::printf("\nwrote %s\n", out->second.c_str());
  }
  return kExitOk;
}

}  // namespace

const Command& probe_command() {
  static const Command command{
      "probe",
      "probe URL [--allow-motion] [--calibration] [--out FILE.yaml] [options]",
      "learn a pod's readings of the open points of the document; write the parameter file",
      "For the first minutes with a real pod (docs/bring_up.md). Listens to the pod's reports,\n"
      "reads back versions and every setting the document has a query for, and learns from the\n"
      "bytes the readings the document leaves open (docs/protocol/decisions.md#conventions).\n"
      "Read-only unless told otherwise:\n"
      "  --allow-motion  centres the gimbal if it is off centre, moves it by a few degrees with\n"
      "                  0x000012 (right/left, up/down) to learn the report's signs and the\n"
      "                  command's scale, then returns it where it was; stops at the first\n"
      "                  refused or unanswered command or move that did not happen;\n"
      "  --calibration   runs one drift calibration (0x000013) to see how its end shows.\n"
      "Prints a table (reading, value, evidence); --out writes the parameter file that\n"
      "'roslaunch k40t_driver k40t.launch conventions:=FILE.yaml' loads. Readings the run could\n"
      "not learn are written as comments: the driver keeps its default for them.\n"
      "Exit 0 when done, 1 when the pod does not answer or a step failed (nothing written),\n"
      "2 for bad arguments.\n\n"
      "example: k40t probe serial:///dev/ttyUSB0 --allow-motion --out pod.yaml",
      {{"--allow-motion", nullptr, "move the gimbal by small steps (learns signs and scale)"},
       {"--calibration", nullptr, "run one drift calibration (learns how it ends)"},
       {"--out", "FILE", "write the parameter file (YAML)"},
       {"--sd-card-gb", "GB", "the SD card's labelled size (learns sd_capacity_unit)"},
       {"--listen", "S", "seconds of listening to the reports (default 3)"},
       {"--timeout", "MS", "ACK timeout per attempt (default 1000)"},
       {"--connect-timeout", "MS", "how long to wait for the link (default 3000)"}},
      &run_probe};
  return command;
}

}  // namespace k40t::tool
