#include "k40t_driver/sim/outcome.h"

#include "k40t_driver/codec/enum_names.h"

namespace k40t::sim {

const char* to_string(Outcome outcome) {
  static constexpr EnumName<Outcome> kNames[] = {{Outcome::kOk, "ok"},
                                                 {Outcome::kFailure, "failure"},
                                                 {Outcome::kBusy, "busy"},
                                                 {Outcome::kNoSpace, "no space"},
                                                 {Outcome::kRecording, "recording"},
                                                 {Outcome::kCameraOpenFailed, "camera open failed"},
                                                 {Outcome::kPhotoInProgress, "photo in progress"},
                                                 {Outcome::kNoSdCard, "no SD card"}};
  return name_in(kNames, outcome);
}

}  // namespace k40t::sim
