#include "k40t_driver/sim/request_handlers.h"

#include <algorithm>

#include "handler_support.h"
#include "k40t_driver/codec/enum_names.h"
#include "k40t_driver/protocol/messages/camera.h"

namespace k40t::sim {

namespace {

// Section 3.2.4.1 (0x000300) note: "拍照模式下不响应录像指令; 录像模式下不响应拍照指令" - in photo
// mode the pod does not answer a record request, in video mode a photo request (a precise
// re-shoot, 0x000307, is one).
bool ignored_in_capture_mode(const PodModel& pod, protocol::MessageId id) {
  const CaptureMode mode = pod.camera().settings().capture_mode;
  if (id == protocol::RecordRequest::kId) return mode == CaptureMode::kPhoto;
  const bool photo =
      id == protocol::TakePhotoRequest::kId || id == protocol::PreciseReshootRequest::kId;
  return photo && mode == CaptureMode::kVideo;
}

}  // namespace

protocol::ResponseCode outcome_code(Outcome outcome) {
  using protocol::ResponseCode;
  static constexpr EnumTo<Outcome, ResponseCode> kCodes[] = {
      {Outcome::kOk, ResponseCode::kOk},
      {Outcome::kFailure, ResponseCode::kFailure},
      {Outcome::kBusy, ResponseCode::kBusy},
      {Outcome::kNoSpace, ResponseCode::kNoSpace},
      {Outcome::kRecording, ResponseCode::kRecording},
      {Outcome::kCameraOpenFailed, ResponseCode::kCameraOpenFailed},
      {Outcome::kPhotoInProgress, ResponseCode::kPhotoInProgress},
      {Outcome::kNoSdCard, ResponseCode::kNoSdCard}};
  return lookup(kCodes, outcome, ResponseCode::kUnknownError);
}

namespace handlers {
protocol::Payload code_ack(protocol::ResponseCode code, const protocol::CodecOptions& codec) {
  protocol::PlainAck ack;
  ack.code = code;
  return *protocol::encode_payload(ack, codec);
}
}  // namespace handlers

const std::vector<HandlerEntry>& request_handlers() {
  static const std::vector<HandlerEntry> kTable = [] {
    std::vector<HandlerEntry> table;
    add_gimbal_handlers(table);
    add_thermal_handlers(table);
    add_visible_handlers(table);
    add_camera_handlers(table);
    add_laser_sbus_handlers(table);
    std::sort(table.begin(), table.end(),
              [](const HandlerEntry& a, const HandlerEntry& b) { return a.id < b.id; });
    return table;
  }();
  return kTable;
}

const HandlerEntry* find_request_handler(protocol::MessageId id) {
  const auto& table = request_handlers();
  const auto it =
      std::lower_bound(table.begin(), table.end(), id,
                       [](const HandlerEntry& e, protocol::MessageId v) { return e.id < v; });
  return it != table.end() && it->id == id ? &*it : nullptr;
}

std::optional<protocol::Payload> answer_request(PodModel& pod, const protocol::CodecOptions& codec,
                                                const protocol::FrameView& request) {
  const HandlerEntry* entry = find_request_handler(request.header.message_id);
  if (!entry) return std::nullopt;
  const bool gimbal_request = request.header.message_id <= 0x0000FF;
  if (!gimbal_request && !pod.camera_available()) return std::nullopt;  // nobody home to answer
  // The check of the mode comes after the model's: a request the mode ignores changes nothing in
  // the model (it refuses it), and a payload too short is still a length mismatch.
  const bool ignored = ignored_in_capture_mode(pod, request.header.message_id);
  RequestContext ctx{pod, codec};
  protocol::Payload ack = entry->handle(ctx, request);
  if (ignored && protocol::ack_response_code(ack.data(), ack.size, codec) !=
                     protocol::ResponseCode::kLengthMismatch)
    return std::nullopt;
  return ack;
}

}  // namespace k40t::sim
