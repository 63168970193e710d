// Every PSDK command struct and every ACK struct: a sample with every field set away from its
// default encodes, decodes to the same fields, re-encodes to the same bytes, stays within the
// declared sizes, and decodes the same through the type-erased catalogue.
#include <gtest/gtest.h>

#include <type_traits>

#include "k40t_driver/psdk/catalogue.h"
#include "k40t_driver/psdk/commands/all.h"
#include "k40t_driver/psdk/frame.h"
#include "psdk_test_support.h"

namespace k40t::psdk {
namespace {

using testing::RecordingSink;

// Sets each field of a layout to a distinct, non-default value that the document's ranges allow
// for most fields; the few with narrower ranges are fixed up below.
class Filler {
 public:
  template <class T, class Int>
  void operator()(const char*, T& v, wire::Raw<Int>) {
    if constexpr (std::is_enum_v<T>)
      v = other_code(v);
    else if constexpr (std::is_same_v<T, bool>)
      v = true;
    else
      v = static_cast<T>(next() % 7 + 1);
  }
  template <class Int>
  void operator()(const char*, double& v, wire::Scaled<Int>) {
    v = static_cast<double>(next() % 9 + 1) * 0.5;
  }
  template <class T, class Float>
  void operator()(const char*, T& v, wire::Real<Float>) {
    v = static_cast<T>((next() % 7 + 1) * 0.125);
  }
  void operator()(const char*, std::string& v, wire::Text) { v = "t" + std::to_string(next()); }
  void operator()(const char*, const wire::Gap&, wire::Reserved) {}
  template <size_t N>
  void operator()(const char*, std::array<uint8_t, N>& v, wire::Bytes<N>) {
    for (uint8_t& b : v) b = static_cast<uint8_t>(next() * 37 + 1);
  }
  template <class Sub, class Int>
  void operator()(const char*, Sub& v, wire::Packed<Int>) {
    Sub::layout(v, *this);
  }
  template <class T>
  void operator()(const char*, T& v, wire::Bits b) {
    if constexpr (std::is_enum_v<T>)
      v = other_code(v);
    else if constexpr (std::is_same_v<T, bool>)
      v = true;
    else
      v = static_cast<T>(next() % ((1u << b.width) - 1) + 1);
  }

