// DJI Pilot widgets of the K40T (APP function set 0x02, ids 0x04..0x08, sections 3.2.4..3.2.8):
//   0 choose list "Palette"      ten of the pod's 20 thermal palettes, named as
//   cfg/setting_enums.txt
//                                names them (dynamic_reconfigure)
//   1 choose list "Image mode"   thermal, visible, split screen (dynamic_reconfigure)
//   2 button      "Laser range"  one ranging (laser/measure) per press (value 1 = pressed down, 0 =
//                                released, as DJI's headers number the button states); the result
//                                as a floating window
//   3 switch      "Record"       record start/stop; reads back the pod's recording state
// All values fit one group.
#include <algorithm>  // std::replace
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <string>

#include "k40t_driver/protocol/messages/thermal.h"
#include "k40t_driver/skyport/skyport_bridge.h"

namespace k40t::driver::skyport {

using namespace psdk;
using detail::refused;

namespace {

enum Widget : uint8_t { kPalette = 0, kImageMode = 1, kLaser = 2, kRecord = 3, kWidgetCount = 4 };

struct Choice {
  std::string name;  // at most 15 bytes (3.2.5)
  int pod_value;
};

char upper(char c) {
  return static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
}

// A palette's name (cfg/setting_enums.txt, the protocol's to_string) as a widget item: "iron_red"
// -> "Iron red"; a name longer than an item's 15 bytes keeps its last word and the initials of
// the others ("high_contrast_rainbow" -> "HC rainbow").
std::string palette_label(protocol::Palette palette) {
  std::string label = protocol::to_string(palette);
  std::replace(label.begin(), label.end(), '_', ' ');
  if (label.size() >= kChooseItemNameSize) {  // 15 bytes + NUL
    const size_t last = label.rfind(' ');
    std::string initials;
    for (size_t i = 0; i < last; i = label.find(' ', i) + 1) initials += upper(label[i]);
    return initials + label.substr(last);
  }
  label[0] = upper(label[0]);
  return label;
}

// Ten of K40t.cfg's palettes.
const std::array<Choice, 10>& palettes() {
  static const std::array<Choice, 10> choices = [] {
    using P = protocol::Palette;
    std::array<Choice, 10> c;
    const std::array<P, 10> offered{
        P::kWhiteHot, P::kBlackHot, P::kRainbow,    P::kHighContrastRainbow, P::kIronRed,
        P::kMagma,    P::kSky,      P::kMediumGrey, P::kWarningRed,          P::kIceFire};
    for (size_t i = 0; i < c.size(); ++i) {
      c[i] = {palette_label(offered[i]), static_cast<int>(offered[i])};
    }
    return c;
  }();
  return choices;
}
// K40t.cfg's image modes.
const std::array<Choice, 3> kImageModes{{{"Thermal", 0}, {"Visible", 5}, {"Split", 7}}};

template <size_t N>
void fill_choices(WidgetListDataAck& ack, const std::array<Choice, N>& choices) {
  ack.choose_item_count = static_cast<uint8_t>(N);
  for (size_t i = 0; i < N; ++i) ack.choose_items[i] = choices[i].name;
}

WidgetListDataAck describe_widget(uint8_t index) {
  WidgetListDataAck ack;
  ack.index = index;
  switch (index) {
    case kPalette:
      ack.type = WidgetType::kChooseList;
      ack.name = "Palette";
      fill_choices(ack, palettes());
      break;
    case kImageMode:
      ack.type = WidgetType::kChooseList;
      ack.name = "Image mode";
      fill_choices(ack, kImageModes);
      break;
    case kLaser:
      ack.type = WidgetType::kButton;
      ack.name = "Laser range";
      break;
    case kRecord:
      ack.type = WidgetType::kSwitch;
      ack.name = "Record";
      break;
    default:
      return refused<WidgetListDataAck>(AckCode::kError);
  }
  return ack;
}

int32_t image_mode_item(uint8_t pod_image_mode) {
  for (size_t i = 0; i < kImageModes.size(); ++i) {
    if (kImageModes[i].pod_value == pod_image_mode) return static_cast<int32_t>(i);
  }
  return pod_image_mode == 6 ? 1 : 0;  // the document's second code for visible
}

}  // namespace

void SkyportBridge::register_widgets() {
  session_.handle<GetWidgetListLength>([](const GetWidgetListLength&) {
    WidgetListLengthAck ack;
    ack.count = kWidgetCount;
    return ack;
  });
  session_.handle<GetWidgetListData>(
      [](const GetWidgetListData& c) { return describe_widget(c.index); });
  session_.handle<GetWidgetGroupCount>([](const GetWidgetGroupCount&) {
    WidgetGroupCountAck ack;
    ack.count = 1;
    return ack;
  });
  session_.handle<GetWidgetGroupData>([this](const GetWidgetGroupData& c) {
    if (c.group != 0) return refused<WidgetGroupDataAck>(AckCode::kError);
    const PodSnapshot s = pod_.snapshot();
    WidgetGroupDataAck ack;
    ack.count = kWidgetCount;
    int32_t palette_item = 0;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      palette_item = palette_item_;
    }
    ack.widgets[kPalette] = {WidgetType::kChooseList, kPalette, palette_item};
    ack.widgets[kImageMode] = {WidgetType::kChooseList, kImageMode, image_mode_item(s.image_mode)};
    ack.widgets[kLaser] = {WidgetType::kButton, kLaser, 0};
    ack.widgets[kRecord] = {WidgetType::kSwitch, kRecord, s.recording ? 1 : 0};
    return ack;
  });
  deferred<SetWidgetValue>([this](const SetWidgetValue& c) { return set_widget(c.widget); });
}

