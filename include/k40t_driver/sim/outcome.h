// What the simulated pod does with a command, in the model's own words. The protocol front-end
// maps each to its response code (document section 3.3); the model itself knows no wire codes.
#pragma once

namespace k40t::sim {

enum class Outcome {
  kOk,
  kFailure,           // not allowed in this state, or outside what the pod can do
  kBusy,              // the same operation is already under way (repeated request)
  kNoSpace,           // the SD card has no room for it
  kRecording,         // refused because a recording is running
  kCameraOpenFailed,  // the camera is not available
  kPhotoInProgress,   // refused because a photo (burst, time-lapse) is being taken
  kNoSdCard,          // needs an SD card and there is none
};

const char* to_string(Outcome outcome);

}  // namespace k40t::sim
