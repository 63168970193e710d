// moved; include the new path (codec/byte_io.h, the layer below both protocols). The aliases keep
// the protocol's own names (protocol::ByteReader, ...) that its messages and older code use.
#pragma once
#include "k40t_driver/codec/byte_io.h"

namespace k40t::protocol {
using codec::ByteOrder;
using codec::ByteReader;
using codec::ByteWriter;
}  // namespace k40t::protocol
