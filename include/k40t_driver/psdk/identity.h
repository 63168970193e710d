// Identity verification (0x01/0x01; protocol document 3.1.1, docs/psdk.md#frames): the adapter
// sends 16 random bytes, the payload answers with the raw MD5 of its app key (ASCII) followed by
// the random bytes up to the first 0x00. If 12 or fewer random bytes remain, the payload refuses
// (0x01). Both roles are here: the payload answers, the adapter (simulator) checks. Keys are never
// logged.
#pragma once

#include <string>

#include "k40t_driver/psdk/aes.h"
#include "k40t_driver/psdk/commands/payload_state.h"

namespace k40t::psdk {

// Fewer random bytes than this (before the first 0x00) are refused.
constexpr size_t kMinRandomBytes = 13;

// The random bytes that count: up to the first 0x00, at most 16.
size_t usable_random_length(const IdentityVerification& command);

Md5Digest identity_digest(const std::string& app_key, const IdentityVerification& command);

// Payload side: code 0x00 + digest, or 0x01 (digest zero) when too few random bytes remain.
IdentityVerificationAck answer_identity_verification(const std::string& app_key,
                                                     const IdentityVerification& command);

// Adapter side: true when `ack` proves knowledge of `app_key`.
bool identity_answer_matches(const std::string& app_key, const IdentityVerification& command,
                             const IdentityVerificationAck& ack);

}  // namespace k40t::psdk
