// One request/ACK session per link (NOTES A3, A5): frames requests with sequence numbers and the
// right destination, matches ACKs by id (one outstanding request per id; a second request for
// the same id waits its turn), retries on timeout, maps response codes to text, routes periodic
// reports and status frames to typed handlers, and answers requests that come from the pod
// (0x000310) through a handler. Thread-safe: requests may be issued from any thread; handlers run
// on the transport's I/O thread.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "k40t_driver/protocol/codec_options.h"
#include "k40t_driver/protocol/frame.h"
#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/parser.h"
#include "k40t_driver/transport/transport.h"

namespace k40t::session {

struct SessionOptions {
  protocol::CodecOptions codec;
  protocol::CrcCoverage crc_coverage = protocol::CrcCoverage::kAuto;
  protocol::Address own_address = protocol::kHostAddress;
  std::chrono::milliseconds ack_timeout{300};
  int retries = 2;  // extra attempts after the first
};

struct SessionStats {
  protocol::ParserStats parser;
  transport::LinkStats link;
  uint64_t requests = 0;
  uint64_t acks = 0;
  uint64_t nacks = 0;          // ACKs whose code is not OK
  uint64_t ack_timeouts = 0;   // requests that got no ACK after all retries
  uint64_t retries = 0;
  uint64_t late_acks = 0;      // ACKs with no outstanding request
  uint64_t frames_sent = 0;
};

// The outcome of one request: transport/timeout failures and NACKs are all readable.
struct AckResult {
  bool ok() const { return received && code == protocol::ResponseCode::kOk; }
  bool received = false;                      // false: timeout or send failure
  protocol::ResponseCode code = protocol::ResponseCode::kTimeout;
  std::string message;                        // response text, or why nothing came back
  std::vector<uint8_t> payload;               // the whole ACK payload (code included)
  int attempts = 0;
};

}  // namespace k40t::session
