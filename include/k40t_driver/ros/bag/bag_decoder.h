// Offline decoding of recorded flights (`k40t bag`): the raw frames of a bag go through the same
// replay-mode PodDriver and the same advertise_decoded_topics() as `replay.launch`, at full speed,
// and every decoded message is written to another bag instead of published. Stamps and header.seq
// are those a recording of the replay would hold (BagTopicSink).
//
// Each `<ns>/raw/rx` topic (k40t_driver/Frame) of the input is one driver: several pods in one bag
// decode side by side, each into its own namespace. `<ns>/raw/tx` (the driver's requests) only
// feeds the exports. Besides the decoded topics, /tf_static (when publish_tf) is written once,
// before the first decoded message, stamped with the first frame's stamp (live: the driver's
// start time). Diagnostics are not decoded: they are driven by the wall clock, not by frames.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <rosbag/bag.h>

#include "frame_export.h"  // tools/k40t_bag: the exports, ROS-free
#include "k40t_driver/ros/ros_params.h"

namespace k40t::driver {

struct BagDecodeOptions {
  RosPodConfig config;  // the driver's parameters (replay is forced)
  // Frame and joint prefix by namespace ("/pod_a" -> "pod_a_"; the key "" for every namespace),
  // as replay.launch's frame_prefix sets both; a namespace without one keeps config.ids.
  std::map<std::string, std::string> frame_prefixes;
  std::vector<FrameExport*> exports;     // optional
  std::function<void(double)> progress;  // fraction 0..1 of the input's raw frames, may be empty
};

struct BagDecodeSummary {
  std::vector<std::string> namespaces;  // one per raw/rx topic
  uint64_t rx_frames = 0;               // raw/rx messages read
  uint64_t tx_frames = 0;
  uint64_t messages_written = 0;
  uint64_t bad_frames = 0;  // raw/rx messages the parser did not accept as one good frame
};

// Fails with a readable message for an unreadable or truncated bag, or one without raw/rx; what
// was written to `output` before the failure stays there (the caller discards it).
Result<BagDecodeSummary> decode_bag(const std::string& input, rosbag::Bag& output,
                                    const BagDecodeOptions& options);

}  // namespace k40t::driver
