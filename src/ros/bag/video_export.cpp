#include "k40t_driver/ros/bag/video_export.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>
#include <set>

#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <opencv2/imgcodecs.hpp>

#include "k40t_driver/CompressedVideo.h"
#include "k40t_driver/video/container_writer.h"
#include "k40t_driver/video/video_codec.h"

namespace k40t::driver {

namespace {

constexpr const char* kVideoType = "k40t_driver/CompressedVideo";

Result<std::string> pick_topic(rosbag::Bag& bag, const std::string& wanted) {
  rosbag::View all(bag);
  std::set<std::string> video;
  std::set<std::string> others;
  for (const rosbag::ConnectionInfo* c : all.getConnections())
    (c->datatype == kVideoType ? video : others).insert(c->topic);
  if (!wanted.empty()) {
    if (video.count(wanted)) return wanted;
    return Result<std::string>::fail(
        "topic " + wanted +
        (others.count(wanted) ? " is not " + std::string(kVideoType) : " is not in the bag"));
  }
  if (video.size() == 1) return *video.begin();
  if (video.empty())
    return Result<std::string>::fail(std::string("the bag has no ") + kVideoType +
                                     " topic (record.launch records <ns>/image_raw/k40t_video)");
  std::string list;
  for (const std::string& t : video) list += (list.empty() ? "" : ", ") + t;
  return Result<std::string>::fail("the bag has several video topics (" + list +
                                   "): choose one with --video-topic");
}

// DIR/frame_NNNNNN.png and DIR/frames.csv.
class FrameFiles {
 public:
  static Result<std::unique_ptr<FrameFiles>> open(const std::string& dir) {
    if (::mkdir(dir.c_str(), 0777) != 0 && errno != EEXIST)
      return Status::fail("cannot create " + dir + ": " + std::strerror(errno));
    const std::string csv = dir + "/frames.csv";
    FILE* file = std::fopen(csv.c_str(), "w");
    if (!file) return Status::fail("cannot write " + csv + ": " + std::strerror(errno));
    std::fprintf(file, "frame,stamp_ns,key_frame,file\n");
    return std::unique_ptr<FrameFiles>(new FrameFiles(dir, file));
  }
  ~FrameFiles() {
    if (csv_) std::fclose(csv_);
  }
  Status write(const video::DecodedFrame& frame, int64_t stamp_ns, bool key_frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06llu.png", static_cast<unsigned long long>(count_));
    const std::string path = dir_ + "/" + name;
    if (!cv::imwrite(path, video::i420_to_bgr(frame))) return Status::fail("cannot write " + path);
    std::fprintf(csv_, "%llu,%lld,%d,%s\n", static_cast<unsigned long long>(count_),
                 static_cast<long long>(stamp_ns), key_frame ? 1 : 0, name);
    ++count_;
    return Status::ok();
  }
  Status close() {
    const bool ok = std::fflush(csv_) == 0 && !std::ferror(csv_);
    std::fclose(csv_);
    csv_ = nullptr;
    return ok ? Status::ok() : Status::fail("cannot write " + dir_ + "/frames.csv");
  }
  uint64_t count() const { return count_; }

 private:
  FrameFiles(std::string dir, FILE* csv) : dir_(std::move(dir)), csv_(csv) {}
  std::string dir_;
  FILE* csv_;
  uint64_t count_ = 0;
};

// Where the export is, message by message.
struct Exporter {
  const VideoExportOptions& options;
  VideoExportSummary summary;
  std::unique_ptr<video::ContainerWriter> container;
  std::unique_ptr<video::VideoDecoder> decoder;
  std::unique_ptr<FrameFiles> frames;
  std::optional<int64_t> first_key_ns;
  int64_t last_ns = 0;

  Status add(const k40t_driver::CompressedVideo& m) {
    ++summary.messages;
    Result<video::Codec> codec = video::parse_codec(m.format);
    if (!codec)
      return Status::fail("message " + std::to_string(summary.messages) + ": " + codec.error());
    if (summary.format.empty()) summary.format = m.format;
    if (summary.format != m.format)
      return Status::fail("the topic changes format from " + summary.format + " to " + m.format);
    const int64_t stamp_ns = static_cast<int64_t>(m.header.stamp.toNSec());
    if (!first_key_ns && !m.key_frame) return Status::ok();
    if (!first_key_ns) first_key_ns = stamp_ns;
    last_ns = stamp_ns;
    if (!options.video_file.empty()) {
      if (!container) {
        auto opened = video::ContainerWriter::open(options.video_file, codec.value());
        if (!opened) return opened.status();
        container = std::move(opened.value());
      }
      if (auto w = container->write(m.data.data(), m.data.size(), m.key_frame, stamp_ns); !w)
        return w.status();
    }
    if (frames) return decode(codec.value(), m, stamp_ns);
    return Status::ok();
  }

  Status decode(video::Codec codec, const k40t_driver::CompressedVideo& m, int64_t stamp_ns) {
    if (!decoder) {
      auto created = video::VideoDecoder::create(codec);
      if (!created) return created.status();
      decoder = std::move(created.value());
    }
    Result<bool> pushed = decoder->push(m.data.data(), m.data.size(), m.key_frame, 0);
    if (!pushed) return pushed.status();
    if (!pushed.value()) return Status::ok();
    std::optional<video::DecodedFrame> frame = decoder->pull(std::chrono::seconds(5));
    if (!frame) {
      // A damaged access unit: counted as missing, decoding goes on from the next key frame.
      decoder->resync();
      return Status::ok();
    }
    return frames->write(*frame, stamp_ns, m.key_frame);
  }

  Status finish() {
    if (!first_key_ns) return Status::fail("the topic has no key frame: nothing to export");
    summary.duration_s = (last_ns - *first_key_ns) / 1e9;
    if (container) {
      if (Status s = container->finish(); !s) return s;
      summary.written = container->written();
    }
    if (frames) {
      summary.frames = frames->count();
      return frames->close();
    }
    return Status::ok();
  }
};

}  // namespace

Result<VideoExportSummary> export_video(const std::string& bag_path,
                                        const VideoExportOptions& options) {
  if (options.video_file.empty() && options.frames_dir.empty())
    return Status::fail("nothing to export: give a video file or a frames directory");
  if (!options.video_file.empty()) {
    if (auto c = video::container_for(options.video_file); !c) return c.status();
  }
  Exporter exporter{options, {}, nullptr, nullptr, nullptr, std::nullopt, 0};
  try {
    rosbag::Bag bag(bag_path, rosbag::bagmode::Read);
    Result<std::string> topic = pick_topic(bag, options.topic);
    if (!topic) return Status::fail(bag_path + ": " + topic.error());
    exporter.summary.topic = topic.value();
    if (!options.frames_dir.empty()) {
      auto frames = FrameFiles::open(options.frames_dir);
      if (!frames) return frames.status();
      exporter.frames = std::move(frames.value());
    }
    rosbag::View view(bag, rosbag::TopicQuery(topic.value()));
    for (const rosbag::MessageInstance& m : view) {
      auto message = m.instantiate<k40t_driver::CompressedVideo>();
      if (!message) continue;
      if (Status s = exporter.add(*message); !s) return Status::fail(bag_path + ": " + s.message());
    }
  } catch (const std::exception& e) {
    return Status::fail(bag_path + ": cannot read: " + e.what());
  }
  if (Status s = exporter.finish(); !s) return Status::fail(bag_path + ": " + s.message());
  return exporter.summary;
}

}  // namespace k40t::driver
