// The PSDK session over an in-memory transport: ACKs echo sequence, set and id and copy the
// encryption type; unknown commands get 0x02; our requests are matched on sequence + set + id
// and time out; typed handlers; encryption of what the payload must encrypt.
#include <gtest/gtest.h>

#include <atomic>
#include <future>
#include <thread>

#include "eventually.h"
#include "k40t_driver/psdk/commands/all.h"
#include "k40t_driver/psdk/parser.h"
#include "k40t_driver/psdk/session.h"
#include "psdk_fake_transport.h"
#include "psdk_test_support.h"

namespace k40t::psdk {
namespace {

using testing::FakeLink;

using testing::Bytes;
using testing::command_frame;
using testing::kGetVersion;
using testing::kGetVersionAck;

const AesKey kKey = {0x71, 0xc6, 0x82, 0xc7, 0xe3, 0x73, 0x20, 0x53,
                     0xf0, 0x05, 0xc0, 0xdd, 0x78, 0xd0, 0x1e, 0x5e};

using k40t::test::eventually;

struct Endpoint {
  FakeLink* link = nullptr;
  std::unique_ptr<Session> session;
};

SessionOptions with_ack_timeout(std::chrono::milliseconds timeout) {
  SessionOptions options;
  options.ack_timeout = timeout;
  return options;
}

Endpoint make_endpoint(SessionOptions options = {}) {
  auto link = std::make_unique<FakeLink>();
  Endpoint e;
  e.link = link.get();
  e.session = std::make_unique<Session>(std::move(link), std::move(options));
  return e;
}

// An adapter and a payload session on two paired links. Both are stopped before either link is
// destroyed: a running side may still be writing into its peer.
struct LinkedPair {
  explicit LinkedPair(SessionOptions adapter_options)
      : adapter(make_endpoint(adapter_options)), payload(make_endpoint()) {
    FakeLink::pair(*adapter.link, *payload.link);
  }
  ~LinkedPair() {
    adapter.session->stop();
    payload.session->stop();
  }
  Endpoint adapter;
  Endpoint payload;
};

Bytes ack_frame(CommandKey key, uint16_t sequence, const Bytes& data) {
  FrameHeader h;
  h.packet_type = PacketType::kAck;
  h.command = key;
  h.sequence = sequence;
  return testing::make_frame(h, data);
}

struct Parsed {
  FrameHeader header;
  Bytes data;  // plain
};

Parsed parse_one(const Bytes& frame, const Aes128Ecb* cipher = nullptr) {
  FrameParser parser;
  Parsed out;
  int frames = 0;
  parser.feed(frame.data(), frame.size(), [&](const FrameView& f) {
    ++frames;
    out.header = f.header;
    auto d = open_data(f, cipher);
    EXPECT_TRUE(d) << d.error();
    if (d) out.data.assign(d->data(), d->data() + d->size);
  });
  EXPECT_EQ(frames, 1);
  return out;
}

TEST(PsdkSession, AnswersTheDocumentsVersionRequestWithItsAckVector) {
  Endpoint payload = make_endpoint();
  payload.session->handle<GetPsdkVersion>([](const GetPsdkVersion&) {
    PsdkVersionAck ack;
    ack.version = {1, 3, 0, 0};
    return ack;
  });
  ASSERT_TRUE(payload.session->start());
  payload.link->inject(kGetVersion);
  const auto sent = payload.link->wait_for_sent(1);
  ASSERT_EQ(sent.size(), 1u);
  EXPECT_EQ(sent[0], kGetVersionAck);
  EXPECT_TRUE(eventually([&] { return payload.session->stats().acks_sent == 1; }));
}

TEST(PsdkSession, AckEchoesSequenceSetAndId) {
  Endpoint payload = make_endpoint();
  std::atomic<int> shots{0};
  payload.session->handle<ShootPhoto>([&](const ShootPhoto& c) {
    if (c.action == ShootPhotoAction::kStart) ++shots;
    return AckCode::kOk;
  });
  ASSERT_TRUE(payload.session->start());
  payload.link->inject(command_frame(ShootPhoto::key(), 0xBEEF, {0x01}));
  const auto sent = payload.link->wait_for_sent(1);
  ASSERT_EQ(sent.size(), 1u);
  const Parsed ack = parse_one(sent[0]);
  EXPECT_EQ(ack.header.packet_type, PacketType::kAck);
  EXPECT_EQ(ack.header.sequence, 0xBEEF);
  EXPECT_EQ(ack.header.command, ShootPhoto::key());
  EXPECT_EQ(ack.header.ack_request, AckRequest::kNoAck);
  EXPECT_EQ(ack.data, Bytes{0x00});
  EXPECT_EQ(shots.load(), 1);
}

TEST(PsdkSession, UnknownCommandsAreAnsweredUnsupported) {
  Endpoint payload = make_endpoint();
  ASSERT_TRUE(payload.session->start());
  payload.link->inject(command_frame({0x04, 0x50}, 7, {0x01, 0x02}));  // not in the document
  payload.link->inject(command_frame(GetGimbalState::key(), 8, {}));   // no handler
  const auto sent = payload.link->wait_for_sent(2);
  ASSERT_EQ(sent.size(), 2u);
  const Parsed first = parse_one(sent[0]);
  EXPECT_EQ(first.header.command, (CommandKey{0x04, 0x50}));
  EXPECT_EQ(first.header.sequence, 7);
  EXPECT_EQ(first.data, Bytes{0x02});
  const Parsed second = parse_one(sent[1]);
  EXPECT_EQ(second.header.command, GetGimbalState::key());
  EXPECT_EQ(second.data, Bytes{0x02});
  EXPECT_EQ(payload.session->stats().unsupported, 2u);
}

TEST(PsdkSession, NoAckWhenNoneIsRequested) {
  Endpoint payload = make_endpoint();
  std::atomic<int> pushes{0};
  payload.session->handle<AttitudePush>([&](const AttitudePush&) { ++pushes; });
  ASSERT_TRUE(payload.session->start());
  const Bytes attitude = {0x00, 0x00, 0x80, 0x3f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  payload.link->inject(command_frame(AttitudePush::key(), 1, attitude, AckRequest::kNoAck));
  payload.link->inject(
      command_frame({0x03, 0x7F}, 2, {}, AckRequest::kNoAck));  // unknown, no ACK wanted
  payload.link->drain();
  EXPECT_EQ(pushes.load(), 1);
  EXPECT_TRUE(payload.link->sent().empty());
  EXPECT_EQ(payload.session->stats().commands_received, 2u);
}

TEST(PsdkSession, UndecodableCommandIsAnsweredError) {
  Endpoint payload = make_endpoint();
  payload.session->handle<ControlGimbalSpeed>(
      [](const ControlGimbalSpeed&) { return AckCode::kOk; });
  ASSERT_TRUE(payload.session->start());
  payload.link->inject(command_frame(ControlGimbalSpeed::key(), 3, {0x01, 0x02}));  // 2 of 7 bytes
  const auto sent = payload.link->wait_for_sent(1);
  ASSERT_EQ(sent.size(), 1u);
  EXPECT_EQ(parse_one(sent[0]).data, Bytes{0x01});
  EXPECT_EQ(payload.session->stats().decode_errors, 1u);
}

TEST(PsdkSession, AckCopiesTheCommandsEncryption) {
  SessionOptions options;
  options.aes_key = kKey;
  Endpoint payload = make_endpoint(options);
  payload.session->handle<GetRecordState>([](const GetRecordState&) {
    RecordStateAck ack;
    ack.recording = true;
    ack.duration_s = 42;
    return ack;
  });
  ASSERT_TRUE(payload.session->start());
  const Aes128Ecb cipher(kKey);
  payload.link->inject(
      command_frame(GetRecordState::key(), 11, {}, AckRequest::kAfterExecution, &cipher));
  const auto sent = payload.link->wait_for_sent(1);
  ASSERT_EQ(sent.size(), 1u);
  const Parsed ack = parse_one(sent[0], &cipher);
  EXPECT_EQ(ack.header.encryption, Encryption::kAes);
  EXPECT_EQ(ack.header.padding, 12);  // 4 bytes of DATA in one block
  EXPECT_EQ(ack.data, (Bytes{0x00, 0x01, 0x2a, 0x00}));
}

TEST(PsdkSession, EncryptedCommandWithoutKeyIsCountedAndDropped) {
  Endpoint payload = make_endpoint();
  ASSERT_TRUE(payload.session->start());
  const Aes128Ecb cipher(kKey);
  payload.link->inject(
      command_frame(GetRecordState::key(), 1, {}, AckRequest::kAfterExecution, &cipher));
  payload.link->drain();
  EXPECT_TRUE(payload.link->sent().empty());
  EXPECT_EQ(payload.session->stats().decrypt_errors, 1u);
}

TEST(PsdkSession, RequestsAreMatchedOnSequenceSetAndId) {
  Endpoint payload = make_endpoint(with_ack_timeout(std::chrono::milliseconds(300)));
  ASSERT_TRUE(payload.session->start());

  AckResult result;
  std::thread requester([&] {
    GetPosition p;
    p.base_time = {2024, 1, 2, 3, 4, 5};
    Result<GetPositionAck> ack = payload.session->request(p, &result);
    EXPECT_FALSE(ack);  // the matching ACK never comes
  });
  const auto sent = payload.link->wait_for_sent(1);
  ASSERT_EQ(sent.size(), 1u);
  const Parsed request = parse_one(sent[0]);
  EXPECT_EQ(request.header.sequence, 0);  // our first command
  EXPECT_EQ(request.header.ack_request, AckRequest::kAfterExecution);
  // ACKs with the wrong sequence, the wrong id and the wrong set do not match.
  payload.link->inject(ack_frame(GetPosition::key(), 1, {0x01}));
  payload.link->inject(ack_frame({0x07, 0x02}, 0, {0x01}));
  payload.link->inject(ack_frame({0x06, 0x01}, 0, {0x01}));
  requester.join();
  payload.link->drain();
  EXPECT_TRUE(result.sent);
  EXPECT_FALSE(result.received);
  EXPECT_NE(result.message.find("no ACK within 300 ms"), std::string::npos) << result.message;
  const SessionStats stats = payload.session->stats();
  EXPECT_EQ(stats.late_acks, 3u);
  EXPECT_EQ(stats.ack_timeouts, 1u);
}

TEST(PsdkSession, AdapterAndPayloadTalk) {
  SessionOptions adapter_options;
  adapter_options.role = Sender::kAdapter;
  LinkedPair pair(adapter_options);
  Endpoint& adapter = pair.adapter;
  Endpoint& payload = pair.payload;
  payload.session->handle<GetGimbalState>([](const GetGimbalState&) {
    GimbalStateAck ack;
    ack.mode = GimbalStateMode::kFollowing;
    ack.angles = {-45.5, 0.0, 12.3};
    return ack;
  });
  ASSERT_TRUE(adapter.session->start());
  ASSERT_TRUE(payload.session->start());

  for (int i = 0; i < 3; ++i) {
    Result<GimbalStateAck> ack = adapter.session->request(GetGimbalState{});
    ASSERT_TRUE(ack) << ack.error();
    EXPECT_EQ(ack->code, AckCode::kOk);
    EXPECT_EQ(ack->mode, GimbalStateMode::kFollowing);
    EXPECT_DOUBLE_EQ(ack->angles.pitch_deg, -45.5);
  }
  // Unhandled on the payload side: the typed request gets the refusal, code only.
  Result<CameraWorkModeAck> refused = adapter.session->request(GetCameraWorkMode{});
  ASSERT_TRUE(refused) << refused.error();
  EXPECT_EQ(refused->code, AckCode::kUnsupported);
  EXPECT_EQ(adapter.session->stats().acks_received, 4u);
  EXPECT_TRUE(eventually([&] { return payload.session->stats().acks_sent == 4; }));
}

TEST(PsdkSession, ConcurrentRequestsAllFindTheirAcks) {
  SessionOptions adapter_options;
  adapter_options.role = Sender::kAdapter;
  adapter_options.ack_timeout = std::chrono::seconds(5);
  LinkedPair pair(adapter_options);
  Endpoint& adapter = pair.adapter;
  Endpoint& payload = pair.payload;
  payload.session->handle<Handshake>([](const Handshake& h) {
    HandshakeAck ack;
    ack.data = h.data;
    return ack;
  });
  ASSERT_TRUE(adapter.session->start());
  ASSERT_TRUE(payload.session->start());
  std::vector<std::thread> threads;
  std::atomic<int> echoed{0};
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      for (int i = 0; i < 25; ++i) {
        Handshake h;
        h.data = Blob<32>::from("t" + std::to_string(t) + "i" + std::to_string(i));
        Result<HandshakeAck> ack = adapter.session->request(h);
        if (ack && ack->data == h.data) ++echoed;
      }
    });
  }
  for (auto& th : threads) th.join();
  EXPECT_EQ(echoed.load(), 100);
}

