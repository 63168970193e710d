#include "k40t_driver/ros/skyport/skyport_bridge.h"

#include <algorithm>
#include <cmath>

#include "k40t_driver/psdk/identity.h"
#include "k40t_driver/ros/skyport/ack_reply.h"

namespace k40t::driver::skyport {

using namespace psdk;
using detail::refused;
using detail::reply_data;

namespace {

constexpr double kDegPerRad = 180.0 / M_PI;

// CameraStatus constants (msg/CameraStatus.msg), kept here so the core needs no ROS header.
constexpr uint8_t kPhotoSingle = 0, kPhotoBurst = 1, kPhotoTimelapse = 2;
constexpr uint8_t kSdOk = 0, kSdAbnormal = 1, kSdMissing = 3, kSdFull = 4, kSdFormatError = 5;
// The pod's stream is 1920x1080; a PSDK focus zone point becomes a box around it.
constexpr double kStreamWidth = 1920, kStreamHeight = 1080, kFocusBoxHalf = 100;

uint16_t clamp_px(double v, double hi) {
  return static_cast<uint16_t>(std::lround(std::clamp(v, 0.0, hi)));
}

}  // namespace

SkyportBridge::SkyportBridge(Session& session, PodPort& pod, BridgeOptions options,
                             BatteryObserver battery, Log log)
    : session_(session),
      pod_(pod),
      options_(std::move(options)),
      battery_(std::move(battery)),
      log_(std::move(log)),
      photo_progress_(std::chrono::duration_cast<PhotoProgress::Clock::duration>(
          std::chrono::duration<double>(options_.photo_storing_s))) {
  register_payload_state();
  register_camera();
  register_camera_lens();
  register_gimbal();
  register_battery();
  register_widgets();
  worker_ = std::thread([this] { run_worker(); });
}

SkyportBridge::~SkyportBridge() {
  {
    std::lock_guard<std::mutex> lock(jobs_mutex_);
    stopping_ = true;
  }
  jobs_wake_.notify_all();
  worker_.join();
}

BridgeStats SkyportBridge::stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stats_;
}

void SkyportBridge::run_worker() {
  std::unique_lock<std::mutex> lock(jobs_mutex_);
  while (true) {
    jobs_wake_.wait(lock, [this] { return stopping_ || !jobs_.empty(); });
    if (stopping_) return;
    std::function<void()> job = std::move(jobs_.front());
    jobs_.pop_front();
    lock.unlock();
    job();
    lock.lock();
  }
}

AckCode SkyportBridge::pod_code(const PodCall& call, const char* what) {
  std::lock_guard<std::mutex> lock(mutex_);
  ++stats_.pod_calls;
  if (call.ok) return AckCode::kOk;
  ++stats_.pod_call_failures;
  if (log_) log_(std::string("SKYPORT ") + what + ": the pod refused: " + call.message);
  return AckCode::kError;
}

AckCode SkyportBridge::capture_code(const PodCall& call, const char* what) {
  photo_progress_.capture_answered(call, PhotoProgress::Clock::now());
  return pod_code(call, what);
}

AckCode SkyportBridge::unsupported() {
  std::lock_guard<std::mutex> lock(mutex_);
  ++stats_.unsupported_answers;
  return AckCode::kUnsupported;
}

// --- 0x01 payload state --------------------------------------------------------------------------

void SkyportBridge::register_payload_state() {
  session_.handle<IdentityVerification>([this](const IdentityVerification& c) {
    IdentityVerificationAck ack = answer_identity_verification(options_.app_key, c);
    std::lock_guard<std::mutex> lock(mutex_);
    ++stats_.identity_requests;
    if (ack.code != AckCode::kOk) ++stats_.identity_refused;
    return ack;
  });
  session_.handle<GetPsdkVersion>([this](const GetPsdkVersion&) {
    PsdkVersionAck ack;
    ack.version = options_.firmware;
    return ack;
  });
  session_.handle<Handshake>([](const Handshake& c) {
    HandshakeAck ack;
    ack.data = c.data;
    return ack;
  });
  session_.handle<GetProductInfo>([this](const GetProductInfo&) {
    ProductInfoAck ack;
    ack.product_name = options_.product_name;
    ack.product_id = options_.product_id;
    ack.developer_account = options_.developer_account;
    return ack;
  });
  session_.handle<GetProductAlias>([this](const GetProductAlias&) {
    ProductAliasAck ack;
    ack.alias = options_.alias;
    return ack;
  });
  session_.handle<GetSkyportVersion>([](const GetSkyportVersion&) {
    SkyportVersionAck ack;  // the protocol version this payload was written for: PSDK v1.0
    ack.version = Version{1, 0, 0, 0};
    return ack;
  });
}

