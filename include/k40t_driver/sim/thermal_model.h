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

enum class MeasurementType : uint8_t { kPoint = 0, kArea = 1 };
enum class GainMode : uint8_t { kHigh = 0, kLow = 1, kAuto = 2 };

struct MeasurementArea {
  int width = 0;
  int height = 0;
  int centre_x = 800;
  int centre_y = 528;
};

// Stored as the pod returns them; codes the model does not interpret (palette, sharpness...) are
// kept as the document's numbers.
struct ThermalSettings {
  uint8_t palette = 1;  // 1..20, white hot
  bool measurement_on = true;
  MeasurementType measurement_type = MeasurementType::kArea;
  bool radiometric = true;   // "temperature measurement version" core
  uint8_t digital_zoom = 1;  // 1..8
  uint8_t sharpness = 50;
  GainMode gain = GainMode::kHigh;
  uint8_t brightness = 50;
  uint8_t contrast = 50;
  bool denoise_on = true;
  uint8_t denoise_level = 50;
  uint8_t enhancement = 0;  // 0 off, 1..10
  bool overlay = false;
  std::optional<double> high_alarm_degC;  // none = off (-2732 on the wire)
  std::optional<double> low_alarm_degC;
  std::optional<double> difference_alarm_degC;
  bool threshold_alarm_on = false;
  double threshold_reference_degC = 0;  // -30..50
  double threshold_float_degC = 10;     // 0..80
  PixelPoint spot{800, 528};            // the frame's centre
  MeasurementArea area;                 // width/height 0 = whole image
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
  ThermalSettings& settings() { return settings_; }
  const ThermalSettings& settings() const { return settings_; }

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
