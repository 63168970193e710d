// The offline pieces of `k40t bag`: the driver's YAML parameter file read without a master, and
// the bag sink's topic names, header.seq and receive times.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <set>
#include <string>

#include <rosbag/view.h>

#include "k40t_driver/ros/bag/bag_topic_sink.h"
#include "k40t_driver/ros/bag/yaml_params.h"
#include "k40t_driver/ros/decoded_topics.h"
#include "k40t_driver/ros/ros_params.h"

namespace k40t::driver {
namespace {

class TempFile {
 public:
  explicit TempFile(const std::string& suffix)
      : path_("/tmp/k40t_bag_offline_" + std::to_string(::getpid()) + suffix) {}
  ~TempFile() { std::remove(path_.c_str()); }
  const std::string& path() const { return path_; }
  void write(const std::string& text) const { std::ofstream(path_) << text; }

 private:
  std::string path_;
};

Result<RosPodConfig> config_from(const std::string& yaml) {
  TempFile file(".yaml");
  file.write(yaml);
  Result<XmlRpc::XmlRpcValue> params = load_yaml_params(file.path());
  if (!params) return Result<RosPodConfig>::fail(params.error());
  ParamReader reader(params.value(), "~");
  return read_params(reader);
}

TEST(YamlParams, ValuesAreTypedAsRosparamLoadsThem) {
  Result<RosPodConfig> c = config_from(
      "frame_prefix: left_\nbaud: 57600\npublish_tf: false\ncrc_coverage: whole_frame\n"
      "tele_offset: [1, 0.5, -2]\nlaser_max_range: 800\ntime_sync_period: 2.5\n");
  ASSERT_TRUE(c) << c.error();
  EXPECT_EQ(c->ids.base, "left_base_link");
  EXPECT_EQ(c->driver.baud, 57600);
  EXPECT_FALSE(c->publish_tf);
  EXPECT_EQ(c->driver.session.crc_coverage, protocol::CrcCoverage::kWholeFrame);
  EXPECT_EQ(c->geometry.tele, (std::array<double, 3>{1.0, 0.5, -2.0}));  // integers read as reals
  EXPECT_FLOAT_EQ(c->range.max_range, 800.0f);
  EXPECT_DOUBLE_EQ(c->driver.time_sync_period_s, 2.5);
}

// docs/protocol/decisions.md#a4: above 364, 180 deg x scale no longer fits 0x000012's uint16.
TEST(YamlParams, AnAngleScaleTheMagnitudeCannotCarryIsRefused) {
  Result<RosPodConfig> large = config_from("angle_command_scale: 1000\n");
  ASSERT_FALSE(large);
  EXPECT_EQ(large.error(), "parameter ~/angle_command_scale must be 1..364, got 1000");
  Result<RosPodConfig> fraction = config_from("angle_command_scale: 100.5\n");
  ASSERT_FALSE(fraction);
  EXPECT_EQ(fraction.error(), "parameter ~/angle_command_scale must be a whole number");
  Result<RosPodConfig> most = config_from("angle_command_scale: 364\n");
  ASSERT_TRUE(most) << most.error();
  EXPECT_EQ(most->driver.session.codec.angle_command_scale, 364);
}

TEST(YamlParams, AbsentParametersKeepTheDriversDefaults) {
  Result<RosPodConfig> c = config_from("device: serial:///dev/ttyUSB1\n");
  ASSERT_TRUE(c) << c.error();
  EXPECT_EQ(c->ids.base, "k40t_base_link");
  EXPECT_TRUE(c->publish_tf);
  EXPECT_EQ(c->driver.session.codec.ack_byte_order, protocol::ByteOrder::kBig);
}

TEST(YamlParams, BadValuesFailNamingTheParameter) {
  Result<RosPodConfig> wrong_type = config_from("baud: fast\n");
  ASSERT_FALSE(wrong_type);
  EXPECT_EQ(wrong_type.error(), "parameter ~/baud has the wrong type");
  Result<RosPodConfig> quoted_number = config_from("publish_tf: \"true\"\n");
  ASSERT_FALSE(quoted_number);  // a quoted scalar is a string, as for rosparam
  EXPECT_EQ(quoted_number.error(), "parameter ~/publish_tf has the wrong type");
  Result<RosPodConfig> out_of_range = config_from("laser_max_range: -1\n");
  ASSERT_FALSE(out_of_range);
  EXPECT_NE(out_of_range.error().find("parameter ~/laser_max_range must be"), std::string::npos)
      << out_of_range.error();
  Result<RosPodConfig> short_list = config_from("laser_offset: [1, 2]\n");
  ASSERT_FALSE(short_list);
  EXPECT_NE(short_list.error().find("laser_offset must be a list of 3 numbers"), std::string::npos);
}

TEST(YamlParams, LookAtParameters) {
  Result<RosPodConfig> c = config_from(
      "look_at_drive: rate\nlook_at_rate: 25\ngimbal_yaw_continuous: true\nlook_at_lead: 0.1\n"
      "look_at_point_timeout: 2\n");
  ASSERT_TRUE(c) << c.error();
  EXPECT_EQ(c->look_at.control.drive, LookAtDrive::kRate);
  EXPECT_DOUBLE_EQ(c->look_at.rate_hz, 25);
  EXPECT_TRUE(c->look_at.control.limits.yaw_continuous);
  EXPECT_DOUBLE_EQ(c->look_at.control.lead_s, 0.1);
  EXPECT_DOUBLE_EQ(c->look_at.point_timeout_s, 2);
  Result<RosPodConfig> defaults = config_from("device: serial:///dev/ttyUSB1\n");
  ASSERT_TRUE(defaults) << defaults.error();
  EXPECT_EQ(defaults->look_at.control.drive, LookAtDrive::kAngle);
  EXPECT_FALSE(defaults->look_at.control.limits.yaw_continuous);
  Result<RosPodConfig> bad = config_from("look_at_drive: fast\n");
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error(), "parameter ~/look_at_drive must be angle or rate, got 'fast'");
  Result<RosPodConfig> slow = config_from("look_at_rate: 5\n");
  ASSERT_FALSE(slow);  // below the 10 Hz
  EXPECT_NE(slow.error().find("look_at_rate must be 10..50"), std::string::npos) << slow.error();
}

// A conventions file as `k40t probe --out` writes it (docs/protocol/decisions.md#conventions): each
// reading by its name; the diagnostic learns which ones were set.
TEST(YamlParams, ConventionsAreReadByTheirNames) {
  Result<RosPodConfig> c = config_from(
      "yaw_sign: left\npitch_sign: down\nsd_capacity_unit: 0.1mb\ncalibration_end: ack\n"
      "ack_byte_order: little\n");
  ASSERT_TRUE(c) << c.error();
  const protocol::Conventions& got = c->driver.session.codec.conventions;
  EXPECT_EQ(got.yaw_sign, protocol::YawSign::kLeft);
  EXPECT_EQ(got.pitch_sign, protocol::PitchSign::kDown);
  EXPECT_EQ(got.sd_capacity_unit, protocol::SdCapacityUnit::kTenthMb);
  EXPECT_EQ(got.calibration_end, protocol::CalibrationEnd::kAck);
  EXPECT_EQ(got.roll_sign, protocol::RollSign::kRightDown);  // not in the file: the default
  EXPECT_EQ(c->driver.session.codec.ack_byte_order, protocol::ByteOrder::kLittle);
  EXPECT_EQ(c->driver.conventions_from_parameters,
            (std::set<std::string>{"yaw_sign", "pitch_sign", "sd_capacity_unit", "calibration_end",
                                   "ack_byte_order"}));
  Result<RosPodConfig> bad = config_from("yaw_sign: up\n");
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error(), "parameter ~/yaw_sign must be right or left, got 'up'");
  EXPECT_FALSE(config_from("shutter_field: 100\n"));  // a number, not one of the words
}

