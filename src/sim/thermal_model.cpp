#include "k40t_driver/sim/thermal_model.h"

#include <algorithm>
#include <cmath>

#include "k40t_driver/sim/lens.h"

namespace k40t::sim {

namespace {
constexpr double kFrameScaleX =
    double(ThermalFrame::kRight + 1 - ThermalFrame::kLeft) / kThermalWidthPx;
constexpr double kFrameScaleY =
    double(ThermalFrame::kBottom + 1 - ThermalFrame::kTop) / kThermalHeightPx;
constexpr int kGridStepPx = 8;  // coarse search; the extremes are then refined pixel by pixel

struct SensorRect {
  int u0, v0, u1, v1;  // inclusive
};

struct Sample {
  int u = 0;
  int v = 0;
  double degC = 0;
};

// Renders single thermal pixels of the world as the camera sees it now.
class ThermalView {
 public:
  ThermalView(const World& world, double yaw_deg, double pitch_deg, int digital_zoom)
      : world_(world), basis_(camera_basis(yaw_deg, pitch_deg)) {
    const FieldOfView fov = field_of_view(Lens::kThermal, digital_zoom);
    tan_half_h_ = std::tan(deg_to_rad(fov.horizontal_deg / 2));
    tan_half_v_ = std::tan(deg_to_rad(fov.vertical_deg / 2));
  }
  double at(double u, double v) const {
    const double nx = (u + 0.5 - kThermalWidthPx / 2.0) / (kThermalWidthPx / 2.0) * tan_half_h_;
    const double ny = -(v + 0.5 - kThermalHeightPx / 2.0) / (kThermalHeightPx / 2.0) * tan_half_v_;
    return world_.trace(normalized(basis_.forward + basis_.right * nx + basis_.up * ny))
        .temperature_degC;
  }

