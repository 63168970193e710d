#include "k40t_driver/psdk/identity.h"

#include <openssl/crypto.h>

namespace k40t::psdk {

size_t usable_random_length(const IdentityVerification& command) {
  size_t n = 0;
  while (n < command.random.size() && command.random[n] != 0) ++n;
  return n;
}

Md5Digest identity_digest(const std::string& app_key, const IdentityVerification& command) {
  return md5(reinterpret_cast<const uint8_t*>(app_key.data()), app_key.size(),
             command.random.data(), usable_random_length(command));
}

IdentityVerificationAck answer_identity_verification(const std::string& app_key,
                                                     const IdentityVerification& command) {
  IdentityVerificationAck ack;
  if (usable_random_length(command) < kMinRandomBytes) {
    ack.code = AckCode::kError;
    return ack;
  }
  ack.md5 = identity_digest(app_key, command);
  return ack;
}

bool identity_answer_matches(const std::string& app_key, const IdentityVerification& command,
                             const IdentityVerificationAck& ack) {
  if (ack.code != AckCode::kOk || usable_random_length(command) < kMinRandomBytes) return false;
  const Md5Digest expected = identity_digest(app_key, command);
  // Constant time, as any secret-derived comparison should be.
  return CRYPTO_memcmp(expected.data(), ack.md5.data(), expected.size()) == 0;
}

}  // namespace k40t::psdk
