#include "k40t_driver/video/stream_view.h"

#include "k40t_driver/codec/enum_names.h"

namespace k40t::video {

const char* to_string(Lens lens) {
  static constexpr EnumName<Lens> kNames[] = {
      {Lens::kWide, "wide"}, {Lens::kThermal, "thermal"}, {Lens::kTele, "tele"}};
  return name_in(kNames, lens, "tele");
}

StreamView stream_view(std::optional<int> image_mode, cv::Size frame, Lens mode6_lens) {
  if (frame == cv::Size(kThermalWidth, kThermalHeight)) return {Lens::kThermal, false};
  if (image_mode == 7) return {Lens::kTele, true};
  if (image_mode == 6) return {mode6_lens, false};
  return {Lens::kTele, false};
}

SplitLayout split_layout(cv::Size frame) {
  const int half = frame.width / 2;
  const cv::Size visible(half, frame.height / 2);
  const cv::Size thermal(half, half * kThermalHeight / kThermalWidth);
  return {{0, (frame.height - visible.height) / 2, visible.width, visible.height},
          {half, (frame.height - thermal.height) / 2, thermal.width, thermal.height}};
}

}  // namespace k40t::video
