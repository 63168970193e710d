#include "k40t_driver/ros/bag/bag_decoder.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <map>
#include <memory>

#include <rosbag/view.h>

#include "k40t_driver/Frame.h"
#include "k40t_driver/ros/bag/bag_topic_sink.h"
#include "k40t_driver/ros/decoded_topics.h"

namespace k40t::driver {

namespace {

// Whole name components: "/k40t/raw/rx", "/raw/rx", never "/k40traw/rx".
constexpr const char* kRxSuffix = "/raw/rx";
constexpr const char* kTxSuffix = "/raw/tx";

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// "/k40t/raw/rx" -> "/k40t"; "/raw/rx" -> "/".
std::string namespace_of(const std::string& topic, const std::string& suffix) {
  const std::string ns = topic.substr(0, topic.size() - suffix.size());
  return ns.empty() ? "/" : ns;
}

// The parameters of the pod in `ns`: the common ones, with its frame prefix if it has one.
RosPodConfig config_for(const std::string& ns, const BagDecodeOptions& options) {
  RosPodConfig config = options.config;
  auto prefix = options.frame_prefixes.find(ns);
  if (prefix == options.frame_prefixes.end()) prefix = options.frame_prefixes.find("");
  if (prefix != options.frame_prefixes.end()) config.ids = FrameIds(prefix->second, prefix->second);
  return config;
}

// One pod of the bag: a replay-mode driver writing its decoded topics, and the raw frames'
// exports.
class PodDecoder {
 public:
  PodDecoder(std::string ns, rosbag::Bag& output, const BagDecodeOptions& options,
             const std::string& bag, const std::string& rx_topic, const std::string& tx_topic)
      : sink_(output, ns),
        options_(options),
        config_(config_for(ns, options)),
        bag_(bag),
        rx_topic_(rx_topic),
        tx_topic_(tx_topic) {
    DriverOptions driver_options = config_.driver;
    driver_options.replay = true;
    driver_ = PodDriver::create(driver_options, [] { return StampNs{0}; }).value();
    advertise_decoded_topics(sink_, *driver_, config_);
    if (config_.publish_tf)
      static_tf_ = sink_.advertise<tf2_msgs::TFMessage>("/tf_static", 100, true);
    if (!options.exports.empty()) {
      driver_->on_rx_frame([this](const protocol::FrameView& frame, StampNs stamp) {
        export_frame(rx_topic_, rx_index_++, frame, stamp);
      });
      tx_ = std::make_unique<session::Dispatcher>(driver_options.session.crc_coverage,
                                                  driver_options.session.codec);
      tx_->on_frame([this](const protocol::FrameView& frame) {
        export_frame(tx_topic_, tx_index_++, frame, tx_stamp_);
      });
    }
    driver_->start();  // replay mode: no link, no threads
  }

  void received(const k40t_driver::Frame& frame, const ros::Time& receive_time) {
    if (frame.direction != k40t_driver::Frame::RX) return;  // as the replay input
    sink_.set_receive_time(receive_time);
    const StampNs stamp = static_cast<StampNs>(frame.stamp.toNSec());
    if (static_tf_) {
      tf2_msgs::TFMessage transforms;
      transforms.transforms = sensor_transforms(frame.stamp, config_.ids, config_.geometry);
      static_tf_(transforms);
      static_tf_ = nullptr;
    }
    driver_->replay_frame(frame.data.data(), frame.data.size(), stamp);
  }

  void sent(const k40t_driver::Frame& frame) {
    if (!tx_) return;
    tx_stamp_ = static_cast<StampNs>(frame.stamp.toNSec());
    tx_->feed_frame(frame.data.data(), frame.data.size());
  }

  uint64_t written() const { return sink_.written(); }
  uint64_t good_frames() const { return driver_->stats().session.parser.frames_good; }

 private:
  void export_frame(const std::string& topic, uint64_t index, const protocol::FrameView& frame,
                    StampNs stamp) {
    const ExportedFrame exported{bag_, topic, stamp, index, frame};
    // The driver's codec now: with ack_byte_order: auto, the order the pod's ACKs showed.
    for (FrameExport* e : options_.exports) e->write(exported, driver_->codec());
  }

