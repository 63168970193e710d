// Transparent data from ROS (skyport/transparent/to_mobile, to_onboard) to the adapter, ROS-free:
// a message longer than the command's DATA limit (3.2.2: 128 bytes to the mobile app; 3.6.2: 255
// to the onboard computer) goes out as consecutive commands of at most the limit each, in order.
#pragma once

#include <cstddef>
#include <vector>

namespace k40t::driver::skyport {

struct ByteSpan {
  size_t offset = 0;
  size_t size = 0;
  bool operator==(const ByteSpan& other) const {
    return offset == other.offset && size == other.size;
  }
};

// The pieces of `total` bytes, each at most `limit` (> 0) long, all full but the last; none for 0
// bytes (an empty message sends nothing: the commands need at least one byte).
std::vector<ByteSpan> transparent_chunks(size_t total, size_t limit);

}  // namespace k40t::driver::skyport
