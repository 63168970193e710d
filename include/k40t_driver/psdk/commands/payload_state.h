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
  template <class S, class V>
  static void layout(S& s, V&& v) {
    v("debug", s.debug, wire::u8);
    v("modify", s.modify, wire::u8);
    v("minor", s.minor, wire::u8);
    v("major", s.major, wire::u8);
  }
};

// The DATA of the version ACKs (3.1.2, 3.1.5).
struct VersionValue {
  Version version;
  template <class S, class V>
  static void layout(S& s, V&& v) {
    Version::layout(s.version, v);
  }
};

// 3.1.1 ACK: the raw 16-byte MD5 of (app key, random bytes); see identity.h.
struct IdentityVerificationAck : Reply<CommandSet::kPayloadState, 0x01, Sender::kPayload> {
  K40T_PSDK_NAMED("identity_verification_ack", "3.1.1");
  std::array<uint8_t, 16> md5{};
  template <class S, class V>
  static void layout(S& s, V&& v) {
    v("md5", s.md5, wire::Bytes<16>{});
  }
};

// 3.1.1: sent at irregular times by the adapter.
struct IdentityVerification
    : Command<CommandSet::kPayloadState, 0x01, Sender::kAdapter, IdentityVerificationAck> {
  K40T_PSDK_NAMED("identity_verification", "3.1.1");
  std::array<uint8_t, kRandomSize> random{};
  template <class S, class V>
  static void layout(S& s, V&& v) {
    v("random", s.random, wire::Bytes<kRandomSize>{});
  }
};

// 3.1.2 ACK.
struct PsdkVersionAck : Reply<CommandSet::kPayloadState, 0x02, Sender::kPayload>, VersionValue {
  K40T_PSDK_NAMED("get_psdk_version_ack", "3.1.2");
};

// 3.1.2.
K40T_PSDK_NO_DATA(GetPsdkVersion, kPayloadState, 0x02, PsdkVersionAck, "get_psdk_version", "3.1.2");

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
struct ProductInfoAck : Reply<CommandSet::kPayloadState, 0x04, Sender::kPayload> {
  K40T_PSDK_NAMED("get_product_info_ack", "3.1.4");
  std::string product_name;       // at most 31 bytes + NUL
  std::string product_id;         // at most 15 bytes + NUL
  std::string developer_account;  // at most 63 bytes + NUL
  template <class S, class V>
  static void layout(S& s, V&& v) {
    v("product_name", s.product_name, wire::Text{kProductNameSize});
    v("product_id", s.product_id, wire::Text{kProductIdSize});
    v("developer_account", s.developer_account, wire::Text{kDeveloperAccountSize});
  }
};

// 3.1.4.
K40T_PSDK_NO_DATA(GetProductInfo, kPayloadState, 0x04, ProductInfoAck, "get_product_info", "3.1.4");

// 3.1.5 ACK: the SKYPORT version the payload wants (for upgrading it with DJI Assistant 2).
struct SkyportVersionAck : Reply<CommandSet::kPayloadState, 0x05, Sender::kPayload>, VersionValue {
  K40T_PSDK_NAMED("get_skyport_version_ack", "3.1.5");
};

// 3.1.5.
K40T_PSDK_NO_DATA(GetSkyportVersion, kPayloadState, 0x05, SkyportVersionAck, "get_skyport_version",
                  "3.1.5");

// 3.1.6 ACK.
struct ProductAliasAck : Reply<CommandSet::kPayloadState, 0x06, Sender::kPayload> {
  K40T_PSDK_NAMED("get_product_alias_ack", "3.1.6");
  std::string alias;  // at most 31 bytes + NUL
  template <class S, class V>
  static void layout(S& s, V&& v) {
    v("alias", s.alias, wire::Text{kProductNameSize});
  }
};

// 3.1.6.
K40T_PSDK_NO_DATA(GetProductAlias, kPayloadState, 0x06, ProductAliasAck, "get_product_alias",
                  "3.1.6");

}  // namespace k40t::psdk