  BagTopicSink sink_;
  const BagDecodeOptions& options_;
  const RosPodConfig config_;
  const std::string& bag_;
  std::string rx_topic_, tx_topic_;
  std::unique_ptr<PodDriver> driver_;
  std::function<void(const tf2_msgs::TFMessage&)> static_tf_;
  std::unique_ptr<session::Dispatcher> tx_;
  StampNs tx_stamp_ = 0;
  uint64_t rx_index_ = 0, tx_index_ = 0;
};

std::string topic_list(rosbag::View& view) {
  std::string topics;
  for (const rosbag::ConnectionInfo* c : view.getConnections())
    topics += (topics.empty() ? "" : ", ") + c->topic;
  return topics.empty() ? "none" : topics;
}

}  // namespace

Result<BagDecodeSummary> decode_bag(const std::string& input, rosbag::Bag& output,
                                    const BagDecodeOptions& options) {
  using Fail = Result<BagDecodeSummary>;
  BagDecodeSummary summary;
  if (::access(input.c_str(), R_OK) != 0)
    return Fail::fail(input + ": cannot open: " + std::strerror(errno));
  uint64_t read = 0;
  try {
    rosbag::Bag bag(input, rosbag::bagmode::Read);
    rosbag::View everything(bag);
    // Which topics are whose: <ns>/raw/rx and <ns>/raw/tx of type k40t_driver/Frame.
    std::map<std::string, std::unique_ptr<PodDecoder>> pods;     // by namespace
    std::map<std::string, std::pair<PodDecoder*, bool>> routes;  // topic -> pod, is rx
    const std::string frame_type = ros::message_traits::datatype<k40t_driver::Frame>();
    for (const rosbag::ConnectionInfo* c : everything.getConnections()) {
      if (c->datatype == frame_type && ends_with(c->topic, kRxSuffix)) {
        const std::string ns = namespace_of(c->topic, kRxSuffix);
        if (pods.count(ns)) continue;
        const std::string tx_topic = c->topic.substr(0, c->topic.size() - 2) + "tx";
        pods[ns] = std::make_unique<PodDecoder>(ns, output, options, input, c->topic, tx_topic);
        routes[c->topic] = {pods[ns].get(), true};
        summary.namespaces.push_back(ns);
      }
    }
    if (pods.empty()) {
      return Fail::fail(input + ": no raw/rx topic (k40t_driver/Frame) to decode; topics: " +
                        topic_list(everything));
    }
    for (const rosbag::ConnectionInfo* c : everything.getConnections()) {
      if (c->datatype != frame_type || !ends_with(c->topic, kTxSuffix)) continue;
      auto pod = pods.find(namespace_of(c->topic, kTxSuffix));
      if (pod != pods.end()) routes[c->topic] = {pod->second.get(), false};
    }
    std::vector<std::string> topics;
    for (const auto& [topic, route] : routes) topics.push_back(topic);
    rosbag::View frames(bag, rosbag::TopicQuery(topics));
    const uint64_t total = frames.size();
    const uint64_t step = std::max<uint64_t>(1, total / 1000);
    for (const rosbag::MessageInstance& m : frames) {
      const k40t_driver::Frame::ConstPtr frame = m.instantiate<k40t_driver::Frame>();
      const auto& [pod, rx] = routes.at(m.getTopic());
      if (frame && rx) {
        pod->received(*frame, m.getTime());
        ++summary.rx_frames;
      } else if (frame) {
        pod->sent(*frame);
        ++summary.tx_frames;
      }
      if (options.progress && ++read % step == 0)
        options.progress(static_cast<double>(read) / static_cast<double>(total));
    }
    uint64_t good = 0;
    for (const auto& [ns, pod] : pods) {
      summary.messages_written += pod->written();
      good += pod->good_frames();
    }
    summary.bad_frames = summary.rx_frames > good ? summary.rx_frames - good : 0;
    if (options.progress) options.progress(1.0);
  } catch (const std::exception& e) {
    // rosbag's BagException family: unreadable, unindexed or truncated files, bad chunks.
    return Fail::fail(input + ": cannot read the bag" +
                      (read ? " after " + std::to_string(read) + " frames" : std::string()) + ": " +
                      e.what() + " (a truncated bag may be repaired with `rosbag reindex`)");
  }
  return summary;
}

}  // namespace k40t::driver
