#include "frame_sender.h"

#include <string>

namespace k40t::session {

FrameSender::FrameSender(transport::Transport* transport, protocol::CrcCoverage coverage,
                         const Dispatcher& dispatcher)
    : transport_(transport), coverage_(coverage), dispatcher_(dispatcher) {
  sequences_.reserve(4);
}

FrameSender::SenderSequence& FrameSender::sequence_of(protocol::Address source) {
  for (SenderSequence& s : sequences_) {
    if (s.source == source) return s;
  }
  sequences_.push_back({source, 0});
  return sequences_.back();
}

Status FrameSender::send(protocol::MessageId id, const uint8_t* payload, size_t size,
                         protocol::Address source, protocol::Address destination) {
  if (transport_ == nullptr) return Status::fail("no transport: the session was given none");
  // Send what the pod uses once the parser has locked; kAuto encodes as header_excluded (A1).
  const protocol::CrcCoverage coverage =
      coverage_ == protocol::CrcCoverage::kAuto ? dispatcher_.locked_coverage() : coverage_;

  std::lock_guard<std::mutex> lock(mutex_);
  protocol::FrameHeader header;
  header.destination = destination;
  header.source = source;
  header.message_id = id;
  SenderSequence& sequence = sequence_of(source);
  header.sequence = sequence.next;
  Result<protocol::EncodedFrame> frame = protocol::encode_frame(header, payload, size, coverage);
  if (!frame) return frame.status();  // nothing written: the number stays unused
  // From here the number is spent even if the write fails: part of the frame may be on the wire
  // already, and a gap is what the receiver should see then. uint8_t wraps 255 -> 0.
  ++sequence.next;
  const Status written = transport_->send(frame->data(), frame->size());
  if (!written) {
    send_errors_.fetch_add(1, std::memory_order_relaxed);
    return written;
  }
  frames_sent_.fetch_add(1, std::memory_order_relaxed);
  if (!sent_handlers_.empty()) {
    protocol::FrameView view;
    view.header = header;
    view.payload = frame->data() + protocol::kHeaderSize;
    view.payload_size = size;
    view.bytes = frame->data();
    view.size = frame->size();
    view.coverage = coverage == protocol::CrcCoverage::kAuto
                        ? protocol::CrcCoverage::kHeaderExcluded
                        : coverage;
    for (const FrameHandler& handler : sent_handlers_) handler(view);
  }
  return Status::ok();
}

}  // namespace k40t::session
