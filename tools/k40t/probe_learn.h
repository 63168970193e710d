// k40t probe's learners: each one looks at the frames the pod sent (raw bytes, so that every
// reading can be tried on them) and puts what it found, or why it could not, into the report.
// The names are the driver parameters of protocol/conventions.h (docs/protocol/decisions.md
// #conventions).
#pragma once

#include <optional>
#include <string>

#include "k40t_driver/session/session.h"
#include "probe_link.h"
#include "probe_report.h"

namespace k40t::tool {

// What the user knows and the traffic cannot tell.
struct ProbeHints {
  std::optional<double> sd_card_gb;  // the card's label, for sd_capacity_unit
};

// From the frames heard so far (reports and the read-backs' ACKs): crc_coverage, ack_byte_order,
// the system ids, yaw_range, sd_capacity_unit, shutter_field, enhancement_switch,
// thermal_zoom_code.
void learn_from_traffic(const ProbeLink& link, const ProbeHints& hints, ProbeReport& report);

// With --allow-motion: yaw_sign, pitch_sign, angle_command_scale (and yaw_range when the yaw
// crosses zero). Small steps through 0x000012's direction bytes, then back where it was. Fails at
// the first refused or unanswered command or move that did not happen, after trying to return.
Status learn_from_motion(ProbeLink& link, ProbeReport& report, std::string& log);

// With --calibration: one drift calibration (0x000013), and how its end shows (calibration_end).
Status learn_calibration_end(ProbeLink& link, ProbeReport& report, std::string& log);

// Little-endian and big-endian 16-bit reads of a payload (callers check the size).
uint16_t u16_little(const std::vector<uint8_t>& p, size_t at);
uint16_t u16_big(const std::vector<uint8_t>& p, size_t at);

}  // namespace k40t::tool
