// Where k40t's bytes come from when they do not come from a link: hex text (--hex, stdin) and
// binary capture files.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "k40t_driver/protocol/result.h"
#include "k40t_driver/session/dispatcher.h"

namespace k40t::tool {

// Hex digits, two per byte; whitespace and commas separate, a "0x" prefix per token is allowed
// ("FD 02 04", "FD0204", "0xFD, 0x02"). Errors name the offending character and its position.
Result<std::vector<uint8_t>> parse_hex(const std::string& text);

Result<std::vector<uint8_t>> read_binary_file(const std::string& path);
std::string read_all(std::FILE* stream);

// Feeds a capture to a dispatcher one byte at a time, so that a frame handler can tell where in
// the capture its frame started: `fed` - frame.size.
struct CaptureCursor {
  uint64_t fed = 0;
  uint64_t frame_offset(const protocol::FrameView& frame) const { return fed - frame.size; }
};
void feed_capture(session::Dispatcher& dispatcher, const std::vector<uint8_t>& bytes,
                  CaptureCursor& cursor);

// "FD 02 04 ..." (upper case, space-separated).
std::string to_hex(const uint8_t* data, size_t size);

}  // namespace k40t::tool
