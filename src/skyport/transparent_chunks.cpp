#include "k40t_driver/skyport/transparent_chunks.h"

#include <algorithm>

namespace k40t::driver::skyport {

std::vector<ByteSpan> transparent_chunks(size_t total, size_t limit) {
  std::vector<ByteSpan> out;
  if (limit == 0) return out;  // no piece could carry anything
  for (size_t at = 0; at < total; at += limit) out.push_back({at, std::min(limit, total - at)});
  return out;
}

}  // namespace k40t::driver::skyport