TEST(PsdkSession, SequenceStartsAtZeroAndIncrementsPerCommand) {
  Endpoint payload = make_endpoint();
  ASSERT_TRUE(payload.session->start());
  FloatingWindowMessage m;
  m.text = "recording started";
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(payload.session->send(m));
  const auto sent = payload.link->wait_for_sent(3);
  ASSERT_EQ(sent.size(), 3u);
  for (uint16_t i = 0; i < 3; ++i) {
    const Parsed p = parse_one(sent[i]);
    EXPECT_EQ(p.header.sequence, i);
    EXPECT_EQ(p.header.ack_request, AckRequest::kNoAck);
    EXPECT_EQ(p.header.encryption, Encryption::kNone);  // no key configured
  }
}

TEST(PsdkSession, PayloadEncryptsWhatItMustWhenKeyed) {
  SessionOptions options;
  options.aes_key = kKey;
  Endpoint payload = make_endpoint(options);
  ASSERT_TRUE(payload.session->start());
  FloatingWindowMessage text;
  text.text = "SD card full";
  ASSERT_TRUE(payload.session->send(text));
  TransparentToMobile mobile;
  mobile.data = Blob<128>::from("abc");
  ASSERT_TRUE(payload.session->send(mobile));
  const auto sent = payload.link->wait_for_sent(2);
  ASSERT_EQ(sent.size(), 2u);
  const Aes128Ecb cipher(kKey);
  const Parsed p = parse_one(sent[0], &cipher);
  EXPECT_EQ(p.header.encryption, Encryption::kAes);
  EXPECT_EQ(std::string(p.data.begin(), p.data.end()), std::string("SD card full", 13));
  EXPECT_EQ(parse_one(sent[1], &cipher).header.encryption, Encryption::kAes);
}

