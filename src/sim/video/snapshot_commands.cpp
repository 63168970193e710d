#include "k40t_driver/sim/video/snapshot_commands.h"

#include <cmath>
#include <sstream>
#include <vector>

#include "k40t_driver/sim/video/palette.h"

namespace k40t::sim::video {

namespace {

// Every word after the command, as numbers; nothing if one is not a number.
std::optional<std::vector<double>> numbers(std::istringstream& in) {
  std::vector<double> values;
  std::string word;
  while (in >> word) {
    size_t used = 0;
    double value = 0;
    try {
      value = std::stod(word, &used);
    } catch (const std::exception&) {
      return std::nullopt;
    }
    if (used != word.size() || !std::isfinite(value)) return std::nullopt;
    values.push_back(value);
  }
  return values;
}

Status usage(const std::string& command, const std::string& expected) {
  return Status::fail("'" + command + "' expects " + expected);
}

bool in_range(double v, double lo, double hi) {
  return v >= lo && v <= hi;
}

bool is_integer(double v) {
  return v == std::floor(v);
}

}  // namespace

Status apply_command(const std::string& line, VideoSnapshot& snapshot) {
  std::istringstream in(line);
  std::string command;
  if (!(in >> command) || command[0] == '#') return Status::ok();
  const std::optional<std::vector<double>> args = numbers(in);
  const size_t count = args ? args->size() : 0;
  const double a = count > 0 ? (*args)[0] : 0;

  if (command == "mode") {
    if (count != 1 || !is_integer(a) || !is_image_mode(static_cast<int>(a))) {
      return usage(command, "one image mode: 0 (thermal), 5 or 6 (visible), 7 (split screen)");
    }
    snapshot.image_mode = static_cast<ImageMode>(static_cast<int>(a));
  } else if (command == "palette") {
    if (count != 1 || !is_integer(a) || !in_range(a, kFirstPalette, kLastPalette)) {
      return usage(command, "one palette code 1..20");
    }
    snapshot.palette = static_cast<int>(a);
  } else if (command == "zoom") {
    if (count != 1 || !in_range(a, 1, 160)) return usage(command, "one zoom ratio 1..160");
    snapshot.hybrid_zoom = a;
  } else if (command == "thermal_zoom") {
    if (count != 1 || !is_integer(a) || !in_range(a, 1, 8)) {
      return usage(command, "one digital zoom 1..8 (integer)");
    }
    snapshot.thermal_zoom = static_cast<int>(a);
  } else if (command == "gimbal") {
    if (count != 2 || !in_range((*args)[1], -90, 90)) {
      return usage(command, "a yaw and a pitch in degrees, pitch -90..90");
    }
    snapshot.yaw_deg = a;
    snapshot.pitch_deg = (*args)[1];
  } else if (command == "resolution") {
    if (count != 1 || (a != 1080 && a != 720)) return usage(command, "1080 or 720");
    snapshot.resolution = a == 720 ? StreamResolution::k720p : StreamResolution::k1080p;
  } else {
    return Status::fail("unknown command '" + command +
                        "' (mode, palette, zoom, thermal_zoom, gimbal, resolution)");
  }
  return Status::ok();
}

}  // namespace k40t::sim::video
