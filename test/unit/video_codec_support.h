// Helpers of the codec and passthrough tests: NAL unit types of an Annex B access unit, read
// by hand from the standard (ITU-T H.264 section 7.3.1 / B.1: start code 00 00 01 or
// 00 00 00 01, then the NAL header whose low 5 bits are nal_unit_type: 5 IDR slice, 7 SPS,
// 8 PPS, 9 access unit delimiter, 1 non-IDR slice), and PSNR.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

namespace k40t::video::testing {

inline std::vector<int> h264_nal_types(const std::vector<uint8_t>& bytes) {
  std::vector<int> types;
  for (size_t i = 0; i + 3 < bytes.size(); ++i) {
    if (bytes[i] == 0 && bytes[i + 1] == 0 && bytes[i + 2] == 1) {
      types.push_back(bytes[i + 3] & 0x1F);
      i += 2;
    }
  }
  return types;
}

// H.265 (ITU-T H.265 section 7.3.1.2): the same start codes, then a two-byte NAL header whose
// first byte holds forbidden_zero_bit (1 bit) and nal_unit_type (6 bits): 32 VPS, 33 SPS,
// 34 PPS, 16..23 IRAP pictures (19/20 IDR, 21 CRA: where a decoder can start), 0..9 others.
inline std::vector<int> h265_nal_types(const std::vector<uint8_t>& bytes) {
  std::vector<int> types;
  for (size_t i = 0; i + 4 < bytes.size(); ++i) {
    if (bytes[i] == 0 && bytes[i + 1] == 0 && bytes[i + 2] == 1) {
      types.push_back((bytes[i + 3] >> 1) & 0x3F);
      i += 2;
    }
  }
  return types;
}

inline bool contains(const std::vector<int>& types, int type) {
  for (int t : types)
    if (t == type) return true;
  return false;
}

inline double psnr(const cv::Mat& a, const cv::Mat& b) {
  const double mse = cv::norm(a, b, cv::NORM_L2SQR) / static_cast<double>(a.total() * a.channels());
  return mse == 0 ? 99.0 : 10.0 * std::log10(255.0 * 255.0 / mse);
}

}  // namespace k40t::video::testing
