#include "k40t_driver/protocol/codec_options.h"

namespace k40t::protocol {

const char* to_string(CrcCoverage coverage) {
  switch (coverage) {
    case CrcCoverage::kHeaderExcluded:
      return "header_excluded";
    case CrcCoverage::kWholeFrame:
      return "whole_frame";
    case CrcCoverage::kAuto:
      return "auto";
  }
  return "?";
}

Result<CrcCoverage> parse_crc_coverage(const std::string& text) {
  if (text == "auto") return CrcCoverage::kAuto;
  if (text == "header_excluded") return CrcCoverage::kHeaderExcluded;
  if (text == "whole_frame") return CrcCoverage::kWholeFrame;
  return Result<CrcCoverage>::fail(
      "crc_coverage must be auto, header_excluded or whole_frame, got '" + text + "'");
}

const char* to_string(ByteOrder order) {
  return order == ByteOrder::kBig ? "big" : "little";
}

Result<ByteOrder> parse_byte_order(const std::string& text) {
  if (text == "big") return ByteOrder::kBig;
  if (text == "little") return ByteOrder::kLittle;
  return Result<ByteOrder>::fail("ack_byte_order must be big or little, got '" + text + "'");
}

Status parse_ack_byte_order(const std::string& text, CodecOptions& codec) {
  if (text == "auto") {
    codec.ack_byte_order = ByteOrder::kBig;
    codec.ack_byte_order_auto = true;
    return Status::ok();
  }
  Result<ByteOrder> order = parse_byte_order(text);
  if (!order) return Status::fail("ack_byte_order must be big, little or auto, got '" + text + "'");
  codec.ack_byte_order = *order;
  codec.ack_byte_order_auto = false;
  return Status::ok();
}

}  // namespace k40t::protocol
