#include "k40t_driver/sim/sd_card.h"

#include <algorithm>
#include <utility>
#include <vector>

#include "k40t_driver/codec/enum_names.h"

namespace k40t::sim {

const char* to_string(SdState state) {
  static constexpr EnumName<SdState> kNames[] = {
      {SdState::kNormal, "normal"}, {SdState::kAbnormal, "abnormal"},
      {SdState::kSlow, "slow"},     {SdState::kAbsent, "absent"},
      {SdState::kFull, "full"},     {SdState::kFormatError, "format error"}};
  return name_in(kNames, state);
}

SdState SdCard::state() const {
  if (!present_) return SdState::kAbsent;
  // The document has no "formatting" state: the card is unusable meanwhile, so it reads abnormal.
  if (formatting()) return SdState::kAbnormal;
  if (fault_ != SdState::kNormal) return fault_;
  if (free_mb() < config_.full_reserve_mb) return SdState::kFull;
  return SdState::kNormal;
}

Outcome SdCard::can_write(double mb) const {
  if (!present_) return Outcome::kNoSdCard;
  if (formatting()) return Outcome::kBusy;
  if (fault_ == SdState::kAbnormal || fault_ == SdState::kFormatError) return Outcome::kFailure;
  if (mb > free_mb() || state() == SdState::kFull) return Outcome::kNoSpace;
  return Outcome::kOk;
}

double SdCard::write(double mb) {
  if (!present_ || formatting()) return 0;
  const double fitted = std::clamp(mb, 0.0, free_mb());
  used_mb_ += fitted;
  return fitted;
}

Outcome SdCard::start_format() {
  if (!present_) return Outcome::kNoSdCard;
  if (formatting()) return Outcome::kBusy;
  format_left_s_ = config_.format_s;
  since_status_s_ = 0;
  announce_ = true;
  return Outcome::kOk;
}

bool SdCard::step(double dt_s, EventQueue& events) {
  if (!formatting()) return false;
  if (!present_) {  // pulled out while formatting
    format_left_s_ = 0;
    events.push_back(FormatStatusEvent{FormatState::kFailed});
    return false;
  }
  format_left_s_ -= dt_s;
  if (format_left_s_ <= 0) {
    format_left_s_ = 0;
    used_mb_ = 0;
    fault_ = SdState::kNormal;
    events.push_back(FormatStatusEvent{FormatState::kDone});
    return true;
  }
  since_status_s_ += dt_s;
  if (announce_ || since_status_s_ >= config_.format_status_period_s) {
    events.push_back(FormatStatusEvent{FormatState::kInProgress});
    since_status_s_ = announce_ ? 0 : since_status_s_ - config_.format_status_period_s;
    announce_ = false;
  }
  return false;
}

void SdCard::insert() {
  if (present_) return;
  present_ = true;
  used_mb_ = 0;  // a fresh card
  fault_ = SdState::kNormal;
}

void SdCard::remove() {
  present_ = false;
}

void SdCard::fill() {
  if (present_) used_mb_ = std::max(used_mb_, config_.capacity_mb - config_.full_reserve_mb / 2);
}

void SdCard::set_fault(SdState fault) {
  fault_ =
      (fault == SdState::kAbnormal || fault == SdState::kSlow || fault == SdState::kFormatError)
          ? fault
          : SdState::kNormal;
}

namespace {
using SdChange = void (*)(SdCard&);
const std::vector<std::pair<std::string, SdChange>>& sd_conditions() {
  static const std::vector<std::pair<std::string, SdChange>> kConditions = {
      {"absent", [](SdCard& sd) { sd.remove(); }},
      {"insert", [](SdCard& sd) { sd.insert(); }},
      {"fill", [](SdCard& sd) { sd.fill(); }},
      {"normal", [](SdCard& sd) { sd.set_fault(SdState::kNormal); }},
      {"abnormal", [](SdCard& sd) { sd.set_fault(SdState::kAbnormal); }},
      {"slow", [](SdCard& sd) { sd.set_fault(SdState::kSlow); }},
      {"format-error", [](SdCard& sd) { sd.set_fault(SdState::kFormatError); }},
  };
  return kConditions;
}
}  // namespace

bool set_sd_condition(SdCard& sd, const std::string& condition) {
  for (const auto& [name, change] : sd_conditions()) {
    if (name != condition) continue;
    change(sd);
    return true;
  }
  return false;
}

const std::string& sd_condition_names() {
  static const std::string kNames = [] {
    std::string names;
    for (const auto& entry : sd_conditions()) names += (names.empty() ? "" : "|") + entry.first;
    return names;
  }();
  return kNames;
}

}  // namespace k40t::sim
