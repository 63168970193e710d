// moved; include the new path (codec/field_visit.h, the layer below both protocols). The aliases
// keep the protocol's own names (protocol::FieldSink, ...) that older code uses.
#pragma once
#include "k40t_driver/codec/field_visit.h"

namespace k40t::protocol {
using codec::FieldSink;
using codec::visit_fields;
namespace detail {
using codec::detail::IsByteArray;
using codec::detail::SinkAdapter;
}  // namespace detail
}  // namespace k40t::protocol
