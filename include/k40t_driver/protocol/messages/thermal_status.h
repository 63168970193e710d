// The thermal camera's 5 Hz status report 0x000004 (document section 3.2.1.2, system 0x04).
// Temperatures are int16 in 0.1 degC on the wire and double degC here; pixel coordinates are in
// the 1920x1088 picture the document's measurement commands use (black border included).
// The settings and their read-back are in thermal.h; enums and ranges in thermal_types.h.
#pragma once

#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/message_layout.h"
#include "k40t_driver/protocol/messages/thermal_types.h"

namespace k40t::protocol {

// ---- 0x000004, section 3.2.1.2, 5 Hz ---------------------------------------------------------
// Area measurement fills max/min/centre/average and their coordinates; point measurement fills
// point_degC and its coordinates.
struct ThermalStatus {
  // kMinSize: the 4 reserved bytes are optional on receive
  K40T_POD_REPORT(0x000004, "thermal_status", "3.2.1.2", 34, 30);

  double max_degC = 0;
  double min_degC = 0;
  double center_degC = 0;
  double point_degC = 0;
  double average_degC = 0;
  uint16_t max_x_px = 0;
  uint16_t max_y_px = 0;
  uint16_t min_x_px = 0;
  uint16_t min_y_px = 0;
  uint16_t center_x_px = 0;
  uint16_t center_y_px = 0;
  uint16_t point_x_px = 0;
  uint16_t point_y_px = 0;
  bool high_alarm = false;
  bool low_alarm = false;
  bool difference_alarm = false;
  bool threshold_alarm = false;

  K40T_LAYOUT(s, v) {
    constexpr auto degC =
        wire::scaled<int16_t>(10).range(kThermalDeciDegMin, kThermalDeciDegMax, "degC");
    v("max_degC", s.max_degC, degC);
    v("min_degC", s.min_degC, degC);
    v("center_degC", s.center_degC, degC);
    v("point_degC", s.point_degC, degC);
    v("average_degC", s.average_degC, degC);
    v("max_x_px", s.max_x_px, wire::u16);
    v("max_y_px", s.max_y_px, wire::u16);
    v("min_x_px", s.min_x_px, wire::u16);
    v("min_y_px", s.min_y_px, wire::u16);
    v("center_x_px", s.center_x_px, wire::u16);
    v("center_y_px", s.center_y_px, wire::u16);
    v("point_x_px", s.point_x_px, wire::u16);
    v("point_y_px", s.point_y_px, wire::u16);
    // A report is what the pod says: any non-zero flag byte counts as "alarm".
    v("high_alarm", s.high_alarm, wire::u8);
    v("low_alarm", s.low_alarm, wire::u8);
    v("difference_alarm", s.difference_alarm, wire::u8);
    v("threshold_alarm", s.threshold_alarm, wire::u8);
    v("reserved", wire::gap, wire::reserved(4));
  }
};

}  // namespace k40t::protocol
