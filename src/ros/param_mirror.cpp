#include "k40t_driver/ros/param_mirror.h"

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include <ros/callback_queue_interface.h>
#include <boost/make_shared.hpp>

namespace k40t::driver {

namespace {

// Writes each parameter of `now` whose value differs from (or is missing in) `before`.
template <class Param>
void write_changed(const ros::NodeHandle& nh, const std::vector<Param>& now,
                   const std::vector<Param>& before) {
  for (const Param& param : now) {
    const auto same = [&](const Param& old) { return old.name == param.name; };
    const auto old = std::find_if(before.begin(), before.end(), same);
    if (old == before.end() || old->value != param.value) nh.setParam(param.name, param.value);
  }
}

class WriteCallback : public ros::CallbackInterface {
 public:
  explicit WriteCallback(std::function<void()> write) : write_(std::move(write)) {}
  CallResult call() override {
    write_();
    return Success;
  }

 private:
  std::function<void()> write_;
};

uint64_t owner_id(const ParamMirror* mirror) {
  return reinterpret_cast<uint64_t>(mirror);
}

}  // namespace

ParamMirror::~ParamMirror() {
  nh_.getCallbackQueue()->removeByID(owner_id(this));
}

void ParamMirror::publish(const Config& config) {
  dynamic_reconfigure::Config message;
  config.__toMessage__(message);
  std::lock_guard<std::mutex> lock(mutex_);
  const bool queued = pending_.has_value();
  pending_ = std::move(message);
  if (queued) return;  // the write already queued takes the latest
  nh_.getCallbackQueue()->addCallback(
      boost::make_shared<WriteCallback>([this] { write_pending(); }), owner_id(this));
}

void ParamMirror::write_pending() {
  std::lock_guard<std::mutex> one_write(write_mutex_);
  dynamic_reconfigure::Config now;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!pending_) return;
    now = std::move(*pending_);
    pending_.reset();
  }
  write_changed(nh_, now.bools, written_.bools);
  write_changed(nh_, now.ints, written_.ints);
  write_changed(nh_, now.strs, written_.strs);
  write_changed(nh_, now.doubles, written_.doubles);
  written_ = std::move(now);
}

}  // namespace k40t::driver
