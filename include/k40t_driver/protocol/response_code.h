// ACK response codes (document section 3.3).
#pragma once

#include <cstdint>
#include <string>

namespace k40t::protocol {

enum class ResponseCode : uint16_t {
  kOk = 0x0000,
  kFailure = 0x0001,
  kUnknownError = 0x0002,
  kCheckFailed = 0x0003,
  kTimeout = 0x0004,
  kMd5CheckFailed = 0x0005,
  kNoSpace = 0x0006,
  kLengthMismatch = 0x0007,
  kBusy = 0x0008,  // repeated request
  kNoSuchFile = 0x0009,
  kFileMergeError = 0x000A,
  kRecording = 0x0201,
  kCameraOpenFailed = 0x0202,
  kPhotoInProgress = 0x0203,
  kNoSdCard = 0x0204,
  // Not the pod's: the driver could not read a response code (an ACK payload under 2 bytes).
  // Outside the document's list so that a local decode error never reads as the pod's 0x0007.
  kAckUnreadable = 0xFFFF,
};

// The document's text for the code; codes it does not list get "unknown response code 0xNNNN".
std::string response_text(uint16_t code);
inline std::string response_text(ResponseCode code) {
  return response_text(static_cast<uint16_t>(code));
}
// For the field visitor: a name for every listed code, nullptr for others.
const char* to_string(ResponseCode code);

}  // namespace k40t::protocol
