// Identity verification (3.1.1, docs/psdk.md#frames). Expected digests computed with Python:
//   hashlib.md5(b"0123456789abcdef0123456789abcdef" + bytes(range(0x10, 0x20))).hexdigest()
//     == "aebecdd8e8f8de15606640180aab9cb5"
//   hashlib.md5(b"0123456789abcdef0123456789abcdef" + bytes([1,2,...,13])).hexdigest()
//     == "13926ae59dd9e2506067ffd281c847c5"
#include <gtest/gtest.h>

#include "k40t_driver/psdk/identity.h"

namespace k40t::psdk {
namespace {

const std::string kAppKey = "0123456789abcdef0123456789abcdef";

IdentityVerification with_random(std::array<uint8_t, 16> random) {
  IdentityVerification c;
  c.random = random;
  return c;
}

TEST(PsdkIdentity, DigestOfKeyAndAllSixteenBytes) {
  const auto command = with_random({0x10, 0x11, 0x12, 0x13, 0x14, 0x15, 0x16, 0x17, 0x18, 0x19,
                                    0x1a, 0x1b, 0x1c, 0x1d, 0x1e, 0x1f});
  const IdentityVerificationAck ack = answer_identity_verification(kAppKey, command);
  EXPECT_EQ(ack.code, AckCode::kOk);
  const std::array<uint8_t, 16> expected = {0xae, 0xbe, 0xcd, 0xd8, 0xe8, 0xf8, 0xde, 0x15,
                                            0x60, 0x66, 0x40, 0x18, 0x0a, 0xab, 0x9c, 0xb5};
  EXPECT_EQ(ack.md5, expected);
  // On the wire: 17 bytes, code first.
  const Result<Data> data = encode_data(ack);
  ASSERT_TRUE(data);
  EXPECT_EQ(data->size, 17u);
  EXPECT_EQ(data->bytes[0], 0x00);
  EXPECT_EQ(data->bytes[1], 0xae);
}

TEST(PsdkIdentity, RandomBytesStopAtTheFirstZero) {
  const auto command = with_random({1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 0, 15, 16});
  EXPECT_EQ(usable_random_length(command), 13u);
  const IdentityVerificationAck ack = answer_identity_verification(kAppKey, command);
  EXPECT_EQ(ack.code, AckCode::kOk);
  const std::array<uint8_t, 16> expected = {0x13, 0x92, 0x6a, 0xe5, 0x9d, 0xd9, 0xe2, 0x50,
                                            0x60, 0x67, 0xff, 0xd2, 0x81, 0xc8, 0x47, 0xc5};
  EXPECT_EQ(ack.md5, expected);
}

TEST(PsdkIdentity, TwelveOrFewerRandomBytesAreRefused) {
  const auto command = with_random({1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 0, 14, 15, 16});
  const IdentityVerificationAck ack = answer_identity_verification(kAppKey, command);
  EXPECT_EQ(ack.code, AckCode::kError);
  EXPECT_EQ(ack.md5, (std::array<uint8_t, 16>{}));
  EXPECT_FALSE(identity_answer_matches(kAppKey, command, ack));
}

TEST(PsdkIdentity, AdapterSideAcceptsTheRightKeyOnly) {
  const auto command = with_random({0xde, 0xad, 0xbe, 0xef, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12});
  const IdentityVerificationAck good = answer_identity_verification(kAppKey, command);
  EXPECT_TRUE(identity_answer_matches(kAppKey, command, good));
  const IdentityVerificationAck wrong = answer_identity_verification("not the key", command);
  EXPECT_FALSE(identity_answer_matches(kAppKey, command, wrong));
  IdentityVerificationAck flipped = good;
  flipped.md5[15] ^= 1;
  EXPECT_FALSE(identity_answer_matches(kAppKey, command, flipped));
}

}  // namespace
}  // namespace k40t::psdk