AckCode SkyportBridge::set_widget(const WidgetValue& widget) {
  const int32_t v = widget.value;
  switch (widget.index) {
    case kPalette: {
      if (v < 0 || v >= static_cast<int32_t>(palettes().size()))
        return invalid("palette widget: no item " + std::to_string(v));
      const AckCode code = pod_code(pod_.set_palette(palettes()[v].pod_value), "palette widget");
      if (code == AckCode::kOk) {
        std::lock_guard<std::mutex> lock(mutex_);
        palette_item_ = v;
      }
      return code;
    }
    case kImageMode:
      if (v < 0 || v >= static_cast<int32_t>(kImageModes.size()))
        return invalid("image mode widget: no item " + std::to_string(v));
      return pod_code(pod_.set_image_mode(kImageModes[v].pod_value), "image mode widget");
    case kLaser: {
      // One tap is a press then a release: range on the press only, once until released.
      if (v != 0 && v != 1) return invalid("laser button: value " + std::to_string(v));
      const bool was_pressed = laser_pressed_;
      laser_pressed_ = v == 1;
      if (v == 0 || was_pressed) return AckCode::kOk;
      double range_m = 0;
      const AckCode code = pod_code(pod_.measure_range(range_m), "laser widget");
      if (code != AckCode::kOk) return code;
      char text[64];
      if (std::isfinite(range_m)) {
        std::snprintf(text, sizeof text, "K40T laser range: %.1f m", range_m);
      } else {
        std::snprintf(text, sizeof text, "K40T laser range: no return");
      }
      floating_window(text);
      return code;
    }
    case kRecord:
      if (v != 0 && v != 1) return invalid("record switch: value " + std::to_string(v));
      return pod_code(pod_.record(v == 1), "record widget");
    default:
      return invalid("no widget " + std::to_string(widget.index));
  }
}

void SkyportBridge::floating_window(const std::string& text) {
  FloatingWindowMessage message;
  message.text = text.substr(0, 127);
  const Status sent = session_.send(message);
  if (!sent && log_) log_("SKYPORT floating window: " + sent.message());
}

}  // namespace k40t::driver::skyport
