// The learners that only listen: every reading is tried on the raw bytes, and a reading is
// learned only when the frames fit it and no other (docs/protocol/decisions.md#conventions).
#include <array>
#include <cmath>
#include <cstdio>
#include <set>

#include "frame_text.h"
#include "k40t_driver/protocol/ack_byte_order_evidence.h"
#include "k40t_driver/protocol/catalogue.h"
#include "k40t_driver/protocol/convention_readings.h"
#include "k40t_driver/protocol/conventions.h"
#include "k40t_driver/protocol/messages/camera.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/protocol/messages/thermal.h"
#include "k40t_driver/protocol/messages/visible.h"
#include "probe_learn.h"

namespace k40t::tool {

uint16_t u16_little(const std::vector<uint8_t>& p, size_t at) {
  return static_cast<uint16_t>(p[at] | (p[at + 1] << 8));
}
uint16_t u16_big(const std::vector<uint8_t>& p, size_t at) {
  return static_cast<uint16_t>((p[at] << 8) | p[at + 1]);
}

namespace {

std::string default_of(const char* name) {
  const protocol::ConventionInfo* info = protocol::find_convention(name);
  return info != nullptr ? info->default_value : "";
}

// Every value of an enum reading except `auto`, as enum and name.
template <class E>
std::vector<std::pair<E, std::string>> alternatives(const char* reading) {
  std::vector<std::pair<E, std::string>> all;
  const std::vector<const char*>& values = protocol::find_convention(reading)->values;
  for (size_t i = 0; i < values.size(); ++i) {
    if (std::string(values[i]) != "auto") all.push_back({static_cast<E>(i), values[i]});
  }
  return all;
}

std::string format(const char* pattern, double a, double b = 0, double c = 0) {
  char text[160];
  std::snprintf(text, sizeof(text), pattern, a, b, c);
  return text;
}

// Of the candidate readings, those every frame fits. One left: learned; several: the default is
// kept (the frames cannot tell them apart); none: the frames contradict each other.
void decide(ProbeReport& report, const char* name, const std::set<std::string>& fitting,
            const std::string& evidence, const std::string& ambiguous_why) {
  if (fitting.size() == 1) {
    report.learned(name, *fitting.begin(), evidence);
    return;
  }
  std::string list;
  for (const std::string& f : fitting) list += (list.empty() ? "" : ", ") + f;
  if (fitting.empty()) {
    report.kept(name, default_of(name), "frames fit no reading (" + evidence + "): check by hand");
  } else {
    report.kept(name, default_of(name), "frames fit " + list + ": " + ambiguous_why);
  }
}

void learn_crc_coverage(const ProbeLink& link, ProbeReport& report) {
  auto counts = link.coverage_counts();
  const size_t excluded = counts[protocol::CrcCoverage::kHeaderExcluded];
  const size_t whole = counts[protocol::CrcCoverage::kWholeFrame];
  if (excluded + whole == 0) {
    report.kept("crc_coverage", default_of("crc_coverage"), "no frame heard");
  } else if (excluded > 0 && whole > 0) {
    report.kept("crc_coverage", default_of("crc_coverage"),
                std::to_string(excluded) + " frames without STX, " + std::to_string(whole) +
                    " with it: auto keeps both");
  } else {
    report.learned("crc_coverage", excluded > 0 ? "header_excluded" : "whole_frame",
                   std::to_string(excluded + whole) + " frames, checksum " +
                       (excluded > 0 ? "from LEN (STX left out)" : "from STX"));
  }
}

void learn_ack_byte_order(const ProbeLink& link, ProbeReport& report) {
  protocol::AckOrderFit fit;
  for (protocol::MessageId id : link.ids()) {
    if (protocol::kind_of(id) != protocol::MessageKind::kAck) continue;
    for (const HeardFrame& f : link.frames(id))
      protocol::fit_ack_byte_order(id, f.payload.data(), f.payload.size(), fit);
  }
  std::set<std::string> fitting;
  if (fit.big) fitting.insert("big");
  if (fit.little) fitting.insert("little");
  decide(report, "ack_byte_order", fitting, fit.evidence,
         "every ACK field heard reads the same both ways (codes 0, symmetric values)");
}

// The source system of the pod's own reports: where it lives, so where requests go (A3).
void learn_system_id(const ProbeLink& link, ProbeReport& report, const char* name,
                     std::initializer_list<protocol::MessageId> reports, const char* what) {
  std::set<int> systems;
  for (protocol::MessageId id : reports) {
    for (const HeardFrame& f : link.frames(id)) systems.insert(f.source.system);
  }
  if (systems.size() == 1) {
    report.learned(name, std::to_string(*systems.begin()),
                   std::string(what) + " come from system " + std::to_string(*systems.begin()));
  } else if (systems.empty()) {
    report.kept(name, default_of(name), std::string("no ") + what + " heard");
  } else {
    report.kept(name, default_of(name),
                std::string(what) + " come from several systems: check the cabling");
  }
}

// 0x000002's yaws as int16 (the layout's reading): what each report shows (yaw_range_evidence).
void learn_yaw_range(const ProbeLink& link, ProbeReport& report) {
  bool heading = false;
  bool negative = false;
  for (const HeardFrame& f : link.frames(protocol::GimbalAttitude::kId)) {
    const Result<protocol::GimbalAttitude> attitude =
        protocol::decode_payload<protocol::GimbalAttitude>(f.payload.data(), f.payload.size(),
                                                           protocol::CodecOptions{});
    if (!attitude) continue;
    const protocol::YawRange seen = protocol::yaw_range_evidence(*attitude);
    heading = heading || seen == protocol::YawRange::kHeading;
    negative = negative || seen == protocol::YawRange::kSigned;
  }
  if (heading && !negative) {
    report.learned("yaw_range", "heading", "0x000002 yaw beyond 180 deg (a 0..360 heading)");
  } else if (negative && !heading) {
    report.learned("yaw_range", "signed", "0x000002 yaw between -180 and 0 deg");
  } else if (heading) {
    report.kept("yaw_range", default_of("yaw_range"),
                "0x000002 yaw both negative and beyond 180 deg: check by hand");
  } else {
    report.kept("yaw_range", default_of("yaw_range"),
                "every yaw heard was 0..180 deg, which both readings share (--allow-motion "
                "crosses 0)");
  }
}

void learn_sd_capacity_unit(const ProbeLink& link, const ProbeHints& hints, ProbeReport& report) {
  const std::optional<HeardFrame> status = link.latest(protocol::CameraSystemStatus::kId);
  if (!status || status->payload.size() < 15) {
    report.kept("sd_capacity_unit", default_of("sd_capacity_unit"), "no 0x000003 heard");
    return;
  }
  const double total = u16_little(status->payload, 9);
  const std::string both = format("total %.0f counts: %.1f GB at 10 MB, %.2f GB at 0.1 MB", total,
                                  total * 10 / 1000, total * 0.1 / 1000);
  if (total == 65535) {
    report.learned("sd_capacity_unit", "0.1mb",
                   "0x000003 total saturated at 65535 counts (a card over 6.5 GB in 0.1 MB)");
  } else if (total == 0) {
    report.kept("sd_capacity_unit", default_of("sd_capacity_unit"), "0x000003 shows no card");
  } else if (hints.sd_card_gb) {
    // Labels are decimal GB; file systems show a little less than the label.
    auto near_label = [&](double mb) {
      const double ratio = mb / (*hints.sd_card_gb * 1000);
      return ratio > 0.85 && ratio < 1.1;
    };
    std::set<std::string> fitting;
    if (near_label(total * 10)) fitting.insert("10mb");
    if (near_label(total * 0.1)) fitting.insert("0.1mb");
    decide(report, "sd_capacity_unit", fitting,
           both + format(", card label %.0f GB", *hints.sd_card_gb), "");
  } else {
    report.kept("sd_capacity_unit", default_of("sd_capacity_unit"),
                "not learnable from traffic alone (" + both + "): give --sd-card-gb");
  }
}

// The shutters the camera offers (3.2.3.x, decision A7).
constexpr std::array<double, 14> kShutterDenominators = {4,   8,    15,   30,   60,   125,  250,
                                                         500, 1000, 2000, 4000, 5000, 6000, 8000};

double shutter_code_us(uint8_t code) {
  return code >= 1 && code <= kShutterDenominators.size() ? 1e6 / kShutterDenominators[code - 1]
                                                          : 0;
}

// Whether a 0x000005 shutter value fits a reading: at a manual shutter (read back from 0x010200)
// the value that reading puts on the wire; in auto exposure any shutter the camera offers,
// 1/8000 .. 1/4 s (65535 is a saturated "us" and tells nothing).
bool shutter_fits(protocol::ShutterField reading, uint16_t raw, double manual_us) {
  if (manual_us > 0) return std::abs(raw - protocol::shutter_to_wire(manual_us, reading)) <= 1;
  if (reading == protocol::ShutterField::kMicroseconds && raw == 65535) return true;
  const double us = protocol::shutter_us_from_wire(raw, reading);
  return us >= 1e6 / 8000 * 0.99 && us <= 1e6 / 4 * 1.01;
}

void learn_shutter_field(const ProbeLink& link, ProbeReport& report) {
  double manual_us = 0;
  std::string evidence;
  const std::optional<HeardFrame> settings = link.latest(protocol::VisibleSettingsAck::kId);
  if (settings && settings->payload.size() >= 11 && settings->payload[10] != 0) {
    manual_us = shutter_code_us(settings->payload[10]);
    evidence = format("0x010200 shutter 1/%.0f s", 1e6 / manual_us) + ", ";
  }
  const std::vector<HeardFrame> reports = link.frames(protocol::VisibleStatus::kId);
  if (reports.empty()) {
    report.kept("shutter_field", default_of("shutter_field"), "no 0x000005 heard");
    return;
  }
  std::set<std::string> fitting;
  for (const auto& [reading, reading_name] :
       alternatives<protocol::ShutterField>("shutter_field")) {
    bool all = true;
    for (const HeardFrame& f : reports) {
      if (f.payload.size() >= 10)
        all = all && shutter_fits(reading, u16_little(f.payload, 8), manual_us);
    }
    if (all) fitting.insert(reading_name);
  }
  evidence += "0x000005 shutter " + std::to_string(u16_little(reports.back().payload, 8));
  decide(report, "shutter_field", fitting, evidence,
         "these read this shutter alike (a manual 1/4 s shutter tells all three apart)");
}

void learn_thermal_read_back(const ProbeLink& link, ProbeReport& report) {
  const std::optional<HeardFrame> ack = link.latest(protocol::ThermalSettingsAck::kId);
  if (!ack || ack->payload.size() < 10) {
    report.kept("enhancement_switch", default_of("enhancement_switch"), "no 0x010100 read back");
    report.kept("thermal_zoom_code", default_of("thermal_zoom_code"), "no 0x010100 read back");
    return;
  }
  // Byte 10: each reading gives a switch and a level. 0x00010E sets one number, "0 off, 1-10
  // level", so a pod's switch says on exactly when its level is not 0; the switch bit is kept
  // here (enhancement_from_wire reads any level as on, which cannot tell the readings apart).
  const uint8_t b = ack->payload[9];
  auto consistent = [](bool on, int level) { return level <= 10 && on == (level > 0); };
  std::set<std::string> fitting;
  if (consistent(b & 0x80, b & 0x7F)) fitting.insert("bit7");
  if (consistent(b & 0x01, b >> 1)) fitting.insert("bit0");
  if (consistent(b > 0, b)) fitting.insert("level");
  decide(report, "enhancement_switch", fitting, "0x010100 byte 10 = " + std::to_string(b),
         "enhancement off reads 0 under every reading");
  // Byte 4 bits 3-7: the ratio 1..8 under each reading.
  const uint8_t zoom = ack->payload[3] >> 3;
  fitting.clear();
  for (const auto& [reading, reading_name] :
       alternatives<protocol::ThermalZoomCode>("thermal_zoom_code")) {
    if (protocol::thermal_zoom_fits(zoom, reading)) fitting.insert(reading_name);
  }
  decide(report, "thermal_zoom_code", fitting, format("0x010100 zoom code %.0f", zoom),
         "codes 1..7 read as both (at 1x a ratio pod shows 1, a zero-based pod 0)");
}

}  // namespace

void learn_from_traffic(const ProbeLink& link, const ProbeHints& hints, ProbeReport& report) {
  learn_crc_coverage(link, report);
  learn_ack_byte_order(link, report);
  learn_system_id(link, report, "gimbal_system_id",
                  {protocol::GimbalStatus::kId, protocol::GimbalAttitude::kId}, "gimbal reports");
  learn_system_id(link, report, "camera_system_id",
                  {protocol::CameraSystemStatus::kId, protocol::VisibleStatus::kId},
                  "camera reports");
  learn_yaw_range(link, report);
  learn_sd_capacity_unit(link, hints, report);
  learn_shutter_field(link, report);
  learn_thermal_read_back(link, report);
}

}  // namespace k40t::tool
