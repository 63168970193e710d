// A compile-time list of message structs. Each message family header ends with the list of its
// message types (e.g. `using ThermalMessages = MessageList<ThermalStatus, ...>`); the catalogue
// entries, the catalogue tests' round trips and the fuzz entries are derived from those lists, so
// a new message struct is registered by adding it to its family's list and nowhere else.
#pragma once

#include <cstddef>

namespace k40t::protocol {

template <class... T>
struct MessageList {
  static constexpr size_t kSize = sizeof...(T);
};

// Calls `f.template operator()<T>()`-style visitors without naming the types: f(T*) with a null
// pointer of each type, in list order.
template <class... T, class F>
void for_each_message(MessageList<T...>, F&& f) {
  (f(static_cast<T*>(nullptr)), ...);
}

// The lists of several families as one.
template <class... Lists>
struct JoinMessageLists;
template <>
struct JoinMessageLists<> {
  using type = MessageList<>;
};
template <class... T>
struct JoinMessageLists<MessageList<T...>> {
  using type = MessageList<T...>;
};
template <class... A, class... B, class... Rest>
struct JoinMessageLists<MessageList<A...>, MessageList<B...>, Rest...> {
  using type = typename JoinMessageLists<MessageList<A..., B...>, Rest...>::type;
};
template <class... Lists>
using JoinedMessages = typename JoinMessageLists<Lists...>::type;

}  // namespace k40t::protocol