// ack_byte_order: auto (big until the pod's ACKs show the order); a bad value names all three.
TEST(YamlParams, AckByteOrderTakesAuto) {
  Result<RosPodConfig> c = config_from("ack_byte_order: auto\n");
  ASSERT_TRUE(c) << c.error();
  EXPECT_TRUE(c->driver.session.codec.ack_byte_order_auto);
  EXPECT_EQ(c->driver.session.codec.ack_byte_order, protocol::ByteOrder::kBig);
  Result<RosPodConfig> fixed = config_from("ack_byte_order: little\n");
  ASSERT_TRUE(fixed) << fixed.error();
  EXPECT_FALSE(fixed->driver.session.codec.ack_byte_order_auto);
  Result<RosPodConfig> bad = config_from("ack_byte_order: middle\n");
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error(), "parameter ~/ack_byte_order must be big, little or auto, got 'middle'");
}

TEST(YamlParams, UnreadableFilesFailWithTheirPath) {
  Result<XmlRpc::XmlRpcValue> missing = load_yaml_params("/nonexistent/k40t.yaml");
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().find("/nonexistent/k40t.yaml"), std::string::npos);
  TempFile file(".yaml");
  file.write("baud: [1, 2\n");
  EXPECT_FALSE(load_yaml_params(file.path()));
  file.write("- a list\n- not a mapping\n");
  Result<XmlRpc::XmlRpcValue> list = load_yaml_params(file.path());
  ASSERT_FALSE(list);
  EXPECT_NE(list.error().find("not a mapping"), std::string::npos);
}