 private:
  const World& world_;
  CameraBasis basis_;
  double tan_half_h_ = 0;
  double tan_half_v_ = 0;
};

// Every sample of a range with `step`, always including the last value.
template <class F>
void for_each_step(int first, int last, int step, F&& f) {
  for (int i = first;; i += step) {
    if (i >= last) {
      f(last);
      return;
    }
    f(i);
  }
}

template <class Better>
Sample refine(const ThermalView& view, const SensorRect& rect, Sample best, Better better) {
  const Sample coarse = best;
  for (int v = std::max(rect.v0, coarse.v - kGridStepPx + 1);
       v <= std::min(rect.v1, coarse.v + kGridStepPx - 1); ++v) {
    for (int u = std::max(rect.u0, coarse.u - kGridStepPx + 1);
         u <= std::min(rect.u1, coarse.u + kGridStepPx - 1); ++u) {
      const double t = view.at(u, v);
      if (better(t, best.degC)) best = {u, v, t};
    }
  }
  return best;
}

int sensor_index(double coordinate, int size) {
  return std::clamp(static_cast<int>(std::floor(coordinate)), 0, size - 1);
}
}  // namespace

PixelPoint ThermalFrame::from_sensor(double u, double v) {
  return {kLeft + static_cast<int>(std::floor((u + 0.5) * kFrameScaleX)),
          kTop + static_cast<int>(std::floor((v + 0.5) * kFrameScaleY))};
}
double ThermalFrame::sensor_u(double x) {
  return (x + 0.5 - kLeft) / kFrameScaleX;
}
double ThermalFrame::sensor_v(double y) {
  return (y + 0.5 - kTop) / kFrameScaleY;
}

protocol::ThermalSettingsAck factory_thermal_settings() {
  protocol::ThermalSettingsAck s;
  s.palette = protocol::Palette::kWhiteHot;
  s.measurement_on = true;
  s.measurement_type = MeasurementType::kArea;
  s.core_type = protocol::ThermalCoreType::kRadiometric;
  s.zoom_x = 1;
  s.sharpness = 50;
  s.gain_mode = GainMode::kHigh;
  s.brightness = 50;
  s.contrast = 50;
  s.denoise_on = true;
  s.denoise_level = 50;
  s.enhancement_on = false;
  s.enhancement_level = 0;
  s.high_alarm_on = s.low_alarm_on = s.difference_alarm_on = false;  // -2732 on the wire
  s.threshold_alarm_on = false;
  s.threshold_reference_degC = 0;  // -30..50
  s.threshold_float_degC = 10;     // 0..80
  return s;
}

GainRange gain_range(GainMode mode) {
  // High gain: fine resolution over everyday temperatures; low gain: up to hot engines and fires.
  return mode == GainMode::kLow ? GainRange{-40, 550} : GainRange{-40, 150};
}

Outcome ThermalModel::set_digital_zoom(int zoom) {
  if (zoom < 1 || zoom > 8) return Outcome::kFailure;
  settings_.reported.zoom_x = static_cast<uint8_t>(zoom);
  return Outcome::kOk;
}

Outcome ThermalModel::set_spot(int x, int y) {
  if (!ThermalFrame::inside(x, y)) return Outcome::kFailure;  // on the black border
  settings_.spot = {x, y};
  settings_.reported.measurement_type = MeasurementType::kPoint;
  return Outcome::kOk;
}

Outcome ThermalModel::set_area(int width, int height, int centre_x, int centre_y) {
  // Section 3.2.2.11 note: half the frame plus the centre must stay inside the image.
  if (width < 1 || height < 1) return Outcome::kFailure;
  if (!ThermalFrame::inside(centre_x - width / 2, centre_y - height / 2) ||
      !ThermalFrame::inside(centre_x + width / 2, centre_y + height / 2)) {
    return Outcome::kFailure;
  }
  settings_.area = {width, height, centre_x, centre_y};
  settings_.reported.measurement_type = MeasurementType::kArea;
  return Outcome::kOk;
}

Outcome ThermalModel::set_alarms(std::optional<double> high_degC, std::optional<double> low_degC,
                                 std::optional<double> difference_degC) {
  const auto in = [](const std::optional<double>& v, double lo, double hi) {
    return !v || (*v >= lo && *v <= hi);
  };
  if (!in(high_degC, -100, 500) || !in(low_degC, -100, 500) || !in(difference_degC, 0.1, 600)) {
    return Outcome::kFailure;  // "If other values are set, the command reporting setting fails"
  }
  protocol::ThermalSettingsAck& r = settings_.reported;
  r.high_alarm_on = high_degC.has_value();
  r.high_alarm_degC = high_degC.value_or(0);
  r.low_alarm_on = low_degC.has_value();
  r.low_alarm_degC = low_degC.value_or(0);
  r.difference_alarm_on = difference_degC.has_value();
  r.difference_alarm_degC = difference_degC.value_or(0);
  return Outcome::kOk;
}

Outcome ThermalModel::set_threshold_alarm(bool on, double reference_degC, double float_degC) {
  if (reference_degC < -30 || reference_degC > 50 || float_degC < 0 || float_degC > 80)
    return Outcome::kFailure;
  settings_.reported.threshold_alarm_on = on;
  settings_.reported.threshold_reference_degC = reference_degC;
  settings_.reported.threshold_float_degC = float_degC;
  return Outcome::kOk;
}

ThermalStats ThermalModel::measure(const World& world, double yaw_deg, double pitch_deg) const {
  const ThermalView view(world, yaw_deg, pitch_deg, settings_.reported.zoom_x);

  SensorRect rect{0, 0, kThermalWidthPx - 1, kThermalHeightPx - 1};
  if (settings_.reported.measurement_type == MeasurementType::kArea && settings_.area.width > 0 &&
      settings_.area.height > 0) {
    const MeasurementArea& a = settings_.area;
    rect = {sensor_index(ThermalFrame::sensor_u(a.centre_x - a.width / 2), kThermalWidthPx),
            sensor_index(ThermalFrame::sensor_v(a.centre_y - a.height / 2), kThermalHeightPx),
            sensor_index(ThermalFrame::sensor_u(a.centre_x + a.width / 2), kThermalWidthPx),
            sensor_index(ThermalFrame::sensor_v(a.centre_y + a.height / 2), kThermalHeightPx)};
  }

  Sample hottest{rect.u0, rect.v0, -1e9};
  Sample coldest{rect.u0, rect.v0, 1e9};
  double sum = 0;
  int count = 0;
  for_each_step(rect.v0, rect.v1, kGridStepPx, [&](int v) {
    for_each_step(rect.u0, rect.u1, kGridStepPx, [&](int u) {
      const double t = view.at(u, v);
      if (t > hottest.degC) hottest = {u, v, t};
      if (t < coldest.degC) coldest = {u, v, t};
      sum += t;
      ++count;
    });
  });
  hottest = refine(view, rect, hottest, [](double a, double b) { return a > b; });
  coldest = refine(view, rect, coldest, [](double a, double b) { return a < b; });

  // Auto gain switches to low gain when the scene is too hot for high gain.
  GainMode gain = settings_.reported.gain_mode;
  if (gain == GainMode::kAuto)
    gain = hottest.degC > gain_range(GainMode::kHigh).max_degC ? GainMode::kLow : GainMode::kHigh;
  const GainRange range = gain_range(gain);
  const auto reading = [&](double t) { return std::clamp(t, range.min_degC, range.max_degC); };

  ThermalStats stats;
  stats.max_degC = reading(hottest.degC);
  stats.min_degC = reading(coldest.degC);
  stats.average_degC = reading(sum / count);
  stats.max_at = ThermalFrame::from_sensor(hottest.u, hottest.v);
  stats.min_at = ThermalFrame::from_sensor(coldest.u, coldest.v);
  const int centre_u = (rect.u0 + rect.u1) / 2;
  const int centre_v = (rect.v0 + rect.v1) / 2;
  stats.centre_degC = reading(view.at(centre_u, centre_v));
  stats.centre_at = ThermalFrame::from_sensor(centre_u, centre_v);
  const int spot_u = sensor_index(ThermalFrame::sensor_u(settings_.spot.x), kThermalWidthPx);
  const int spot_v = sensor_index(ThermalFrame::sensor_v(settings_.spot.y), kThermalHeightPx);
  stats.spot_degC = reading(view.at(spot_u, spot_v));
  stats.spot_at = settings_.spot;

  const protocol::ThermalSettingsAck& s = settings_.reported;
  stats.high_alarm = s.high_alarm_on && stats.max_degC >= s.high_alarm_degC;
  stats.low_alarm = s.low_alarm_on && stats.min_degC <= s.low_alarm_degC;
  stats.difference_alarm =
      s.difference_alarm_on && stats.max_degC - stats.min_degC >= s.difference_alarm_degC;
  // Threshold alarm: something in the region leaves reference +- float.
  stats.threshold_alarm = s.threshold_alarm_on &&
                          (stats.max_degC > s.threshold_reference_degC + s.threshold_float_degC ||
                           stats.min_degC < s.threshold_reference_degC - s.threshold_float_degC);
  return stats;
}

}  // namespace k40t::sim
