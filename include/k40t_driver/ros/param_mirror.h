// Keeps the parameter server's copy of the published configuration (what dynamic_reconfigure's
// server would write there itself, served_config.h says why it does not): publish() is cheap and
// never waits for the master; the parameters that differ from what was last written are written
// by a callback queued on the node's callback queue (a spinner thread), so a burst of changes costs
// one write of each changed parameter, not one write of all ~50 per change.
#pragma once

#include <mutex>
#include <optional>

#include <dynamic_reconfigure/Config.h>
#include <ros/node_handle.h>

#include "k40t_driver/ros/setting_binding.h"

namespace k40t::driver {

class ParamMirror {
 public:
  explicit ParamMirror(ros::NodeHandle private_nh) : nh_(private_nh) {}
  // A write not yet started is dropped; one under way is waited for.
  ~ParamMirror();
  ParamMirror(const ParamMirror&) = delete;
  ParamMirror& operator=(const ParamMirror&) = delete;

  // `config` is now the published configuration; written to the parameter server shortly.
  void publish(const Config& config);

 private:
  void write_pending();

  ros::NodeHandle nh_;
  std::mutex mutex_;                                    // guards pending_
  std::optional<dynamic_reconfigure::Config> pending_;  // published, not yet written
  std::mutex write_mutex_;               // one write at a time, in the order published
  dynamic_reconfigure::Config written_;  // what the parameter server holds (write_mutex_)
};

}  // namespace k40t::driver
