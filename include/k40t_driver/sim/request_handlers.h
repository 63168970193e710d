// The pod's answers to the host's requests: each request id of the document has a handler that
// decodes the payload (decode_payload + validate()), lets the model act, and returns the ACK
// payload with the right response code (section 3.3):
//   payload shorter than the message's minimum          -> 0x0007 length mismatch
//   undefined code or value out of the document's range -> 0x0001 failure
//   refused by the model                                -> its Outcome's code (outcome_code())
// Data ACKs (versions, IP, read-all, laser distance, target position, SBUS) carry their data
// after the code. Protocol in, model calls out: no I/O here, so it is tested without a link.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "k40t_driver/protocol/codec_options.h"
#include "k40t_driver/protocol/frame.h"
#include "k40t_driver/protocol/message.h"
#include "k40t_driver/sim/outcome.h"
#include "k40t_driver/sim/pod_model.h"

namespace k40t::sim {

protocol::ResponseCode outcome_code(Outcome outcome);

struct RequestContext {
  PodModel& pod;
  const protocol::CodecOptions& codec;
};

using RequestHandler =
    std::function<protocol::Payload(RequestContext&, const protocol::FrameView&)>;

struct HandlerEntry {
  protocol::MessageId id = 0;
  RequestHandler handle;
};

// Every request the simulated pod answers, sorted by id.
const std::vector<HandlerEntry>& request_handlers();
const HandlerEntry* find_request_handler(protocol::MessageId id);

// The ACK payload for `request`; nullopt when the pod stays silent: an id it does not know
// (section 2.1: "any system that does not recognise ... will skip the packet"), a camera
// request while the camera is shut down or rebooting, or a photo request (0x000302, 0x000307) in
// video mode and a record request (0x000303) in photo mode (section 3.2.4.1 note).
std::optional<protocol::Payload> answer_request(PodModel& pod, const protocol::CodecOptions& codec,
                                                const protocol::FrameView& request);

// Families register their handlers (src/sim/handlers_<family>.cpp).
void add_camera_handlers(std::vector<HandlerEntry>& out);
void add_gimbal_handlers(std::vector<HandlerEntry>& out);
void add_thermal_handlers(std::vector<HandlerEntry>& out);
void add_visible_handlers(std::vector<HandlerEntry>& out);
void add_laser_sbus_handlers(std::vector<HandlerEntry>& out);

}  // namespace k40t::sim
