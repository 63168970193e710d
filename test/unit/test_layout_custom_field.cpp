// wire::custom<C> (codec/wire.h): a field whose wire format a message family defines, here the
// camera's IPv4 addresses (messages/ipv4_field.h), in a message of its own so that the codec
// kind is tested apart from any one pod message: size, bytes, decoding, validation, fields().
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "k40t_driver/protocol/message_layout.h"
#include "k40t_driver/protocol/messages/ipv4_field.h"

namespace k40t::protocol {
namespace {

// A code byte, then one address; the address is optional on receive (kMinSize 1).
struct AddressProbe {
  K40T_POD_REPORT(0x7FFFFF, "address_probe", "none", 5, 1);
  uint8_t tag = 0;
  std::string address = "0.0.0.0";

  K40T_LAYOUT(s, v) {
    v("tag", s.tag, wire::u8);
    v("address", s.address, wire::custom<Ipv4Field>);
  }
};

TEST(LayoutCustomField, OccupiesTheSizeItsFormatGives) {
  const AddressProbe probe{};
  size_t size = 0;
  AddressProbe::layout(probe, codec::LayoutSizer(size));
  EXPECT_EQ(size, 1u + Ipv4Field::kSize);
}

TEST(LayoutCustomField, EncodesAndDecodesThroughItsFormat) {
  AddressProbe m;
  m.tag = 7;
  m.address = "10.0.0.1";
  const Result<Payload> p = encode_payload(m);
  ASSERT_TRUE(p) << p.error();
  // 10.0.0.1: the octets in written order.
  EXPECT_EQ(std::vector<uint8_t>(p->bytes.begin(), p->bytes.begin() + p->size),
            (std::vector<uint8_t>{7, 0x0A, 0x00, 0x00, 0x01}));
  const Result<AddressProbe> back = decode_payload<AddressProbe>(p->data(), p->size);
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back->tag, 7);
  EXPECT_EQ(back->address, "10.0.0.1");
}

TEST(LayoutCustomField, AnOptionalCustomFieldKeepsItsDefaultWhenLeftOff) {
  const uint8_t tag_only[1] = {3};
  const Result<AddressProbe> m = decode_payload<AddressProbe>(tag_only, 1);
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m->address, "0.0.0.0");
  const uint8_t cut[3] = {3, 10, 0};  // an address cut short is a short payload
  EXPECT_FALSE(decode_payload<AddressProbe>(cut, 3));
}

TEST(LayoutCustomField, ValidationIsTheFormatsCheckNamingTheField) {
  AddressProbe m;
  m.address = "10.0.0";
  EXPECT_EQ(encode_payload(m).error(),
            "address_probe: field 'address' must be an IPv4 address like 192.168.144.64, got "
            "'10.0.0'");
}

TEST(LayoutCustomField, FieldsListTheValueAsTheStructHoldsIt) {
  AddressProbe m;
  m.address = "192.168.1.9";
  std::vector<std::string> names;
  std::string address;
  AddressProbe::fields(m, [&](const char* name, auto& value) {
    names.push_back(name);
    if constexpr (std::is_same_v<std::decay_t<decltype(value)>, std::string>) address = value;
  });
  EXPECT_EQ(names, (std::vector<std::string>{"tag", "address"}));
  EXPECT_EQ(address, "192.168.1.9");
}

}  // namespace
}  // namespace k40t::protocol