TEST(BagTopicSink, NamesSeqAndTimesAreThoseOfALiveRecording) {
  TempFile file(".bag");
  {
    rosbag::Bag bag(file.path(), rosbag::bagmode::Write);
    BagTopicSink sink(bag, "/pod1");
    auto joints = sink.advertise<sensor_msgs::JointState>("joint_states", 10, false);
    auto range = sink.advertise<sensor_msgs::Range>("laser/range", 10, false);
    auto range_again = sink.advertise<sensor_msgs::Range>("laser/range", 10, false);
    auto tf = sink.advertise<tf2_msgs::TFMessage>("/tf", 100, false);
    sensor_msgs::JointState j;
    j.header.seq = 77;  // overwritten, as roscpp does
    j.header.stamp = ros::Time(5, 6);
    // Distinct receive times: rosbag reads equal times in no set order across topics.
    sink.set_receive_time(ros::Time(10, 0));
    joints(j);
    sensor_msgs::Range r;
    sink.set_receive_time(ros::Time(11, 0));
    range(r);
    sink.set_receive_time(ros::Time(12, 0));
    joints(j);
    sink.set_receive_time(ros::Time(13, 0));
    range_again(r);  // one topic, one counter, however often advertised
    sink.set_receive_time(ros::Time(14, 0));
    tf(tf2_msgs::TFMessage());
    EXPECT_EQ(sink.written(), 5u);
  }
  rosbag::Bag bag(file.path(), rosbag::bagmode::Read);
  rosbag::View view(bag);
  std::vector<std::string> topics;
  std::vector<uint32_t> seqs;
  std::vector<uint32_t> seconds;
  for (const rosbag::MessageInstance& m : view) {
    topics.push_back(m.getTopic());
    seconds.push_back(m.getTime().sec);
    if (auto js = m.instantiate<sensor_msgs::JointState>()) {
      seqs.push_back(js->header.seq);
      EXPECT_EQ(js->header.stamp, ros::Time(5, 6));
    } else if (auto rg = m.instantiate<sensor_msgs::Range>()) {
      seqs.push_back(rg->header.seq);
    }
  }
  EXPECT_EQ(topics, (std::vector<std::string>{"/pod1/joint_states", "/pod1/laser/range",
                                              "/pod1/joint_states", "/pod1/laser/range", "/tf"}));
  EXPECT_EQ(seqs, (std::vector<uint32_t>{0, 0, 1, 1}));
  EXPECT_EQ(seconds, (std::vector<uint32_t>{10, 11, 12, 13, 14}));
}

TEST(BagTopicSink, TheRootNamespaceResolvesToAbsoluteNames) {
  TempFile file(".bag");
  rosbag::Bag bag(file.path(), rosbag::bagmode::Write);
  EXPECT_EQ(BagTopicSink(bag, "/").resolve("raw/rx"), "/raw/rx");
  EXPECT_EQ(BagTopicSink(bag, "/a/b").resolve("gimbal/status"), "/a/b/gimbal/status");
  EXPECT_EQ(BagTopicSink(bag, "/a").resolve("/tf"), "/tf");
}

}  // namespace
}  // namespace k40t::driver
