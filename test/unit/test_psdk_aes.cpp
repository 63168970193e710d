// AES-128-ECB through OpenSSL (docs/psdk.md#frames): the FIPS-197 appendix C.1 known answer, round
// trips, the key derivation and MD5 (RFC 1321 test suite).
#include <gtest/gtest.h>

#include <vector>

#include "k40t_driver/psdk/aes.h"

namespace k40t::psdk {
namespace {

TEST(PsdkAes, Fips197KnownAnswer) {
  AesKey key;
  for (size_t i = 0; i < key.size(); ++i) key[i] = static_cast<uint8_t>(i);
  const Aes128Ecb cipher(key);
  const uint8_t plain[16] = {0x00, 0x11, 0x22, 0x33, 0x44, 0x55, 0x66, 0x77,
                             0x88, 0x99, 0xaa, 0xbb, 0xcc, 0xdd, 0xee, 0xff};
  const uint8_t expected[16] = {0x69, 0xc4, 0xe0, 0xd8, 0x6a, 0x7b, 0x04, 0x30,
                                0xd8, 0xcd, 0xb7, 0x80, 0x70, 0xb4, 0xc5, 0x5a};
  uint8_t out[16];
  ASSERT_TRUE(cipher.encrypt(plain, 16, out));
  EXPECT_EQ(std::vector<uint8_t>(out, out + 16), std::vector<uint8_t>(expected, expected + 16));
  ASSERT_TRUE(cipher.decrypt(out, 16, out));
  EXPECT_EQ(std::vector<uint8_t>(out, out + 16), std::vector<uint8_t>(plain, plain + 16));
}

TEST(PsdkAes, EcbEncryptsEqualBlocksEqually) {
  const Aes128Ecb cipher(AesKey{1, 2, 3});
  std::vector<uint8_t> data(32, 0x42);
  std::vector<uint8_t> out(32);
  ASSERT_TRUE(cipher.encrypt(data.data(), data.size(), out.data()));
  EXPECT_TRUE(std::equal(out.begin(), out.begin() + 16, out.begin() + 16));  // no chaining, no IV
  EXPECT_NE(out, data);
}

TEST(PsdkAes, RoundTripInPlaceForEveryBlockCount) {
  const Aes128Ecb cipher(AesKey{9, 8, 7, 6, 5, 4, 3, 2, 1});
  for (size_t blocks = 0; blocks <= 16; ++blocks) {
    std::vector<uint8_t> data(blocks * 16);
    for (size_t i = 0; i < data.size(); ++i) data[i] = static_cast<uint8_t>(i * 7 + blocks);
    std::vector<uint8_t> work = data;
    ASSERT_TRUE(cipher.encrypt(work.data(), work.size(), work.data()));
    if (blocks > 0) {
      EXPECT_NE(work, data);
    }
    ASSERT_TRUE(cipher.decrypt(work.data(), work.size(), work.data()));
    EXPECT_EQ(work, data) << blocks << " blocks";
  }
}

TEST(PsdkAes, RejectsPartialBlocks) {
  const Aes128Ecb cipher(AesKey{});
  uint8_t data[17] = {};
  const Status s = cipher.encrypt(data, 17, data);
  ASSERT_FALSE(s);
  EXPECT_NE(s.message().find("16-byte blocks"), std::string::npos) << s.message();
}

TEST(PsdkMd5, Rfc1321Vectors) {
  const Md5Digest empty = md5(nullptr, 0);
  EXPECT_EQ(empty[0], 0xd4);
  EXPECT_EQ(empty[15], 0x7e);
  const uint8_t abc[] = {'a', 'b', 'c'};
  const Md5Digest d = md5(abc, 3);
  const Md5Digest expected = {0x90, 0x01, 0x50, 0x98, 0x3c, 0xd2, 0x4f, 0xb0,
                              0xd6, 0x96, 0x3f, 0x7d, 0x28, 0xe1, 0x7f, 0x72};
  EXPECT_EQ(d, expected);
  // Two parts hash like their concatenation.
  EXPECT_EQ(md5(abc, 1, abc + 1, 2), expected);
}

TEST(PsdkAes, KeyIsMd5OfTheFourStringsConcatenated) {
  // Python: hashlib.md5(b"K40T bridge" b"123456" b"0123456789abcdef0123456789abcdef"
  //                     b"dev@example.com").hexdigest() == "71c682c7e3732053f005c0dd78d01e5e"
  const AesKey key = derive_aes_key(
      {"K40T bridge", "123456", "0123456789abcdef0123456789abcdef", "dev@example.com"});
  const AesKey expected = {0x71, 0xc6, 0x82, 0xc7, 0xe3, 0x73, 0x20, 0x53,
                           0xf0, 0x05, 0xc0, 0xdd, 0x78, 0xd0, 0x1e, 0x5e};
  EXPECT_EQ(key, expected);
}

}  // namespace
}  // namespace k40t::psdk
