#include "k40t_driver/sim/outcome.h"

namespace k40t::sim {

const char* to_string(Outcome outcome) {
  switch (outcome) {
    case Outcome::kOk:
      return "ok";
    case Outcome::kFailure:
      return "failure";
    case Outcome::kBusy:
      return "busy";
    case Outcome::kNoSpace:
      return "no space";
    case Outcome::kRecording:
      return "recording";
    case Outcome::kCameraOpenFailed:
      return "camera open failed";
    case Outcome::kPhotoInProgress:
      return "photo in progress";
    case Outcome::kNoSdCard:
      return "no SD card";
  }
  return "?";
}

}  // namespace k40t::sim
