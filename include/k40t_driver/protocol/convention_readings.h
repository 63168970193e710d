// What each open reading of the document (convention_values.h, docs/protocol/decisions.md
// #conventions) does to the values of a message, both ways:
//   - *_from_wire: a message decoded by the layouts (which read every field the default way) ->
//     the true values in the project's own terms (0x000002 yaw right-positive, pitch up-positive,
//     roll right-down-positive, -180..180; capacities in MB; shutter in us; enhancement level);
//     the driver applies them to everything it receives;
//   - *_to_wire: the true values -> what a pod following that reading puts in the message; the
//     simulator plays each reading with them;
//   - *_fits: whether a received value can be read under a reading at all (auto-detection and the
//     `conventions` diagnostic's contradictions).
#pragma once

#include <cstdint>

#include "k40t_driver/protocol/codec_options.h"
#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/messages/camera_enums.h"
#include "k40t_driver/protocol/messages/camera_reports.h"
#include "k40t_driver/protocol/messages/flight_controller.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/protocol/messages/thermal.h"

namespace k40t::protocol {

// ---- 0x000002: signs and yaw range -------------------------------------------------------
// `range` is the yaw range in force (kSigned or kHeading; kAuto reads as kSigned).
void attitude_from_wire(GimbalAttitude& m, const Conventions& c, YawRange range);
// The simulator: true angles (right, up, right-down positive, +-180) -> the pod's reading. A
// heading above 327.67 deg is carried by the int16 field's bits (value - 655.36).
void attitude_to_wire(GimbalAttitude& m, const Conventions& c);
// What one report's yaws (decoded as signed) show: kHeading (a yaw beyond +-180 deg: above 180,
// or a uint16 above 327.67), kSigned (a yaw in -180..0, which no 0..360 heading can be), or
// kAuto (0..180: both readings agree, nothing learnt).
YawRange yaw_range_evidence(const GimbalAttitude& as_decoded);
// +1 or -1: the factor from the pod's sign to the project's (yaw right, pitch up, roll right-down).
double yaw_factor(const Conventions& c);
double pitch_factor(const Conventions& c);

// ---- 0x000003: SD capacities ---------------------------------------------------------------
void sd_capacities_from_wire(CameraSystemStatus& m, const Conventions& c);
// The value to put in a capacity field for `true_mb` (rounded down to the reading's unit), so
// that the layout (which counts 10 MB) writes the counts of the reading.
double sd_capacity_to_wire(double true_mb, const Conventions& c);

// ---- 0x000005: shutter ----------------------------------------------------------------------
double shutter_us_from_wire(uint16_t raw, ShutterField field);
uint16_t shutter_to_wire(double true_us, ShutterField field);

// ---- ACK 0x010100 byte 10: thermal enhancement ------------------------------------------------
struct Enhancement {
  bool on = false;
  uint8_t level = 0;  // 0..10
};
// Under every reading a non-zero level is on (decision T7), whatever the switch bit says.
Enhancement enhancement_from_wire(const ThermalSettingsAck& m, EnhancementSwitch reading);
void enhancement_to_wire(ThermalSettingsAck& m, uint8_t level, EnhancementSwitch reading);
// The byte's level under `reading` is 0..10 (kThermalEnhancementMax).
bool enhancement_fits(const ThermalSettingsAck& m, EnhancementSwitch reading);

// ---- ACK 0x010100 byte 4 bits 3-7: thermal zoom --------------------------------------------
uint8_t thermal_zoom_from_wire(uint8_t code, ThermalZoomCode reading);
uint8_t thermal_zoom_to_wire(uint8_t ratio, ThermalZoomCode reading);
bool thermal_zoom_fits(uint8_t code, ThermalZoomCode reading);  // the ratio is 1..8

// ---- 0x000310 / ACK 0x010310: the GPS request's time and the answer's byte order ------------
// The UTC milliseconds of the day of the request's time of day (local: UTC = local +
// minutes_west, the zone the driver sends with its time syncs).
int64_t gps_request_utc_ms_of_day(const CameraGpsRequest& m, GpsRequestTime reading,
                                  int minutes_west);
// The simulator: the time of day a pod following `reading` puts in its request.
void gps_request_time_to_wire(CameraGpsRequest& m, int64_t utc_ms_of_day, GpsRequestTime reading,
                              int minutes_west);
// The answer: the response code in ack_byte_order, its data in gps_answer_byte_order.
Result<Payload> encode_gps_answer(const CameraGpsAck& m, const CodecOptions& o);
Result<CameraGpsAck> decode_gps_answer(const uint8_t* data, size_t size, const CodecOptions& o);

// ---- ACK 0x010320: no laser return -------------------------------------------------------------
// An OK answer at latitude 0, longitude 0 that the reading says means "no return".
bool laser_target_no_return(const TargetGpsAck& m, LaserTargetZeros reading);

// ---- 0x000313: manual focus direction
// ------------------------------------------------------------ The code that focuses nearer (or
// farther) under the reading: 1 "+" or 2 "-".
FocusCommand manual_focus_command(bool nearer, FocusPlus reading);
// The simulator: whether a code 1/2 focuses nearer.
bool manual_focus_is_nearer(FocusCommand command, FocusPlus reading);

}  // namespace k40t::protocol
