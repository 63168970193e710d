// The 0x000319 request of the ai/recognition service (section 3.2.4.23: "同时识别的目标类别。同时
// 最多识别10个类别" - the target classes to recognise, at most 10). The document does not say how
// unused slots are marked, and 0 is a real class in most label files (COCO's "person"): sending
// [2] as [2, 0, ..., 0] would box people too. So the unused slots repeat the last class given
// ([2] -> ten 2s), which names the same set under any reading, and switching recognition on with
// no class at all is refused (there is no "every class" code). Switched off, the classes do not
// matter and are sent as zeros.
#pragma once

#include <cstdint>
#include <vector>

#include "k40t_driver/protocol/messages/camera_imaging.h"
#include "k40t_driver/protocol/result.h"

namespace k40t::operations {

Result<protocol::AiRecognitionRequest> ai_recognition_request(bool enable, uint8_t model,
                                                              const std::vector<uint8_t>& classes);

}  // namespace k40t::operations
