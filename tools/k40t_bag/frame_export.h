// `k40t bag --jsonl / --csv`: every raw frame of the decoded bags (received and sent) with its
// recorded stamp and its decoded fields, for analysis outside ROS.
//   JSON lines: one object per frame: {"bag", "topic", "stamp_ns", "frame": {...}} where "frame"
//               is what `k40t decode` prints for it ("offset" = the frame's index in its topic).
//   CSV:        one file per message, <dir>/<id>_<name>.csv (e.g. 0x000002_gimbal_attitude.csv),
//               columns bag, topic, stamp_ns, src, dst, seq, then the fields as `k40t decode`
//               names them (enums as the code plus a <name>_label column, byte arrays as hex).
//               Frames whose payload does not decode are only counted.
#pragma once

#include <cstdint>
#include <cstdio>
#include <map>
#include <memory>
#include <string>

#include "k40t_driver/protocol/codec_options.h"
#include "k40t_driver/protocol/frame.h"
#include "k40t_driver/protocol/result.h"

namespace k40t::driver {

struct ExportedFrame {
  const std::string& bag;
  const std::string& topic;
  int64_t stamp_ns;
  uint64_t index;  // of the frame in its topic
  const protocol::FrameView& frame;
};

class FrameExport {
 public:
  virtual ~FrameExport() = default;
  virtual void write(const ExportedFrame& frame, const protocol::CodecOptions& codec) = 0;
  // Flushes and reports a write error (disk full...).
  virtual Status finish() = 0;
};

Result<std::unique_ptr<FrameExport>> open_jsonl_export(const std::string& path);
Result<std::unique_ptr<FrameExport>> open_csv_export(const std::string& directory);

}  // namespace k40t::driver