// --- 0x04 camera: capture, storage ---------------------------------------------------------------

void SkyportBridge::register_camera() {
  session_.handle<GetCameraCapability>([](const GetCameraCapability&) {
    CameraCapabilityAck ack;
    ack.supported = {true, true, true, true, true};
    return ack;
  });
  deferred<SetCameraWorkMode>([this](const SetCameraWorkMode& c) {
    return pod_code(pod_.set_video_mode(c.mode == CameraWorkMode::kRecordVideo), "work mode");
  });
  deferred<GetCameraWorkMode>([this](const GetCameraWorkMode&) {
    const PodSnapshot s = pod_.snapshot();
    if (!s.have_camera) return refused<CameraWorkModeAck>(AckCode::kError);
    CameraWorkModeAck ack;
    ack.mode = s.video_mode ? CameraWorkMode::kRecordVideo : CameraWorkMode::kShootPhoto;
    return ack;
  });
  deferred<ShootPhoto>([this](const ShootPhoto& c) {
    const bool stop = c.action == ShootPhotoAction::kStop;
    const PodSnapshot before = pod_.snapshot();
    const PodCall call = pod_.take_photo(stop);
    if (stop) return pod_code(call, "stop photo");
    if (!call.ok) return capture_code(call, "shoot photo");
    photo_progress_.started(before, PhotoProgress::Clock::now());
    return pod_code(call, "shoot photo");
  });
  deferred<GetShootPhotoState>([this](const GetShootPhotoState&) {
    // The pod reports no state for single shots: what the bridge saw of it (photo_progress.h).
    const PodSnapshot s = pod_.snapshot();
    if (!s.have_camera) return refused<ShootPhotoStateAck>(AckCode::kError);
    return photo_progress_.state(s, PhotoProgress::Clock::now());
  });
  deferred<SetShootPhotoMode>([this](const SetShootPhotoMode& c) {
    switch (c.type) {
      case ShootPhotoType::kSingle:
        return capture_code(pod_.set_photo_mode(kPhotoSingle, 0, 0), "photo mode");
      case ShootPhotoType::kBurst:
        if (c.burst_count != 3 && c.burst_count != 5) return AckCode::kError;  // pod: 3 or 5
        return capture_code(pod_.set_photo_mode(kPhotoBurst, 0, c.burst_count), "photo mode");
      case ShootPhotoType::kInterval:
        if (c.interval_s != 5 && c.interval_s != 7 && c.interval_s != 30 && c.interval_s != 60)
          return AckCode::kError;  // the pod's time-lapse intervals
        return capture_code(pod_.set_photo_mode(kPhotoTimelapse, c.interval_s, 0), "photo mode");
    }
    return AckCode::kError;
  });
  deferred<GetShootPhotoMode>([this](const GetShootPhotoMode&) {
    const PodSnapshot s = pod_.snapshot();
    if (!s.have_camera) return refused<ShootPhotoModeAck>(AckCode::kError);
    ShootPhotoModeAck ack;
    if (s.photo_mode == kPhotoBurst) {
      ack.type = ShootPhotoType::kBurst;
      ack.burst_count = s.burst_count;
    } else if (s.photo_mode == kPhotoTimelapse) {
      ack.type = ShootPhotoType::kInterval;
      ack.interval_count = kIntervalShootUntilStopped;
      ack.interval_s = s.timelapse_interval_s;
    }
    return ack;
  });
  deferred<RecordVideo>([this](const RecordVideo& c) {
    return capture_code(pod_.record(c.action == RecordAction::kStart), "record");
  });
  deferred<GetRecordState>([this](const GetRecordState&) {
    const PodSnapshot s = pod_.snapshot();
    RecordStateAck ack;
    ack.recording = s.recording;
    ack.duration_s = s.recording ? s.record_duration_s : 0;
    return ack;
  });
  deferred<GetSdCardInfo>([this](const GetSdCardInfo&) {
    const PodSnapshot s = pod_.snapshot();
    if (!s.have_camera) return refused<SdCardInfoAck>(AckCode::kError);
    SdCardInfoAck ack;
    ack.state.inserted = s.sd_state != kSdMissing;
    ack.state.formatted = s.sd_state == kSdOk || s.sd_state == kSdFull;
    ack.state.full = s.sd_state == kSdFull;
    ack.state.invalid_format = s.sd_state == kSdFormatError;
    ack.state.has_error = s.sd_state == kSdAbnormal || s.sd_state == kSdFormatError;
    ack.capacity_mb = static_cast<uint32_t>(std::max(0.0, s.sd_total_mb));
    ack.remaining_mb = static_cast<uint32_t>(std::max(0.0, s.sd_free_mb));
    return ack;  // remaining shots and record time: the pod does not say (0)
  });
  deferred<FormatSdCard>([this](const FormatSdCard&) {
    return refused<FormatSdCardAck>(capture_code(pod_.format_sd(), "format SD card"));
  });
}

