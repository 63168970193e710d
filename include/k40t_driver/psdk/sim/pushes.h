// The data pushes (set 0x03) a SKYPORT adapter sends, built from one airframe state so they
// agree with each other, and the rates they are sent at.
#pragma once

#include "k40t_driver/psdk/commands/data_push.h"
#include "k40t_driver/psdk/sim/flight_model.h"

namespace k40t::psdk::sim {

// Push rates in Hz; 0 turns a push off. The document gives no rates: these are this project's
// choice, in the range DJI's PSDK 1.x documentation describes (attitude fastest, GPS a few Hz,
// the slow-changing states at 1 Hz).
struct PushRates {
  double attitude_hz = 50;
  double gps_hz = 5;
  double raw_gps_hz = 5;
  double raw_rtk_hz = 5;
  double barometric_altitude_hz = 10;
  double battery_hz = 1;
  double uav_state_hz = 1;
  double link_bandwidth_hz = 1;
  double app_date_time_hz = 1;
  double utc_time_hz = 1;  // one per PPS pulse
  double other_payload_hz = 0.2;
};

AttitudePush attitude_push(const AirframeState& s);
GpsPush gps_push(const AirframeState& s, uint8_t satellites);
RawGpsPush raw_gps_push(const AirframeState& s, uint16_t counter);
RawRtkPush raw_rtk_push(const AirframeState& s);
BarometricAltitudePush barometric_altitude_push(const AirframeState& s);
BatteryInfoPush battery_push(const AirframeState& s);
UavStatePush uav_state_push(const AirframeState& s, DroneType type);
LinkBandwidthPush link_bandwidth_push(const AirframeState& s);
AppDateTimePush app_date_time_push(const AirframeState& s);
// The UTC time of the last whole second (the PPS edge) at or before the state's time.
UtcTimePush utc_time_push(const AirframeState& s);

}  // namespace k40t::psdk::sim
