// What the simulated pod sends on its own, computed from the model — never constants: the
// periodic reports at the document's rates and the status frames of the model's events.
//   0x000001 gimbal status      2 Hz   always (the gimbal has its own board)
//   0x000002 gimbal attitude   10 Hz   always
//   0x000003 camera status      1 Hz   while the camera is up
//   0x000004 thermal status     5 Hz   while the camera is up and measurement is on (0x000108)
//   0x000005 visible status     5 Hz   while the camera is up
//   0x020406 periodic laser     1 Hz   while periodic ranging is on (0x000406)
//   0x000008 upgrade/repair     1 Hz   while upgrading or calibrating (from MaintenanceEvent)
// The gimbal's messages (0x000001, 0x000002 and 0x000010-0x0000FF, section 3.1) come from the
// gimbal's address (docs/protocol/decisions.md#a3), the rest, 0x000003-0x000008 included, from the
// camera's.
#pragma once

#include <optional>
#include <vector>

#include "k40t_driver/protocol/codec_options.h"
#include "k40t_driver/protocol/message.h"
#include "k40t_driver/sim/events.h"
#include "k40t_driver/sim/pod_model.h"

namespace k40t::sim {

struct OutgoingMessage {
  protocol::MessageId id = 0;
  protocol::Payload payload;
};

struct PeriodicReport {
  protocol::MessageId id;
  double period_s;
  bool (*active)(const PodModel& pod);
  Result<protocol::Payload> (*encode)(const PodModel& pod, const protocol::CodecOptions& codec);
};
const std::vector<PeriodicReport>& periodic_reports();

// Decides which reports are due, in model time: each report goes out every period, starting at
// time 0 (a report that was inactive restarts its cadence when it becomes active again).
class ReportScheduler {
 public:
  ReportScheduler();
  // The reports due at model time `now_s` (each at most once per call).
  std::vector<const PeriodicReport*> due(const PodModel& pod, double now_s);

 private:
  std::vector<double> next_due_s_;
};

// The frame for one event; nullopt for GpsRequestEvent (a request, sent by the front-end as one).
std::optional<OutgoingMessage> encode_event(const PodEvent& event,
                                            const protocol::CodecOptions& codec);

}  // namespace k40t::sim