// --- 0x04 camera: lens ---------------------------------------------------------------------------

AckCode SkyportBridge::apply_zoom() {
  const double ratio = optical_zoom_ * digital_zoom_;
  if (ratio < 1.0 || ratio > options_.max_hybrid_zoom) return AckCode::kError;
  return pod_code(pod_.set_zoom(ratio), "zoom");
}

void SkyportBridge::register_camera_lens() {
  deferred<SetMeteringMode>([this](const SetMeteringMode& c) {
    // The pod meters centre-weighted (1), by area (2) or average (3): no spot metering.
    if (c.mode == MeteringMode::kSpot) return unsupported();
    const AckCode code =
        pod_code(pod_.set_metering(c.mode == MeteringMode::kCenter ? 1 : 3), "metering");
    if (code == AckCode::kOk) {
      std::lock_guard<std::mutex> lock(mutex_);  // GetMeteringMode reads it on the session thread
      metering_ = c.mode;
    }
    return code;
  });
  session_.handle<GetMeteringMode>([this](const GetMeteringMode&) {
    MeteringModeAck ack;
    std::lock_guard<std::mutex> lock(mutex_);
    ack.mode = metering_;
    return ack;
  });
  deferred<SetFocusMode>([this](const SetFocusMode& c) {
    const bool autofocus = c.mode == FocusMode::kAuto;
    const AckCode code = pod_code(
        pod_.focus(autofocus ? PodFocus::kAuto : PodFocus::kManualStop, 0, 0, 0, 0), "focus mode");
    if (code == AckCode::kOk) {
      std::lock_guard<std::mutex> lock(mutex_);  // GetFocusMode reads it on the session thread
      focus_mode_ = c.mode;
    }
    return code;
  });
  session_.handle<GetFocusMode>([this](const GetFocusMode&) {
    FocusModeAck ack;
    std::lock_guard<std::mutex> lock(mutex_);
    ack.mode = focus_mode_;
    return ack;
  });
  deferred<SetFocusZone>([this](const SetFocusZone& c) {
    const double x = c.x * kStreamWidth, y = c.y * kStreamHeight;
    const AckCode code =
        pod_code(pod_.focus(PodFocus::kArea, clamp_px(x - kFocusBoxHalf, kStreamWidth),
                            clamp_px(y - kFocusBoxHalf, kStreamHeight),
                            clamp_px(x + kFocusBoxHalf, kStreamWidth),
                            clamp_px(y + kFocusBoxHalf, kStreamHeight)),
                 "focus zone");
    if (code == AckCode::kOk) {
      std::lock_guard<std::mutex> lock(mutex_);
      focus_x_ = c.x;
      focus_y_ = c.y;
    }
    return code;
  });
  session_.handle<GetFocusZone>([this](const GetFocusZone&) {
    FocusZoneAck ack;
    std::lock_guard<std::mutex> lock(mutex_);
    ack.x = focus_x_;
    ack.y = focus_y_;
    return ack;
  });
  deferred<SetDigitalZoomFactor>([this](const SetDigitalZoomFactor& c) {
    const double max_digital = options_.max_hybrid_zoom / options_.max_optical_zoom;
    if (!(c.factor_x >= 1.0f) || c.factor_x > max_digital) return AckCode::kError;
    const double before = digital_zoom_;
    digital_zoom_ = c.factor_x;
    const AckCode code = apply_zoom();
    if (code != AckCode::kOk) digital_zoom_ = before;
    return code;
  });
  deferred<GetDigitalZoomFactor>([this](const GetDigitalZoomFactor&) {
    DigitalZoomFactorAck ack;
    ack.factor_x = static_cast<float>(digital_zoom_);
    return ack;
  });
  session_.handle<GetDigitalZoomSpec>([this](const GetDigitalZoomSpec&) {
    DigitalZoomSpecAck ack;
    ack.max_factor_x = static_cast<float>(options_.max_hybrid_zoom / options_.max_optical_zoom);
    return ack;
  });
  session_.handle<GetOpticalZoomSpec>([this](const GetOpticalZoomSpec&) {
    OpticalZoomSpecAck ack;
    ack.min_focal_length_mm = options_.tele_focal_length_mm;
    ack.max_focal_length_mm = options_.tele_focal_length_mm * options_.max_optical_zoom;
    ack.focal_length_step_mm = 0.1;
    return ack;
  });
  deferred<SetOpticalZoomFocalLength>([this](const SetOpticalZoomFocalLength& c) {
    const double optical = c.focal_length_mm / options_.tele_focal_length_mm;
    if (optical < 1.0 - 1e-6 || optical > options_.max_optical_zoom + 1e-6) return AckCode::kError;
    const double before = optical_zoom_;
    optical_zoom_ = std::clamp(optical, 1.0, options_.max_optical_zoom);
    const AckCode code = apply_zoom();
    if (code != AckCode::kOk) optical_zoom_ = before;
    return code;
  });
  deferred<GetOpticalZoomFocalLength>([this](const GetOpticalZoomFocalLength&) {
    const PodSnapshot s = pod_.snapshot();
    OpticalZoomFocalLengthAck ack;
    ack.focal_length_mm = s.have_visible && s.focal_length_mm > 0
                              ? s.focal_length_mm
                              : options_.tele_focal_length_mm * optical_zoom_;
    return ack;
  });
  deferred<GetOpticalZoomFactor>([this](const GetOpticalZoomFactor&) {
    const PodSnapshot s = pod_.snapshot();
    if (!s.have_visible) return refused<OpticalZoomFactorAck>(AckCode::kError);
    OpticalZoomFactorAck ack;
    ack.factor_x = static_cast<float>(std::min(s.zoom_ratio, options_.max_optical_zoom));
    return ack;
  });
  deferred<StartContinuousZoom>([this](const StartContinuousZoom& c) {
    return pod_code(pod_.zoom(c.direction == ZoomDirection::kIn ? PodZoom::kIn : PodZoom::kOut),
                    "continuous zoom");
  });
  deferred<StopContinuousZoom>(
      [this](const StopContinuousZoom&) { return pod_code(pod_.zoom(PodZoom::kStop), "zoom"); });
  // The pod has no focus ring position and no focus assistant.
  session_.handle<SetFocusAssistant>([this](const SetFocusAssistant&) { return unsupported(); });
  session_.handle<GetFocusAssistant>(
      [this](const GetFocusAssistant&) { return refused<FocusAssistantAck>(unsupported()); });
  session_.handle<GetFocusRingUpperBound>([this](const GetFocusRingUpperBound&) {
    return refused<FocusRingUpperBoundAck>(unsupported());
  });
  session_.handle<SetFocusRing>([this](const SetFocusRing&) { return unsupported(); });
  session_.handle<GetFocusRing>(
      [this](const GetFocusRing&) { return refused<FocusRingAck>(unsupported()); });
  session_.handle<SetSpotMeteringZone>(
      [this](const SetSpotMeteringZone&) { return unsupported(); });
  session_.handle<GetSpotMeteringZone>(
      [this](const GetSpotMeteringZone&) { return refused<SpotMeteringZoneAck>(unsupported()); });
}

