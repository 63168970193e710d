// The thermal camera (section 3.2.2 settings, 3.2.1.2 report): every setting the read-all command
// 0x000100 returns, and the measurement itself, made by looking at the World through the
// gimbal's attitude and the thermal lens at its digital zoom. Max/min/average are searched over
// the measurement region (the whole image, or the rectangle of 0x000110 in area mode) on a grid,
// then refined pixel by pixel around the extremes; centre and spot are read where they are.
//
// Coordinates are those of the document's requests and report: the 1920x1088 output frame in
// which the 640x512 thermal image fills x 320..1279, y 32..1023 (section 3.2.2.10/3.2.2.11 notes).
#pragma once

#include <cstdint>
#include <optional>

#include "k40t_driver/protocol/messages/thermal.h"
#include "k40t_driver/sim/model_part.h"
#include "k40t_driver/sim/outcome.h"
#include "k40t_driver/sim/world.h"

namespace k40t::sim {

struct PixelPoint {
  int x = 0;
  int y = 0;
};

// The thermal image's place in the output frame.
struct ThermalFrame {
  static constexpr int kLeft = 320;
  static constexpr int kRight = 1279;
  static constexpr int kTop = 32;
  static constexpr int kBottom = 1023;
  static PixelPoint from_sensor(double u, double v);  // sensor pixel centre -> frame coordinates
  static double sensor_u(double x);                   // frame -> sensor (fractional)
  static double sensor_v(double y);
  static bool inside(int x, int y) {
    return x >= kLeft && x <= kRight && y >= kTop && y <= kBottom;
  }
};

// The sim speaks the protocol's codes: the measurement type and gain mode are those of 0x010100.
using MeasurementType = protocol::ThermalMeasurementType;
using GainMode = protocol::ThermalGainMode;

struct MeasurementArea {
  int width = 0;
  int height = 0;
  int centre_x = 800;
  int centre_y = 528;
};

// The settings the pod reports in the read-all ACK 0x010100 are kept as that ACK itself (the
// protocol's struct, with the simulated pod's factory defaults), so a reported setting needs no
// field of its own here: its request handler writes the ACK field and the read-all returns it.
protocol::ThermalSettingsAck factory_thermal_settings();

struct ThermalSettings {
  protocol::ThermalSettingsAck reported = factory_thermal_settings();
  // Set by requests but absent from 0x010100:
  bool overlay = false;       // 0x000125
  PixelPoint spot{800, 528};  // 0x00010F, the frame's centre
  MeasurementArea area;       // 0x000110, width/height 0 = whole image
};

struct ThermalStats {
  double max_degC = 0;
  double min_degC = 0;
  double centre_degC = 0;
  double spot_degC = 0;
  double average_degC = 0;
  PixelPoint max_at;
  PixelPoint min_at;
  PixelPoint centre_at;
  PixelPoint spot_at;
  bool high_alarm = false;
  bool low_alarm = false;
  bool difference_alarm = false;
  bool threshold_alarm = false;
};

// The range a gain mode can measure; readings saturate at its ends.
struct GainRange {
  double min_degC;
  double max_degC;
};
GainRange gain_range(GainMode mode);

class ThermalModel {
 public:
  K40T_MODEL_PART(ThermalSettings, settings)

  Outcome set_digital_zoom(int zoom);                                   // 1..8
  Outcome set_spot(int x, int y);                                       // inside the thermal image
  Outcome set_area(int width, int height, int centre_x, int centre_y);  // wholly inside it
  Outcome set_alarms(std::optional<double> high_degC, std::optional<double> low_degC,
                     std::optional<double> difference_degC);
  Outcome set_threshold_alarm(bool on, double reference_degC, double float_degC);

  // Looks at `world` along heading `yaw_deg` and elevation `pitch_deg` (world frame).
  ThermalStats measure(const World& world, double yaw_deg, double pitch_deg) const;

 private:
  ThermalSettings settings_;
};

}  // namespace k40t::sim
