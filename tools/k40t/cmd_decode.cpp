// k40t decode: frames from hex text or a binary capture, one JSON object per frame on stdout,
// counters on stderr.
#include <cstdio>

#include "command.h"
#include "frame_text.h"
#include "input.h"
#include "k40t_driver/protocol/catalogue.h"

namespace k40t::tool {

namespace {

int run_decode(const Command& self, const ParsedArgs& args) {
  Result<WireOptions> wire = wire_options(args);
  if (!wire) return usage_error(self, wire.error());
  if (args.positional.size() > 1)
    return usage_error(self, "give one input, got " + std::to_string(args.positional.size()));
  const bool from_hex_option = args.has("--hex");
  if (from_hex_option && !args.positional.empty()) {
    return usage_error(self, "give --hex or an input file, not both");
  }

  std::vector<uint8_t> bytes;
  if (from_hex_option) {
    Result<std::vector<uint8_t>> parsed = parse_hex(args.options.at("--hex"));
    if (!parsed) return usage_error(self, "--hex: " + parsed.error());
    bytes = std::move(parsed.value());
  } else if (args.positional.empty() || args.positional[0] == "-") {
    Result<std::vector<uint8_t>> parsed = parse_hex(read_all(stdin));
    if (!parsed) {
      std::fprintf(stderr, "k40t decode: stdin: %s\n", parsed.error().c_str());
      return kExitFailed;
    }
    bytes = std::move(parsed.value());
  } else {
    Result<std::vector<uint8_t>> read = read_binary_file(args.positional[0]);
    if (!read) {
      std::fprintf(stderr, "k40t decode: %s\n", read.error().c_str());
      return kExitFailed;
    }
    bytes = std::move(read.value());
  }

  session::Dispatcher dispatcher(wire->crc_coverage, wire->codec);
  CaptureCursor cursor;
  uint64_t undecodable = 0;
  dispatcher.on_frame([&](const protocol::FrameView& frame) {
    bool decoded = false;
    const std::string json =
        frame_json(frame, cursor.frame_offset(frame), dispatcher.codec(), &decoded);
    if (!decoded && protocol::is_known_id(frame.header.message_id)) ++undecodable;
    std::puts(json.c_str());
  });
  feed_capture(dispatcher, bytes, cursor);
  std::fflush(stdout);
  std::fprintf(stderr, "k40t decode: %s\n", counters_text(dispatcher.stats(), undecodable).c_str());
  // A frame that began but never ended is no frame; said, not silently dropped.
  if (const size_t cut = dispatcher.buffered_bytes(); cut > 0) {
    std::fprintf(stderr,
                 "k40t decode: the input ends inside a frame: its last %zu bytes (from offset "
                 "%zu) start a frame that is cut short\n",
                 cut, bytes.size() - cut);
  }
  return kExitOk;
}

}  // namespace

const Command& decode_command() {
  static const Command command{
      "decode",
      "decode [--hex HEX | FILE | -] [options]",
      "frames from hex text or a binary capture -> one JSON object per frame",
      "Reads frames from --hex, from hex text on stdin (no argument, or '-'), or from a binary\n"
      "capture FILE, and prints one JSON object per good frame on stdout: offset in the input,\n"
      "id, name, section, kind, direction, src/dst addresses, seq, crc coverage, payload hex and\n"
      "the decoded fields (units are in the field names), or an \"error\" member when the\n"
      "payload does not decode. Hex text may contain whitespace, commas and 0x prefixes.\n"
      "At the end, the counters (good frames, checksum errors, discarded bytes, unknown ids,\n"
      "sequence gaps, decode errors) go to stderr, and a frame cut short by the end of the\n"
      "input is named there.",
      {{"--hex", "HEX", "decode these bytes, e.g. \"FD 02 04 01 00 01 01 00 04 00 01 00 A2 56\""},
       kCrcCoverageOption,
       kAckByteOrderOption},
      &run_decode};
  return command;
}

}  // namespace k40t::tool
