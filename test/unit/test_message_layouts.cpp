// Messages described by a declarative layout (codec/layout.h, protocol/message_layout.h): the
// layout occupies exactly kSize bytes. encode() and decode() claim kSize bytes and then write or
// read without a check per byte, so a layout longer than kSize would overrun its claim and a
// shorter one would leave bytes unwritten.
#include <gtest/gtest.h>

#include <string>
#include <type_traits>
#include <utility>

#include "k40t_driver/codec/layout.h"
#include "k40t_driver/protocol/messages/all.h"

namespace k40t::protocol {
namespace {

template <class T, class = void>
struct HasLayout : std::false_type {};
template <class T>
struct HasLayout<T, std::void_t<decltype(T::layout(std::declval<const T&>(),
                                                   std::declval<codec::LayoutSizer>()))>>
    : std::true_type {};

TEST(MessageLayouts, EachLayoutOccupiesKSizeBytes) {
  size_t described = 0;
  for_each_message(PodMessages{}, [&](auto* type) {
    using T = std::remove_pointer_t<decltype(type)>;
    if constexpr (HasLayout<T>::value) {
      ++described;
      const T probe{};
      size_t size = 0;
      T::layout(probe, codec::LayoutSizer(size));
      EXPECT_EQ(size, T::kSize) << T::kName;
    }
  });
  // The families converted so far (laser, SBUS, thermal, the byte settings): the check is not
  // vacuous.
  EXPECT_GT(described, 0u);
}

}  // namespace
}  // namespace k40t::protocol
