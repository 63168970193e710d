// Payload state command set 0x01 (protocol document section 3.1, docs/psdk.md#frames' reply table):
// the adapter asks, the payload answers.
#pragma once

#include "k40t_driver/psdk/commands/declare.h"

namespace k40t::psdk {

constexpr size_t kRandomSize = 16;
constexpr size_t kProductNameSize = 32;
constexpr size_t kProductIdSize = 16;
constexpr size_t kDeveloperAccountSize = 64;
constexpr size_t kMaxHandshakeSize = 32;

// "0xAABBCCDD represents version AA.BB.CC.DD", sent as a uint32 LE: debug byte first.
struct Version {
  uint8_t major = 0;
  uint8_t minor = 0;
  uint8_t modify = 0;
  uint8_t debug = 0;
  K40T_PSDK_LAYOUT(s, v) {
    v("debug", s.debug, wire::u8);
    v("modify", s.modify, wire::u8);
    v("minor", s.minor, wire::u8);
    v("major", s.major, wire::u8);
  }
};

// The DATA of the version ACKs (3.1.2, 3.1.5).
struct VersionValue {
  Version version;
  K40T_PSDK_LAYOUT(s, v) { Version::layout(s.version, v); }
};

// 3.1.1 ACK: the raw 16-byte MD5 of (app key, random bytes); see identity.h.
struct IdentityVerificationAck : Reply<CommandSet::kPayloadState, 0x01, Sender::kPayload> {
  K40T_PSDK_NAMED("identity_verification_ack", "3.1.1");
  std::array<uint8_t, 16> md5{};
  K40T_PSDK_LAYOUT(s, v) { v("md5", s.md5, wire::Bytes<16>{}); }
};

// 3.1.1: sent at irregular times by the adapter.
struct IdentityVerification
    : Command<CommandSet::kPayloadState, 0x01, Sender::kAdapter, IdentityVerificationAck> {
  K40T_PSDK_NAMED("identity_verification", "3.1.1");
  std::array<uint8_t, kRandomSize> random{};
  K40T_PSDK_LAYOUT(s, v) { v("random", s.random, wire::Bytes<kRandomSize>{}); }
};

// 3.1.2: GetPsdkVersion, PsdkVersionAck.
K40T_PSDK_GET(PsdkVersion, psdk_version, VersionValue, kPayloadState, 0x02, "3.1.2");

// 3.1.3 ACK: the command's data echoed.
struct HandshakeAck : Reply<CommandSet::kPayloadState, 0x03, Sender::kPayload>,
                      OpaqueData<1, kMaxHandshakeSize> {
  K40T_PSDK_NAMED("link_handshake_ack", "3.1.3");
};

// 3.1.3: 1..32 bytes the payload must echo.
struct Handshake : Command<CommandSet::kPayloadState, 0x03, Sender::kAdapter, HandshakeAck>,
                   OpaqueData<1, kMaxHandshakeSize> {
  K40T_PSDK_NAMED("link_handshake", "3.1.3");
};

// 3.1.4 ACK.
struct ProductInfoValue {
  K40T_PSDK_FIELDS((std::string, product_name,
                    wire::Text{kProductNameSize}),                         // at most 31 bytes + NUL
                   (std::string, product_id, wire::Text{kProductIdSize}),  // at most 15 bytes + NUL
                   (std::string, developer_account,
                    wire::Text{kDeveloperAccountSize}));  // at most 63 bytes + NUL
};

// 3.1.4: GetProductInfo, ProductInfoAck.
K40T_PSDK_GET(ProductInfo, product_info, ProductInfoValue, kPayloadState, 0x04, "3.1.4");

// 3.1.5: GetSkyportVersion, SkyportVersionAck: the SKYPORT version the payload wants (for
// upgrading it with DJI Assistant 2).
K40T_PSDK_GET(SkyportVersion, skyport_version, VersionValue, kPayloadState, 0x05, "3.1.5");

// 3.1.6 ACK.
struct ProductAliasValue {
  K40T_PSDK_FIELDS((std::string, alias, wire::Text{kProductNameSize}));  // at most 31 bytes + NUL
};

// 3.1.6: GetProductAlias, ProductAliasAck.
K40T_PSDK_GET(ProductAlias, product_alias, ProductAliasValue, kPayloadState, 0x06, "3.1.6");

}  // namespace k40t::psdk