// --- 0x05 gimbal ---------------------------------------------------------------------------------

void SkyportBridge::register_gimbal() {
  // The pod's yaw is a joint angle relative to the aircraft: it follows the aircraft's heading,
  // PSDK's "following" mode, the only one it has.
  session_.handle<GetGimbalCapability>([](const GetGimbalCapability&) {
    GimbalCapabilityAck ack;
    ack.supported = true;
    return ack;
  });
  session_.handle<GetGimbalState>([this](const GetGimbalState&) {
    const PodSnapshot s = pod_.snapshot();
    if (!s.have_joints) return refused<GimbalStateAck>(AckCode::kError);
    GimbalStateAck ack;
    ack.mode = GimbalStateMode::kFollowing;
    // DJI signs: pitch up, yaw right (clockwise from above), roll right side down positive.
    ack.angles.pitch_deg = -s.pitch_rad * kDegPerRad;
    ack.angles.yaw_deg = -s.yaw_rad * kDegPerRad;
    ack.angles.roll_deg = s.roll_rad * kDegPerRad;
    return ack;
  });
  session_.handle<SetGimbalMode>([this](const SetGimbalMode& c) {
    return c.mode == GimbalMode::kFollowing ? AckCode::kOk : unsupported();
  });
  deferred<GimbalReturnHead>(
      [this](const GimbalReturnHead&) { return pod_code(pod_.center(), "return head"); });
  deferred<ControlGimbalSpeed>([this](const ControlGimbalSpeed& c) {
    if (c.action == GimbalControlAction::kStop) return pod_code(pod_.set_rate(0, 0), "speed");
    return pod_code(pod_.set_rate(-c.pitch_rate_deg_s / kDegPerRad, -c.yaw_rate_deg_s / kDegPerRad),
                    "gimbal speed");
  });
  const auto angle = [this](double pitch_deg, double roll_deg, double yaw_deg) {
    if (std::fabs(roll_deg) > 0.5) return AckCode::kError;  // the pod's roll only stabilises
    return pod_code(pod_.set_angle(-pitch_deg / kDegPerRad, -yaw_deg / kDegPerRad), "angle");
  };
  deferred<ControlGimbalAngle>(
      [angle](const ControlGimbalAngle& c) { return angle(c.pitch_deg, c.roll_deg, c.yaw_deg); });
  deferred<ControlGimbalJointAngle>([angle](const ControlGimbalJointAngle& c) {
    return angle(c.angles.pitch_deg, c.angles.roll_deg, c.angles.yaw_deg);
  });
  deferred<CalibrateGimbal>([this](const CalibrateGimbal&) {
    const AckCode code = pod_code(pod_.calibrate(), "calibration");
    std::lock_guard<std::mutex> lock(mutex_);
    calibrated_ = calibrated_ || code == AckCode::kOk;
    return code;
  });
  session_.handle<GetCalibrationProgress>([this](const GetCalibrationProgress&) {
    // The pod reports no progress: its one-key calibration counts as done once acknowledged.
    CalibrationProgressAck ack;
    std::lock_guard<std::mutex> lock(mutex_);
    ack.progress_percent = calibrated_ ? 100 : 0;
    ack.status = CalibrationStatus::kComplete;
    return ack;
  });
  session_.handle<GetGimbalAdditionalStatus>([this](const GetGimbalAdditionalStatus&) {
    const PodSnapshot s = pod_.snapshot();
    if (!s.have_joints) return refused<GimbalAdditionalStatusAck>(AckCode::kError);
    GimbalAdditionalStatusAck ack;
    ack.pitch_rate_deg_s = -s.pitch_rate_rad_s * kDegPerRad;
    ack.yaw_rate_deg_s = -s.yaw_rate_rad_s * kDegPerRad;
    ack.roll_rate_deg_s = s.roll_rate_rad_s * kDegPerRad;
    return ack;
  });
}

