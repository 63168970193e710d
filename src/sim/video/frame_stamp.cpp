#include "k40t_driver/sim/video/frame_stamp.h"

#include <array>
#include <chrono>

#include "k40t_driver/protocol/byte_io.h"
#include "k40t_driver/protocol/crc.h"

namespace k40t::sim::video {

namespace {
constexpr uint8_t kMagic = 'K';
constexpr uint8_t kVersion = 1;
constexpr size_t kBytes = kStampColumns * kStampRows / 8;  // 16
using StampBytes = std::array<uint8_t, kBytes>;

StampBytes encode(const FrameStamp& stamp) {
  StampBytes bytes{};
  protocol::ByteWriter writer(bytes.data(), bytes.size());
  writer.u8(kMagic);
  writer.u8(kVersion);
  writer.u32(stamp.counter);
  writer.i64(stamp.render_time_us);
  writer.u16(protocol::crc16(bytes.data(), writer.size()));
  return bytes;
}

// Block `bit` (0 = the first byte's most significant bit) of the grid, row-major.
cv::Rect block_rect(size_t bit) {
  const int column = static_cast<int>(bit % kStampColumns);
  const int row = static_cast<int>(bit / kStampColumns);
  return {column * kStampBlockPx, row * kStampBlockPx, kStampBlockPx, kStampBlockPx};
}

bool bit_of(const StampBytes& bytes, size_t bit) {
  return (bytes[bit / 8] >> (7 - bit % 8)) & 1;
}
}  // namespace

bool draw_frame_stamp(cv::Mat& bgr, const FrameStamp& stamp) {
  if (bgr.type() != CV_8UC3 || bgr.cols < kStampWidthPx || bgr.rows < kStampHeightPx) return false;
  const StampBytes bytes = encode(stamp);
  for (size_t bit = 0; bit < kBytes * 8; ++bit) {
    const uint8_t level = bit_of(bytes, bit) ? 255 : 0;
    bgr(block_rect(bit)).setTo(cv::Scalar(level, level, level));
  }
  return true;
}

std::optional<FrameStamp> read_frame_stamp(const cv::Mat& image) {
  if ((image.type() != CV_8UC3 && image.type() != CV_8UC1) || image.cols < kStampWidthPx ||
      image.rows < kStampHeightPx) {
    return std::nullopt;
  }
  StampBytes bytes{};
  for (size_t bit = 0; bit < kBytes * 8; ++bit) {
    // The centre 4 x 4 pixels: block edges blur into their neighbours after compression.
    const cv::Rect block = block_rect(bit);
    const cv::Rect centre(block.x + 2, block.y + 2, kStampBlockPx - 4, kStampBlockPx - 4);
    const cv::Scalar mean = cv::mean(image(centre));
    const double level = image.channels() == 3 ? (mean[0] + mean[1] + mean[2]) / 3 : mean[0];
    if (level >= 128) bytes[bit / 8] |= static_cast<uint8_t>(1 << (7 - bit % 8));
  }
  protocol::ByteReader reader(bytes.data(), bytes.size());
  const uint8_t magic = reader.u8();
  const uint8_t version = reader.u8();
  FrameStamp stamp;
  stamp.counter = reader.u32();
  stamp.render_time_us = reader.i64();
  const uint16_t crc = reader.u16();
  if (!reader.ok() || magic != kMagic || version != kVersion ||
      crc != protocol::crc16(bytes.data(), kBytes - 2)) {
    return std::nullopt;
  }
  return stamp;
}

int64_t system_time_us() {
  return std::chrono::duration_cast<std::chrono::microseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace k40t::sim::video