 private:
  unsigned next() { return ++counter_; }
  // A defined code other than the current (default) one.
  template <class E>
  E other_code(E current) {
    std::vector<E> codes;
    for (int c = 0; c <= 0xFF; ++c) {
      if (to_string(static_cast<E>(c)) != nullptr && static_cast<E>(c) != current)
        codes.push_back(static_cast<E>(c));
    }
    return codes[next() % codes.size()];
  }
  unsigned counter_ = 0;
};

template <class T>
void fixup(T&) {}
void fixup(GetWidgetGroupData& m) {
  m.group = 1;
}
void fixup(WidgetGroupCountAck& m) {
  m.count = 2;
}
void fixup(SetSpotMeteringZone& m) {
  m.zone = {11, 7};
}
void fixup(SpotMeteringZoneAck& m) {
  m.zone = {3, 5};
}
void fixup(SetDigitalZoomFactor& m) {
  m.factor_x = 2.5f;
}
void fixup(DigitalZoomFactorAck& m) {
  m.factor_x = 4.0f;
}
void fixup(OpticalZoomFactorAck& m) {
  m.factor_x = 30.0f;
}
void fixup(DigitalZoomSpecAck& m) {
  m.max_factor_x = 16.0f;
}
void fixup(OpticalZoomSpecAck& m) {
  m.max_focal_length_mm = 317.0;
  m.min_focal_length_mm = 6.5;
}
void fixup(SetFocusZone& m) {
  m.y = 1.0f;
}

template <class T>
T sample() {
  T m{};
  if constexpr (is_ack_v<T>) m.code = AckCode::kOk;
  Filler filler;
  T::layout(m, filler);
  fixup(m);
  return m;
}

// Hand-made samples of the variable-length structs.
template <class T>
T with_data(const std::string& bytes) {
  T m;
  m.data = decltype(m.data)::from(bytes);
  return m;
}
template <>
Handshake sample<Handshake>() {
  return with_data<Handshake>("hello skyport");
}
template <>
HandshakeAck sample<HandshakeAck>() {
  return with_data<HandshakeAck>(std::string(32, 'x'));
}
template <>
TransparentFromMobile sample<TransparentFromMobile>() {
  return with_data<TransparentFromMobile>(std::string("\x01\x00\x02", 3));
}
template <>
TransparentToMobile sample<TransparentToMobile>() {
  return with_data<TransparentToMobile>(std::string(128, '\xAB'));
}
template <>
TransparentFromOnboard sample<TransparentFromOnboard>() {
  return with_data<TransparentFromOnboard>(std::string(255, '\x5A'));
}
template <>
TransparentToOnboard sample<TransparentToOnboard>() {
  return with_data<TransparentToOnboard>(std::string(1, '\x00'));
}
template <>
FloatingWindowMessage sample<FloatingWindowMessage>() {
  FloatingWindowMessage m;
  m.text = "SD card full \xE2\x80\x94 recording stopped";
  return m;
}
template <>
WidgetListDataAck sample<WidgetListDataAck>() {
  WidgetListDataAck m;
  m.type = WidgetType::kChooseList;
  m.index = 3;
  m.name = "Palette";
  m.choose_item_count = 3;
  m.choose_items = {"white hot", "black hot", "ironbow"};
  return m;
}
template <>
WidgetGroupDataAck sample<WidgetGroupDataAck>() {
  WidgetGroupDataAck m;
  m.count = 3;
  m.widgets[0] = {WidgetType::kSwitch, 0, 1};
  m.widgets[1] = {WidgetType::kRangeBar, 1, 73};
  m.widgets[2] = {WidgetType::kIntegerInputBox, 2, -123456};
  return m;
}
// The header both position lists share: `count` points of task 9, from 2024-06-30 23:59:58.
template <class T>
T position_list(uint8_t count) {
  T m;
  m.count = count;
  m.task_index = 9;
  m.base_time = {2024, 6, 30, 23, 59, 58};
  return m;
}
template <>
GetPosition sample<GetPosition>() {
  GetPosition m = position_list<GetPosition>(5);
  for (size_t i = 0; i < 5; ++i) {
    m.points[i].event.event_index = static_cast<uint16_t>(8191 - i);
    m.points[i].event.target_point_index = static_cast<uint8_t>(7 - i);
    m.points[i].time_offset_us = static_cast<uint32_t>(2000000 - i * 1000);
  }
  return m;
}
template <>
GetPositionAck sample<GetPositionAck>() {
  GetPositionAck m = position_list<GetPositionAck>(4);
  for (size_t i = 0; i < 4; ++i) {
    TargetPosition& p = m.points[i];
    p.event = {static_cast<uint16_t>(100 + i), static_cast<uint8_t>(i)};
    p.time_offset_us = static_cast<uint32_t>(1000 * i);
    p.solution = PositionSolution::kFixed;
    p.uav_pitch_deg = -5;
    p.uav_roll_deg = 3;
    p.uav_yaw_deg = -179;
    p.offset_north_mm = 120;
    p.offset_east_mm = -45;
    p.offset_down_mm = 300;
    p.longitude_deg = 113.9434 + i * 1e-6;
    p.latitude_deg = 22.5790;
    p.height_m = 45.25;
    p.longitude_std_dev = 0.01f;
    p.latitude_std_dev = 0.02f;
    p.height_std_dev = 0.03f;
  }
  return m;
}

std::vector<std::string> fields_of_data(const CommandInfo& info, const Data& data) {
  RecordingSink sink;
  const Status s = info.describe(data.data(), data.size, sink);
  EXPECT_TRUE(s) << info.name << ": " << s.message();
  return sink.lines;
}

template <class T>
void check_round_trip() {
  SCOPED_TRACE(T::kName);
  const T original = sample<T>();
  const Result<Data> encoded = encode_data(original);
  ASSERT_TRUE(encoded) << encoded.error();
  EXPECT_GE(encoded->size, min_data_size<T>());
  EXPECT_LE(encoded->size, max_data_size<T>());

  const Result<T> decoded = decode_data<T>(encoded.value());
  ASSERT_TRUE(decoded) << decoded.error();
  RecordingSink before;
  RecordingSink after;
  describe(original, before);
  describe(decoded.value(), after);
  EXPECT_EQ(before.lines, after.lines);

  const Result<Data> again = encode_data(decoded.value());
  ASSERT_TRUE(again) << again.error();
  EXPECT_EQ(std::vector<uint8_t>(again->data(), again->data() + again->size),
            std::vector<uint8_t>(encoded->data(), encoded->data() + encoded->size));

  // A sample with data must differ from the default struct on the wire: the fields really went
  // somewhere (the default of a variable-length struct may not even be valid).
  if (before.lines.size() > (is_ack_v<T> ? 1u : 0u) && detail::HasLayout<T>::value) {
    const Result<Data> plain = encode_data(T{});
    if (plain) {
      EXPECT_NE(std::vector<uint8_t>(plain->data(), plain->data() + plain->size),
                std::vector<uint8_t>(encoded->data(), encoded->data() + encoded->size));
    }
  }
}

template <class Cmd>
void check_command_and_ack(const CommandKey key, std::vector<std::string>& names) {
  check_round_trip<Cmd>();
  const CommandInfo* info = find_command(key, PacketType::kCommand);
  ASSERT_NE(info, nullptr) << Cmd::kName;
  EXPECT_EQ(info->name, Cmd::kName);
  names.push_back(info->name);
  const Result<Data> encoded = encode_data(sample<Cmd>());
  ASSERT_TRUE(encoded);
  RecordingSink direct;
  describe(sample<Cmd>(), direct);
  EXPECT_EQ(fields_of_data(*info, encoded.value()), direct.lines) << Cmd::kName;

  using Ack = typename Cmd::Ack;
  const CommandInfo* ack_info = find_command(key, PacketType::kAck);
  if constexpr (std::is_same_v<Ack, NoAck>) {
    EXPECT_EQ(ack_info, nullptr) << Cmd::kName << " has no ACK in the document";
    EXPECT_FALSE(info->acked);
  } else {
    ASSERT_NE(ack_info, nullptr) << Cmd::kName;
    EXPECT_TRUE(info->acked);
    EXPECT_NE(ack_info->sender, info->sender);
    names.push_back(ack_info->name);
    if constexpr (!std::is_same_v<Ack, PlainAck>) {
      check_round_trip<Ack>();
      EXPECT_EQ(ack_info->name, Ack::kName);
    } else {
      EXPECT_EQ(ack_info->name, std::string(Cmd::kName) + "_ack");
      EXPECT_EQ(ack_info->min_size, 1u);
    }
  }
}

template <class... Cmds>
void check_all(TypeList<Cmds...>, std::vector<std::string>& names) {
  (check_command_and_ack<Cmds>(Cmds::key(), names), ...);
}

TEST(PsdkCommands, EveryCommandAndAckRoundTrips) {
  std::vector<std::string> names;
  check_all(AllCommands{}, names);
  EXPECT_EQ(names.size(), catalogue().size()) << "catalogue entries not reached from AllCommands";
}

TEST(PsdkCommands, CatalogueNamesAreUniqueAndSorted) {
  const auto& all = catalogue();
  for (size_t i = 0; i < all.size(); ++i) {
    EXPECT_EQ(find_command(all[i].name), &all[i]) << all[i].name;
    if (i > 0) {
      const bool ordered = all[i - 1].key < all[i].key ||
                           (all[i - 1].key == all[i].key && all[i - 1].packet < all[i].packet);
      EXPECT_TRUE(ordered) << all[i - 1].name << " / " << all[i].name;
    }
  }
}

TEST(PsdkCommands, CatalogueCoversEveryCommandOfTheDocument) {
  // Section 2.4 plus the ids chapter 3 adds (text input box 0x02/0x09, UTC 0x03/0x0A, other
  // payloads 0x03/0x0B-0x0C, gimbal 0x05/0x05-0x06/0x08-0x09, sets 0x06 and 0x07).
  const std::vector<std::pair<int, std::vector<int>>> expected = {
      {0x01, {0x01, 0x02, 0x03, 0x04, 0x05, 0x06}},
      {0x02, {0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07, 0x08, 0x09}},
      {0x03, {0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07, 0x08, 0x09, 0x0A, 0x0B, 0x0C}},
      {0x04, {0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07, 0x08, 0x09, 0x0A, 0x20,
              0x21, 0x22, 0x23, 0x30, 0x31, 0x32, 0x33, 0x34, 0x35, 0x36, 0x37,
              0x38, 0x39, 0x40, 0x41, 0x42, 0x43, 0x44, 0x45, 0x46, 0x47, 0xFF}},
      {0x05, {0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07, 0x08, 0x09, 0xFF}},
      {0x06, {0x01, 0x02}},
      {0x07, {0x01}},
  };
  size_t commands = 0;
  for (const auto& [set, ids] : expected) {
    for (int id : ids) {
      const CommandKey key{static_cast<uint8_t>(set), static_cast<uint8_t>(id)};
      EXPECT_NE(find_command(key, PacketType::kCommand), nullptr) << set << "/" << id;
      ++commands;
    }
  }
  size_t in_catalogue = 0;
  for (const CommandInfo& c : catalogue()) in_catalogue += c.packet == PacketType::kCommand;
  EXPECT_EQ(in_catalogue, commands);
}

FrameView view_of(const testing::Bytes& frame) {
  FrameView v;
  v.header = parse_header(frame.data());
  v.data = frame.data() + kHeaderSize;
  v.data_size = frame.size() - kFrameOverhead;
  v.bytes = frame.data();
  v.size = frame.size();
  return v;
}

TEST(PsdkCommands, DescribesWholeFrames) {
  RecordingSink sink;
  ASSERT_TRUE(describe_frame(view_of(testing::kGetVersionAck), nullptr, sink));
  EXPECT_TRUE(sink.has("command=\"get_psdk_version_ack\"")) << ::testing::PrintToString(sink.lines);
  EXPECT_TRUE(sink.has("packet_type=1(ack)"));
  EXPECT_TRUE(sink.has("sequence=0"));
  EXPECT_TRUE(sink.has("code=0(ok)"));
  EXPECT_TRUE(sink.has("major=1"));
  EXPECT_TRUE(sink.has("minor=3"));
}

TEST(PsdkCommands, DescribingAnUnknownCommandNamesIt) {
  FrameHeader h;
  h.command = {0x04, 0x50};
  const testing::Bytes frame = testing::make_frame(h, {0x01, 0x02});
  RecordingSink sink;
  const Status s = describe_frame(view_of(frame), nullptr, sink);
  ASSERT_FALSE(s);
  EXPECT_NE(s.message().find("0x04/0x50 is not in the document"), std::string::npos) << s.message();
  EXPECT_TRUE(sink.has("command=\"unknown\""));
  EXPECT_TRUE(sink.has("data=0102"));
}

TEST(PsdkCommands, PayloadEncryptsWhatPsdkCrcMdLists) {
  EXPECT_TRUE(
      find_command(key_of(CommandSet::kAppFunction, 0x02), PacketType::kCommand)->encrypted);
  EXPECT_TRUE(
      find_command(key_of(CommandSet::kAppFunction, 0x03), PacketType::kCommand)->encrypted);
  EXPECT_TRUE(
      find_command(key_of(CommandSet::kOsdkFunction, 0x02), PacketType::kCommand)->encrypted);
  EXPECT_TRUE(
      find_command(key_of(CommandSet::kPositioning, 0x01), PacketType::kCommand)->encrypted);
  EXPECT_FALSE(
      find_command(key_of(CommandSet::kAppFunction, 0x01), PacketType::kCommand)->encrypted);
  EXPECT_FALSE(find_command(key_of(CommandSet::kCamera, 0x03), PacketType::kCommand)->encrypted);
}

}  // namespace
}  // namespace k40t::psdk
