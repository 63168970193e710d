// The DATA of one PSDK command as bytes, and back: the two helpers of the hand-written golden tests
// (test_psdk_command_golden.cpp, test_psdk_bridge_golden.cpp). A codec failure is a test failure
// that names the codec's message.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "k40t_driver/psdk/commands/all.h"

namespace k40t::psdk::test {

using Bytes = std::vector<uint8_t>;

template <class T>
Bytes encoded(const T& m) {
  const Result<Data> d = encode_data(m);
  EXPECT_TRUE(d) << d.error();
  return d ? Bytes(d->data(), d->data() + d->size) : Bytes{};
}

template <class T>
T decoded(const Bytes& b) {
  const Result<T> m = decode_data<T>(b.data(), b.size());
  EXPECT_TRUE(m) << m.error();
  return m ? m.value() : T{};
}

}  // namespace k40t::psdk::test
