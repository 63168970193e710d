// The messages of the pod protocol document, transcribed from its message catalogue
// (docs/protocol/): what the catalogue must hold (test_catalogue_completeness.cpp) and what the
// tests that count messages count (test_sim_request_coverage.cpp,
// test_thermal_visible_catalogue.cpp), so that no test keeps a count of its own.
#pragma once

#include "k40t_driver/protocol/message_id.h"

namespace k40t::protocol::document {

// Periodic reports, status frames, gimbal/thermal/visible/common
// camera/laser/SBUS requests, the two crossing requests.
inline constexpr MessageId kReports[] = {0x000001, 0x000002, 0x000003,
                                         0x000004, 0x000005, 0x000008};
inline constexpr MessageId kStatusFrames[] = {0x020302, 0x020303, 0x020304, 0x020307,
                                              0x02030C, 0x02030D, 0x020406};
inline constexpr MessageId kRequests[] = {
    // gimbal
    0x000010, 0x000012, 0x000013, 0x000017, 0x000018, 0x00002C, 0x00002D, 0x00002E, 0x00002F,
    0x000030, 0x000031, 0x000033,
    // thermal
    0x000100, 0x000105, 0x000106, 0x000108, 0x00010A, 0x00010B, 0x00010C, 0x00010D, 0x00010E,
    0x00010F, 0x000110, 0x000123, 0x000124, 0x000125, 0x000126,
    // visible
    0x000200, 0x000201, 0x000202, 0x000203, 0x000204, 0x000205, 0x000206, 0x000207, 0x000208,
    0x000209, 0x00020A, 0x00020B,
    // common camera
    0x000300, 0x000301, 0x000302, 0x000303, 0x000304, 0x000306, 0x000307, 0x000308, 0x00030A,
    0x00030B, 0x00030C, 0x00030D, 0x00030E, 0x00030F, 0x000311, 0x000312, 0x000313, 0x000314,
    0x000316, 0x000317, 0x000318, 0x000319, 0x000324,
    // laser, SBUS
    0x000400, 0x000406, 0x000500, 0x000501, 0x000502,
    // crossing: the pod asks the flight controller; the flight controller asks the pod
    0x000310, 0x000320};
// ACKs that carry data beyond the response code (NOTES "ACK" column).
inline constexpr MessageId kDataAcks[] = {0x010018, 0x010100, 0x010200, 0x010310, 0x010312,
                                          0x010317, 0x010320, 0x010400, 0x010502};

}  // namespace k40t::protocol::document
