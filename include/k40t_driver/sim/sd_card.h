// The pod's SD card: capacity, what is used, and the conditions 0x000003 reports (byte 9) and the
// photo/record/format commands refuse on. It fills as photos and video are written, can be taken
// out (absent), filled up, put into a fault state, and formatted (which takes time and reports
// 0x02030D at 5 Hz).
#pragma once

#include <cstdint>
#include <string>

#include "k40t_driver/sim/events.h"
#include "k40t_driver/sim/outcome.h"

namespace k40t::sim {

// Byte 9 of 0x000003 (section 3.2.1.1).
enum class SdState : uint8_t {
  kNormal = 0,
  kAbnormal = 1,
  kSlow = 2,
  kAbsent = 3,
  kFull = 4,
  kFormatError = 5,
};
const char* to_string(SdState state);

struct SdConfig {
  double capacity_mb = 65536;   // 64 GB
  double full_reserve_mb = 30;  // "full" below this: not room for one more full-size photo
  double format_s = 2;
  double format_status_period_s = 0.2;
};

class SdCard {
 public:
  explicit SdCard(const SdConfig& config = {}) : config_(config) {}

  SdState state() const;
  bool present() const { return present_; }
  bool formatting() const { return format_left_s_ > 0; }
  double capacity_mb() const { return present_ ? config_.capacity_mb : 0; }
  double used_mb() const { return present_ ? used_mb_ : 0; }
  double free_mb() const { return capacity_mb() - used_mb(); }

  // Whether `mb` more can be written now: kOk, kNoSdCard, kBusy (formatting), kFailure (a fault
  // state), kNoSpace.
  Outcome can_write(double mb) const;
  // Writes up to `mb`; returns what fitted.
  double write(double mb);

  Outcome start_format();
  // Advances a format under way; returns true in the step it completes (the card is empty).
  bool step(double dt_s, EventQueue& events);

  // Conditions set from outside (command line, control socket).
  void insert();
  void remove();
  void fill();                    // leaves less than the full reserve
  void set_fault(SdState fault);  // kAbnormal, kSlow, kFormatError; kNormal clears
  void set_capacity(double mb) { config_.capacity_mb = mb; }

 private:
  SdConfig config_;
  bool present_ = true;
  double used_mb_ = 0;
  SdState fault_ = SdState::kNormal;
  double format_left_s_ = 0;
  double since_status_s_ = 0;
  bool announce_ = false;  // "in progress" goes out at the first step of a format
};

// Conditions set by name from outside (command line --sd, control socket "sd"): absent, insert,
// fill, normal, abnormal, slow, format-error. Returns false for an unknown name.
bool set_sd_condition(SdCard& sd, const std::string& condition);
// "absent|insert|fill|normal|abnormal|slow|format-error", for help texts and errors.
const std::string& sd_condition_names();

}  // namespace k40t::sim
