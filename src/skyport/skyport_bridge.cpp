#include "k40t_driver/skyport/skyport_bridge.h"

#include "k40t_driver/psdk/identity.h"
#include "k40t_driver/skyport/ack_reply.h"

namespace k40t::driver::skyport {

using namespace psdk;
using detail::refused;
using detail::reply_data;

SkyportBridge::SkyportBridge(Session& session, PodPort& pod, BridgeOptions options,
                             BatteryObserver battery, Log log)
    : session_(session),
      pod_(pod),
      options_(std::move(options)),
      battery_(std::move(battery)),
      log_(std::move(log)),
      photo_progress_(std::chrono::duration_cast<PhotoProgress::Clock::duration>(
          std::chrono::duration<double>(options_.photo_storing_s))),
      jobs_(options_.max_queued_jobs) {
  register_payload_state();
  register_camera();
  register_camera_lens();
  register_gimbal();
  register_battery();
  register_widgets();
}

SkyportBridge::~SkyportBridge() {
  jobs_.stop();  // joins the worker, which may still be calling the pod
}

BridgeStats SkyportBridge::stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  BridgeStats out = stats_;
  out.queued_jobs = jobs_.depth();
  return out;
}

bool SkyportBridge::queue(std::function<void()> job) {
  if (jobs_.push(std::move(job))) return true;
  std::lock_guard<std::mutex> lock(mutex_);
  ++stats_.busy_answers;
  return false;
}

AckCode SkyportBridge::invalid(const std::string& why) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ++stats_.invalid_commands;
  }
  if (log_) log_("SKYPORT command refused: " + why);
  return AckCode::kError;
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

namespace {
// Cmd answered with an ACK whose one field is `value`, fixed by the options.
template <class Cmd, class Field, class V>
void answer_with(Session& session, Field field, const V& value) {
  session.handle<Cmd>([field, value](const Cmd&) {
    typename Cmd::Ack ack;
    ack.*field = value;
    return ack;
  });
}
}  // namespace

void SkyportBridge::register_payload_state() {
  session_.handle<IdentityVerification>([this](const IdentityVerification& c) {
    IdentityVerificationAck ack = answer_identity_verification(options_.app_key, c);
    std::lock_guard<std::mutex> lock(mutex_);
    ++stats_.identity_requests;
    if (ack.code != AckCode::kOk) ++stats_.identity_refused;
    return ack;
  });
  answer_with<GetPsdkVersion>(session_, &PsdkVersionAck::version, options_.firmware);
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
  answer_with<GetProductAlias>(session_, &ProductAliasAck::alias, options_.alias);
  answer_with<GetSkyportVersion>(session_, &SkyportVersionAck::version, options_.skyport_version);
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
        // Stop the pod's recording (it would lose the file), then say ready. Whether it records
        // unknown (record/status went silent): stop it all the same.
        const bool wants_ack = in.header.ack_request != AckRequest::kNoAck;
        const bool queued = queue([this, wants_ack, header = in.header] {
          const PodSnapshot s = pod_.snapshot();
          bool ready = true;
          if (s.recording || !s.recording_known)
            ready = pod_code(pod_.record(false), "stop recording") == AckCode::kOk;
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
          if (wants_ack) session_.send_ack(header, reply_data(ack));
        });
        if (!queued) {  // busy: not ready yet, the next push tries again
          std::lock_guard<std::mutex> lock(mutex_);
          power_off_job_pending_ = false;
          return reply_data(BatteryInfoAck{});
        }
        return std::nullopt;
      });
}

}  // namespace k40t::driver::skyport
