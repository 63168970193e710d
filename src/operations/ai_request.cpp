#include "k40t_driver/operations/ai_request.h"

#include <algorithm>
#include <string>

namespace k40t::operations {

namespace p = protocol;

Result<p::AiRecognitionRequest> ai_recognition_request(bool enable, uint8_t model,
                                                       const std::vector<uint8_t>& classes) {
  p::AiRecognitionRequest r;
  if (classes.size() > r.classes.size()) {
    return Status::fail("field 'classes' must hold at most 10 class ids, got " +
                        std::to_string(classes.size()));
  }
  r.recognition = enable ? p::FeatureSwitch::kOn : p::FeatureSwitch::kOff;
  r.model = model;
  if (!enable) return r;  // classes ignored: all zero
  if (classes.empty()) {
    return Status::fail(
        "field 'classes' must hold 1..10 class ids to switch recognition on, got none (the "
        "document has no code for every class, and an unused slot would read as class 0)");
  }
  std::copy(classes.begin(), classes.end(), r.classes.begin());
  std::fill(r.classes.begin() + static_cast<long>(classes.size()), r.classes.end(), classes.back());
  return r;
}

}  // namespace k40t::operations
