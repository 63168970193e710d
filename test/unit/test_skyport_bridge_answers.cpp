// SkyportBridge: answers that are true and in time (issue: no made-up success). Getters answer
// while a pod call is held; a full work queue answers "busy" at once; deferred ACKs obey the
// ACK-request bits; calibration progress comes from the pod's repair report; commands the pod
// cannot honour (roll, out-of-range rates, a photo count) are refused before the pod sees them.
// Command bytes are written by hand from the document (sections cited).
#include <algorithm>
#include <future>
#include <utility>

#include "skyport_bridge_rig.h"

namespace k40t::driver::skyport {
namespace {

using namespace psdk;
using namespace bridge_testing;

// Sends `data` to `key` asking for an ACK, without waiting.
std::future<AckResult> ask_async(Rig& rig, CommandKey key, std::vector<uint8_t> data = {}) {
  auto promise = std::make_shared<std::promise<AckResult>>();
  Data d;
  std::copy(data.begin(), data.end(), d.bytes.begin());
  d.size = data.size();
  rig.adapter->session().request_async(key, d,
                                       [promise](const AckResult& r) { promise->set_value(r); });
  return promise->get_future();
}

constexpr CommandKey kReturnHead{0x05, 0x03};  // 3.5.3 gimbal return head, no DATA

TEST(SkyportBridgeAnswers, GettersAnswerWhileAPodCallIsHeld) {
  Rig rig;
  rig.pod.hold();
  std::future<AckResult> held = ask_async(rig, kReturnHead);
  ASSERT_TRUE(eventually([&] { return rig.pod.held() == 1; }));
  // The pod call is still held: these can only be answered if they do not wait behind it.
  const Result<GimbalStateAck> state = rig.ask(GetGimbalState{});
  ASSERT_TRUE(state) << state.error();
  EXPECT_EQ(state->code, AckCode::kOk);
  const Result<RecordStateAck> record = rig.ask(GetRecordState{});
  ASSERT_TRUE(record) << record.error();
  EXPECT_EQ(record->code, AckCode::kOk);
  const Result<SdCardInfoAck> sd = rig.ask(GetSdCardInfo{});
  ASSERT_TRUE(sd) << sd.error();
  const Result<DigitalZoomFactorAck> digital = rig.ask(GetDigitalZoomFactor{});
  ASSERT_TRUE(digital) << digital.error();
  const Result<WidgetGroupDataAck> widgets = rig.ask(GetWidgetGroupData{});
  ASSERT_TRUE(widgets) << widgets.error();
  EXPECT_EQ(rig.pod.held(), 1);
  rig.pod.release();
  EXPECT_TRUE(held.get().ok());
}

TEST(SkyportBridgeAnswers, AFullQueueAnswersBusyAtOnceAndCountsIt) {
  Rig rig(kCredentials, BridgeOptions{}.photo_storing_s,
          [](BridgeOptions& o) { o.max_queued_jobs = 2; });
  rig.pod.hold();
  std::vector<std::future<AckResult>> accepted;
  accepted.push_back(ask_async(rig, kReturnHead));  // running, held by the pod
  ASSERT_TRUE(eventually([&] { return rig.pod.held() == 1; }));
  accepted.push_back(ask_async(rig, kReturnHead));  // queued
  accepted.push_back(ask_async(rig, kReturnHead));  // queued: the queue is full
  ASSERT_TRUE(eventually([&] { return rig.bridge->stats().queued_jobs == 2; }));
  // One more is refused at once, while the pod is still held.
  AckResult busy = ask_async(rig, kReturnHead).get();
  EXPECT_TRUE(busy.received) << busy.message;
  EXPECT_EQ(busy.code(), 0x01);
  EXPECT_EQ(rig.bridge->stats().busy_answers, 1u);
  EXPECT_EQ(rig.pod.held(), 1);
  rig.pod.release();
  for (auto& f : accepted) EXPECT_TRUE(f.get().ok());
  EXPECT_EQ(rig.bridge->stats().queued_jobs, 0u);
}

TEST(SkyportBridgeAnswers, ADeferredCommandWithoutTheAckBitGetsNoAck) {
  Rig rig;
  const uint64_t unexpected_before = rig.adapter->stats().session.late_acks;
  // 3.5.3 return head sent as a command that asks for no ACK (header ACK bits 0,
  // docs/psdk.md#frames).
  ASSERT_TRUE(rig.adapter->session().send_raw(kReturnHead, nullptr, 0));
  ASSERT_TRUE(eventually([&] { return has_call(rig.pod, "center"); }));
  // Then one that asks. The worker answers in order: an ACK of the first would have come before
  // this one's, and the adapter would have counted it as an ACK nothing waited for.
  AckResult raw = ask_async(rig, kReturnHead).get();
  EXPECT_TRUE(raw.ok()) << raw.message;
  EXPECT_EQ(rig.adapter->stats().session.late_acks, unexpected_before);
}

TEST(SkyportBridgeAnswers, ADeferredCommandThatDoesNotDecodeIsCounted) {
  Rig rig;
  const uint64_t errors_before = rig.payload->stats().decode_errors;
  // 3.4.5 set shoot photo mode: 4 bytes (type, burst count, interval count, interval); 1 sent.
  EXPECT_EQ(rig.code_of(SetShootPhotoMode::key(), {0x01}), 0x01);
  EXPECT_EQ(rig.payload->stats().decode_errors, errors_before + 1);
  EXPECT_TRUE(rig.pod.calls().empty());
}

// CameraUpgradeStatus STATE_* (msg/CameraUpgradeStatus.msg).
constexpr uint8_t kSucceeded = 0, kFailed = 1, kRepairingState = 3;

TEST(SkyportBridgeAnswers, CalibrationProgressComesFromThePodsRepairReport) {
  Rig rig;
  // Nothing calibrated yet: no progress to report, not "complete".
  EXPECT_EQ(rig.code_of(GetCalibrationProgress::key()), 0x01);
  rig.pod.report_repair(kSucceeded, 100);  // an earlier repair says nothing about this run
  ASSERT_TRUE(rig.ask(CalibrateGimbal{}));
  Result<CalibrationProgressAck> p = rig.ask(GetCalibrationProgress{});
  ASSERT_TRUE(p) << p.error();
  EXPECT_EQ(p->status, CalibrationStatus::kInProgress);
  EXPECT_EQ(p->progress_percent, 0);
  rig.pod.report_repair(kRepairingState, 40);
  p = rig.ask(GetCalibrationProgress{});
  ASSERT_TRUE(p);
  EXPECT_EQ(p->status, CalibrationStatus::kInProgress);
  EXPECT_EQ(p->progress_percent, 40);
  rig.pod.report_repair(kSucceeded, 100);
  p = rig.ask(GetCalibrationProgress{});
  ASSERT_TRUE(p);
  EXPECT_EQ(p->status, CalibrationStatus::kComplete);
  EXPECT_EQ(p->progress_percent, 100);
  ASSERT_TRUE(rig.ask(CalibrateGimbal{}));
  rig.pod.report_repair(kFailed, 60);
  p = rig.ask(GetCalibrationProgress{});
  ASSERT_TRUE(p);
  EXPECT_EQ(p->status, CalibrationStatus::kFailed);
}

TEST(SkyportBridgeAnswers, CalibrationWithoutAnyReportEndsUnknown) {
  Rig rig(kCredentials, BridgeOptions{}.photo_storing_s,
          [](BridgeOptions& o) { o.calibration_report_timeout_s = 0.2; });
  ASSERT_TRUE(rig.ask(CalibrateGimbal{}));
  EXPECT_TRUE(eventually([&] { return rig.code_of(GetCalibrationProgress::key()) == 0x01; }));
}

TEST(SkyportBridgeAnswers, SpeedWithRollOrOutOfRangeIsRefused) {
  Rig rig;
  // 3.5.4: int16 pitch, roll, yaw in 0.1 deg/s, little-endian, then uint8 action (1 control).
  // Roll 10 deg/s = 100 = 0x0064.
  EXPECT_EQ(rig.code_of(ControlGimbalSpeed::key(), {0x00, 0x00, 0x64, 0x00, 0x00, 0x00, 0x01}),
            0x01);
  // Pitch 200 deg/s = 2000 = 0x07D0, beyond 3.5.4's 1800.
  EXPECT_EQ(rig.code_of(ControlGimbalSpeed::key(), {0xD0, 0x07, 0x00, 0x00, 0x00, 0x00, 0x01}),
            0x01);
  EXPECT_TRUE(rig.pod.calls().empty());
  EXPECT_EQ(rig.bridge->stats().invalid_commands, 2u);
  // Pitch -30 deg/s = -300 = 0xFED4: accepted, sent as REP 103 (positive = down).
  EXPECT_EQ(rig.code_of(ControlGimbalSpeed::key(), {0xD4, 0xFE, 0x00, 0x00, 0x00, 0x00, 0x01}),
            0x00);
  EXPECT_TRUE(has_call(rig.pod, "rate 0.5236 -0.0000") || has_call(rig.pod, "rate 0.5236 0.0000"));
}

TEST(SkyportBridgeAnswers, AnIntervalCountThePodCannotHonourIsRefused) {
  Rig rig;
  // 3.4.5: type 6 (interval), burst count 0, interval count 3, interval 5 s.
  EXPECT_EQ(rig.code_of(SetShootPhotoMode::key(), {0x06, 0x00, 0x03, 0x05}), 0x01);
  EXPECT_TRUE(rig.pod.calls().empty());
  // Count 255 (until stopped), interval 5 s: the pod's own time-lapse.
  EXPECT_EQ(rig.code_of(SetShootPhotoMode::key(), {0x06, 0x00, 0xFF, 0x05}), 0x00);
  EXPECT_TRUE(has_call(rig.pod, "photo mode 2 5 3"));
}

TEST(SkyportBridgeAnswers, AnUnknownRecordingStateIsNotAnsweredAsKnown) {
  Rig rig;
  rig.pod.lose_record_status();
  EXPECT_EQ(rig.code_of(GetRecordState::key()), 0x01);
  // The power-off hand-shake stops the recording all the same before it says ready.
  rig.adapter->announce_power_off();
  ASSERT_TRUE(eventually([&] { return rig.adapter->stats().last_power_off_ready; }));
  EXPECT_TRUE(has_call(rig.pod, "record stop"));
}

TEST(SkyportBridgeAnswers, TheLaserButtonRangesOncePerPress) {
  Rig rig;
  SetWidgetValue set;
  AckResult raw;
  set.widget = {WidgetType::kButton, 2, 1};  // pressed
  ASSERT_TRUE(rig.ask(set, &raw));
  set.widget.value = 1;  // pressed again without a release (a repeat): no second ranging
  ASSERT_TRUE(rig.ask(set, &raw));
  set.widget.value = 0;  // released
  ASSERT_TRUE(rig.ask(set, &raw));
  EXPECT_EQ(raw.code(), 0x00);
  size_t ranged = 0;
  for (const auto& c : rig.pod.calls()) ranged += c == "measure";
  EXPECT_EQ(ranged, 1u);
  set.widget.value = 7;  // neither pressed nor released
  ASSERT_TRUE(rig.ask(set, &raw));
  EXPECT_EQ(raw.code(), 0x01);
}

TEST(SkyportBridgeAnswers, ZoomStaysConsistentWithThePod) {
  Rig rig;
  SetOpticalZoomFocalLength focal;
  focal.focal_length_mm = 9.4;  // 2x
  SetDigitalZoomFactor digital;
  digital.factor_x = 3;
  ASSERT_TRUE(rig.ask(focal));
  ASSERT_TRUE(rig.ask(digital));
  // What was set reads back as set, although the pod only knows 6x.
  Result<OpticalZoomFocalLengthAck> f = rig.ask(GetOpticalZoomFocalLength{});
  ASSERT_TRUE(f);
  EXPECT_NEAR(f->focal_length_mm, 9.4, 0.05);
  Result<DigitalZoomFactorAck> d = rig.ask(GetDigitalZoomFactor{});
  ASSERT_TRUE(d);
  EXPECT_NEAR(d->factor_x, 3.0, 0.01);
  // A continuous zoom moves the pod to 8x: optical 8x, digital 1x from now on...
  StartContinuousZoom in;
  in.direction = ZoomDirection::kIn;
  ASSERT_TRUE(rig.ask(in));
  rig.pod.report_zoom(8.0);
  ASSERT_TRUE(rig.ask(StopContinuousZoom{}));
  d = rig.ask(GetDigitalZoomFactor{});
  ASSERT_TRUE(d);
  EXPECT_NEAR(d->factor_x, 1.0, 0.01);
  // ...and the next digital set starts from there instead of jumping back to 2x optical.
  digital.factor_x = 2;
  ASSERT_TRUE(rig.ask(digital));
  EXPECT_TRUE(has_call(rig.pod, "zoom 16.00"));
}

// The pod unplugged while DJI Pilot polls: every pod call hangs (the driver waits for its
// timeout), the snapshot keeps the last known state. Getters are answered from it; commands beyond
// the queue's capacity are answered "busy" at once; the queue never holds more than its capacity.
TEST(SkyportBridgeAnswers, AnUnpluggedPodLeavesGettersAnsweredAndTheQueueBounded) {
  constexpr size_t kCapacity = 4;
  Rig rig(kCredentials, BridgeOptions{}.photo_storing_s,
          [](BridgeOptions& o) { o.max_queued_jobs = kCapacity; });
  rig.pod.hold();
  std::vector<std::future<AckResult>> commands;
  size_t most_queued = 0;
  for (int poll = 0; poll < 50; ++poll) {
    commands.push_back(ask_async(rig, kReturnHead));  // DJI Pilot keeps commanding...
    // The first command is the one held in the pod: on a loaded machine the worker may take it
    // from the queue only after the others have filled it, so the test waits until it has.
    if (poll == 0) {
      ASSERT_TRUE(eventually([&] { return rig.pod.held() == 1; }));
    }
    const Result<GimbalStateAck> state = rig.ask(GetGimbalState{});  // ...and polling
    ASSERT_TRUE(state) << state.error();
    EXPECT_EQ(state->code, AckCode::kOk);
    EXPECT_NEAR(state->angles.pitch_deg, -30, 0.1);  // the last known pose
    const Result<RecordStateAck> record = rig.ask(GetRecordState{});
    ASSERT_TRUE(record) << record.error();
    most_queued = std::max<size_t>(most_queued, rig.bridge->stats().queued_jobs);
  }
  EXPECT_LE(most_queued, kCapacity);
  // 50 commands: one held in the pod, `kCapacity` waiting, the rest refused at once.
  EXPECT_TRUE(eventually([&] { return rig.bridge->stats().busy_answers == 50 - 1 - kCapacity; }))
      << rig.bridge->stats().busy_answers;
  size_t busy = 0;  // the refused ones were answered at once (the others may time out meanwhile)
  for (auto& f : commands) {
    const AckResult r = f.get();
    busy += r.received && r.code() == 0x01;
  }
  EXPECT_EQ(busy, 50 - 1 - kCapacity);
  rig.pod.release();  // plugged in again: the held and the queued commands reach the pod
  const auto centred = [&] {
    size_t n = 0;
    for (const auto& c : rig.pod.calls()) n += c == "center";
    return n;
  };
  EXPECT_TRUE(eventually([&] { return centred() == 1 + kCapacity; })) << centred();
}

// The layouts where DJI's headers and the document disagree (docs/psdk.md P28..P30), checked on
// the ACK bytes. The expected bytes are written by hand from each source.
Rig rig_with(psdk::PsdkLayout layout) {
  return Rig(kCredentials, BridgeOptions{}.photo_storing_s, [layout](BridgeOptions& o) {
    o.gimbal_mode_layout = o.sd_card_layout = o.interval_layout = layout;
  });
}

TEST(SkyportBridgeLayouts, GimbalStateModeFollowsTheChosenNumbering) {
  for (const auto& [layout, code] :
       {std::pair{PsdkLayout::kDjiHeaders, 2},   // headers: yaw follow 2
        std::pair{PsdkLayout::kDocument, 1}}) {  // 3.5.1: following 1
    Rig rig = rig_with(layout);
    AckResult raw;
    rig.ask(GetGimbalState{}, &raw);
    ASSERT_TRUE(raw.received);
    ASSERT_GE(raw.data.size, 2u);
    EXPECT_EQ(raw.data.bytes[1], code) << to_string(layout);
  }
}

TEST(SkyportBridgeLayouts, AHealthyCardReadsHealthyInEitherLayout) {
  for (const auto& [layout, word] : {// headers: bit 0 inserted (no "formatted" bit)
                                     std::pair{PsdkLayout::kDjiHeaders, 0x0001},
                                     // 3.4.9: bit 0 inserted + bit 3 formatted
                                     std::pair{PsdkLayout::kDocument, 0x0009}}) {
    Rig rig = rig_with(layout);
    rig.pod.set_sd(0, 1000, 600);  // CameraStatus SD_OK
    AckResult raw;
    rig.ask(GetSdCardInfo{}, &raw);
    ASSERT_TRUE(raw.received);
    ASSERT_GE(raw.data.size, 11u);
    EXPECT_EQ(raw.data.bytes[1] | raw.data.bytes[2] << 8, word) << to_string(layout);
    // total 1000 MB = 0x03E8, free 600 MB = 0x0258, little-endian uint32.
    EXPECT_EQ(std::vector<uint8_t>(raw.data.bytes.begin() + 3, raw.data.bytes.begin() + 11),
              (std::vector<uint8_t>{0xE8, 0x03, 0x00, 0x00, 0x58, 0x02, 0x00, 0x00}));
  }
}

TEST(SkyportBridgeLayouts, IntervalWidthFollowsTheChosenLayout) {
  for (const auto& [layout, bytes] :
       {// headers: code, type 6, burst 0, count 255, interval uint16 30 s
        std::pair{PsdkLayout::kDjiHeaders,
                  std::vector<uint8_t>{0x00, 0x06, 0x00, 0xFF, 0x1E, 0x00}},
        // 3.4.6: the same with a uint8 interval
        std::pair{PsdkLayout::kDocument, std::vector<uint8_t>{0x00, 0x06, 0x00, 0xFF, 0x1E}}}) {
    Rig rig = rig_with(layout);
    rig.pod.set_timelapse(30);
    const AckResult raw = rig.adapter->session().request_raw(GetShootPhotoMode::key(), nullptr, 0);
    ASSERT_TRUE(raw.received);
    EXPECT_EQ(std::vector<uint8_t>(raw.data.bytes.begin(), raw.data.bytes.begin() + raw.data.size),
              bytes)
        << to_string(layout);
  }
  // A set is read by its length whatever the layout: 5 bytes (headers), interval 0x003C = 60 s.
  Rig rig = rig_with(PsdkLayout::kDocument);
  EXPECT_EQ(rig.code_of(SetShootPhotoMode::key(), {0x06, 0x00, 0xFF, 0x3C, 0x00}), 0x00);
  EXPECT_TRUE(has_call(rig.pod, "photo mode 2 60 3"));
  // 300 s (0x012C) is not one of the pod's intervals: refused, not read as 44 s.
  EXPECT_EQ(rig.code_of(SetShootPhotoMode::key(), {0x06, 0x00, 0xFF, 0x2C, 0x01}), 0x01);
}

}  // namespace
}  // namespace k40t::driver::skyport
