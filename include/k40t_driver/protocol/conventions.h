// The readings of the protocol document that it leaves open ("conventions"), one parameter each:
// docs/protocol/decisions.md#conventions lists them with their section, values, default and why.
//
// One NAME per reading is the ROS parameter (in the driver's private namespace, also loaded from a
// YAML file with `conventions:=FILE.yaml`), the simulator's `--convention NAME=VALUE` and the key
// `k40t probe` writes. Values are short snake_case words; `auto` (where listed) means "the default
// until the pod's frames show which one, then that" (see driver/convention_tracker.h).
//
// The readings that existed before this list stay where they were (crc_coverage in
// session::SessionOptions, the others in CodecOptions); the new ones are CodecOptions::conventions
// (convention_values.h). The table reaches them all through ConventionRefs so that one loop can
// parse, print or write every reading.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "k40t_driver/protocol/codec_options.h"
#include "k40t_driver/protocol/result.h"

namespace k40t::protocol {

// Every reading, wherever it lives: what the table reads and writes.
struct ConventionRefs {
  CrcCoverage& crc_coverage;
  CodecOptions& codec;  // codec.conventions: the readings of convention_values.h
};

// The same, read-only.
struct ConstConventionRefs {
  const CrcCoverage& crc_coverage;
  const CodecOptions& codec;
};

struct ConventionInfo {
  const char* name;     // ROS parameter = --convention NAME = YAML key
  const char* section;  // of the document, e.g. "3.1.1.2 (0x000002)"
  // The allowed values; empty for a number, whose range `number_range` says.
  std::vector<const char*> values;
  const char* number_range;  // "1..1000" or nullptr
  const char* default_value;
  const char* meaning;  // one line
  // Sets the reading from text; a clear error (naming the reading and its values) otherwise.
  Status (*set)(const ConventionInfo& info, ConventionRefs refs, const std::string& text);
  std::string (*get)(const ConventionInfo& info, ConstConventionRefs refs);
  // true where traffic can tell (the value list has "auto", or the reading is checked against
  // frames and a contradiction shows in the `conventions` diagnostic).
  bool detectable;
};

// Every reading, the ones that existed before this list first.
const std::vector<ConventionInfo>& convention_table();
// nullptr if no reading has that name.
const ConventionInfo* find_convention(const std::string& name);
// "NAME=VALUE" (the simulator's and the tools' option); errors name the reading and its values.
Status set_convention(ConventionRefs refs, const std::string& name, const std::string& value);
Status set_convention_assignment(ConventionRefs refs, const std::string& name_equals_value);
// "a, b or c" for messages and docs.
std::string convention_values_text(const ConventionInfo& info);

}  // namespace k40t::protocol
