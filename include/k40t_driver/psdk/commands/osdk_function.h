// OSDK function command set 0x06 (protocol document section 3.6): transparent data between an
// Onboard SDK computer on the airframe and the payload.
#pragma once

#include "k40t_driver/psdk/commands/declare.h"

namespace k40t::psdk {

constexpr size_t kMaxOsdkTransparent = 255;

// 3.6.1: 1..255 bytes from the onboard computer. No ACK.
K40T_PSDK_TRANSPARENT(TransparentFromOnboard, kOsdkFunction, 0x01, kAdapter, kMaxOsdkTransparent,
                      "transparent_from_onboard", "3.6.1");

// 3.6.2: 1..255 bytes to the onboard computer. No ACK. Encrypted by the payload
// (docs/psdk.md#frames).
K40T_PSDK_TRANSPARENT(TransparentToOnboard, kOsdkFunction, 0x02, kPayload, kMaxOsdkTransparent,
                      "transparent_to_onboard", "3.6.2");

}  // namespace k40t::psdk