TEST(PsdkSession, AnswersCanBeSentLater) {
  Endpoint payload = make_endpoint();
  std::mutex mutex;
  std::optional<FrameHeader> kept;
  payload.session->on_command(BatteryInfoPush::key(),
                              [&](const IncomingCommand& in) -> std::optional<Data> {
                                std::lock_guard<std::mutex> lock(mutex);
                                kept = in.header;
                                return std::nullopt;  // answer once recording has stopped
                              });
  ASSERT_TRUE(payload.session->start());
  payload.link->inject(command_frame(BatteryInfoPush::key(), 77, {0x05, 0x01}));
  payload.link->drain();
  EXPECT_TRUE(payload.link->sent().empty());
  BatteryInfoAck ready;
  ready.power_off_ready = true;
  std::lock_guard<std::mutex> lock(mutex);
  ASSERT_TRUE(kept.has_value());
  ASSERT_TRUE(payload.session->send_ack(*kept, encode_data(ready).value()));
  const auto sent = payload.link->wait_for_sent(1);
  const Parsed ack = parse_one(sent[0]);
  EXPECT_EQ(ack.header.sequence, 77);
  EXPECT_EQ(ack.data, (Bytes{0x00, 0x01}));
}

TEST(PsdkSession, FailuresComeBackAsMessages) {
  Endpoint payload = make_endpoint();
  AckResult r = payload.session->request_raw(GetPosition::key(), nullptr, 0);
  EXPECT_FALSE(r.sent);
  EXPECT_NE(r.message.find("not started"), std::string::npos) << r.message;
  ASSERT_TRUE(payload.session->start());
  payload.link->refuse_sends(true);
  r = payload.session->request_raw(GetPosition::key(), nullptr, 0);
  EXPECT_FALSE(r.sent);
  EXPECT_NE(r.message.find("send refused"), std::string::npos) << r.message;
  GetPosition invalid;
  invalid.count = 0;
  Result<GetPositionAck> ack = payload.session->request(invalid);
  ASSERT_FALSE(ack);
  EXPECT_NE(ack.error().find("'count' must be 1..5"), std::string::npos) << ack.error();
  EXPECT_EQ(payload.session->stats().send_errors, 1u);
}

TEST(PsdkSession, StopCompletesOutstandingRequests) {
  Endpoint payload = make_endpoint(with_ack_timeout(std::chrono::seconds(30)));
  ASSERT_TRUE(payload.session->start());
  std::promise<AckResult> done;
  payload.session->request_async(GetPosition::key(), Data{},
                                 [&](const AckResult& r) { done.set_value(r); });
  payload.link->wait_for_sent(1);
  payload.session->stop();
  const AckResult r = done.get_future().get();
  EXPECT_FALSE(r.received);
  EXPECT_NE(r.message.find("stopped"), std::string::npos) << r.message;
}

}  // namespace
}  // namespace k40t::psdk
