// A FieldSink that ignores every field: the fuzz targets want the decoders to run, not output.
#pragma once

#include <string>

#include "k40t_driver/protocol/field_visit.h"

namespace k40t::fuzz {

class NullSink : public protocol::FieldSink {
 public:
  void integer(const char*, int64_t) override {}
  void unsigned_integer(const char*, uint64_t) override {}
  void real(const char*, double) override {}
  void boolean(const char*, bool) override {}
  void text(const char*, const std::string&) override {}
  void enumeration(const char*, int64_t, const char*) override {}
  void bytes(const char*, const uint8_t*, size_t) override {}
};

}  // namespace k40t::fuzz