// --- 0x03/0x03 battery and the power-off hand-shake ----------------------------------------------

void SkyportBridge::register_battery() {
  session_.on_command(
      BatteryInfoPush::key(), [this](const IncomingCommand& in) -> std::optional<Data> {
        const Result<BatteryInfoPush> push = decode_data<BatteryInfoPush>(in.data);
        if (!push) return reply_data(AckCode::kError);
        if (battery_) battery_(push.value());
        {
          std::lock_guard<std::mutex> lock(mutex_);
          ++stats_.battery_pushes;
          stats_.power_off_announced = push->power_off_soon;
          // A withdrawn announcement ends the episode: the next one must stop recording again.
          if (!push->power_off_soon) stats_.power_off_ready = false;
          // Power-off state 0: the ACK's content is ignored (3.3.3). Announced: "ready" once the
          // pod is prepared; while that preparation runs (or failed and is to be retried), not
          // ready.
          if (!push->power_off_soon || stats_.power_off_ready || power_off_job_pending_) {
            BatteryInfoAck ack;
            ack.power_off_ready = push->power_off_soon && stats_.power_off_ready;
            return reply_data(ack);
          }
          power_off_job_pending_ = true;
        }
        // Stop the pod's recording (it would lose the file), then say ready.
        {
          std::lock_guard<std::mutex> lock(jobs_mutex_);
          jobs_.push_back([this, header = in.header] {
            const PodSnapshot s = pod_.snapshot();
            bool ready = true;
            if (s.recording) ready = pod_code(pod_.record(false), "stop recording") == AckCode::kOk;
            {
              std::lock_guard<std::mutex> lock(mutex_);
              // Withdrawn meanwhile: this preparation does not count for a later announcement.
              stats_.power_off_ready = ready && stats_.power_off_announced;
              power_off_job_pending_ = false;
            }
            if (log_)
              log_(ready ? "SKYPORT power-off announced: recording stopped, ready"
                         : "SKYPORT power-off announced: could not stop recording");
            BatteryInfoAck ack;
            ack.power_off_ready = ready;
            session_.send_ack(header, reply_data(ack));
          });
        }
        jobs_wake_.notify_one();
        return std::nullopt;
      });
}

}  // namespace k40t::driver::skyport
