#include "k40t_driver/protocol/response_code.h"

#include <cstdio>

namespace k40t::protocol {

const char* to_string(ResponseCode code) {
  switch (code) {
    case ResponseCode::kOk: return "OK, success";
    case ResponseCode::kFailure: return "failure";
    case ResponseCode::kUnknownError: return "unknown error";
    case ResponseCode::kCheckFailed: return "check failed";
    case ResponseCode::kTimeout: return "timeout";
    case ResponseCode::kMd5CheckFailed: return "MD5 check failed";
    case ResponseCode::kNoSpace: return "insufficient space";
    case ResponseCode::kLengthMismatch: return "length mismatch";
    case ResponseCode::kBusy: return "busy (repeated request)";
    case ResponseCode::kNoSuchFile: return "no such file";
    case ResponseCode::kFileMergeError: return "file merge error";
    case ResponseCode::kRecording: return "recording video";
    case ResponseCode::kCameraOpenFailed: return "camera open failed";
    case ResponseCode::kPhotoInProgress: return "taking photo";
    case ResponseCode::kNoSdCard: return "no SD card";
    case ResponseCode::kAckUnreadable: return "ACK too short to carry a response code (driver)";
  }
  return nullptr;
}

std::string response_text(uint16_t code) {
  if (const char* text = to_string(static_cast<ResponseCode>(code))) return text;
  char buffer[48];
  std::snprintf(buffer, sizeof(buffer), "unknown response code 0x%04X", code);
  return buffer;
}

}  // namespace k40t::protocol
