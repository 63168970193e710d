// AES-128-ECB for encrypted PSDK frames (ENC = 1; protocol document section 2.3,
// docs/psdk.md#frames), through OpenSSL's EVP interface: every 16-byte block is encrypted on its
// own with one key, no IV, no cipher-level padding (the frame's own zero padding makes DATA whole
// blocks).
//
// Key material is wiped when the object dies and is never printed by anything in psdk/.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "k40t_driver/codec/result.h"
#include "k40t_driver/psdk/frame.h"

namespace k40t::psdk {

constexpr size_t kAesKeySize = 16;
using AesKey = std::array<uint8_t, kAesKeySize>;

class Aes128Ecb {
 public:
  explicit Aes128Ecb(const AesKey& key) : key_(key) {}
  Aes128Ecb(const Aes128Ecb&) = default;
  Aes128Ecb& operator=(const Aes128Ecb&) = default;
  ~Aes128Ecb();

  // `size` must be a multiple of 16; `out` may be `in` (in-place). Fails with OpenSSL's reason.
  Status encrypt(const uint8_t* in, size_t size, uint8_t* out) const;
  Status decrypt(const uint8_t* in, size_t size, uint8_t* out) const;

 private:
  Status run(bool encrypt, const uint8_t* in, size_t size, uint8_t* out) const;
  AesKey key_;
};

// The strings a payload is registered with on DJI's developer site. Secret: never log them.
struct Credentials {
  std::string app_name;
  std::string app_id;
  std::string app_key;
  std::string developer_account;
};

// docs/psdk.md#frames: the AES key is MD5(app name + app id + app key + developer account), the
// strings concatenated without separators.
AesKey derive_aes_key(const Credentials& credentials);

using Md5Digest = std::array<uint8_t, 16>;
// MD5 through OpenSSL's EVP digest interface; `first` then `second`, as one message.
Md5Digest md5(const uint8_t* first, size_t first_size, const uint8_t* second = nullptr,
              size_t second_size = 0);

}  // namespace k40t::psdk
