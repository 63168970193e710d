// One actionlib action over one ROS-free operation (operations/): the thin glue that turns a goal
// into the operation, sends its request, feeds it the status frames (through feed(), called by
// the PodDriver handlers of PodActions) and publishes what its tracker decides: feedback after
// every frame or ACK fed to it, then SUCCEEDED, ABORTED (refused goal with nothing sent, NACK,
// failure state, timeout) or PREEMPTED (cancel; the binding's stop() stops what the pod can stop).
//
// Every action's Result has `success`, `message` and `elapsed`, every Feedback `elapsed`, and a
// Feedback's `status`, where it has one, is the tracker's latest status text; the binding fills
// the rest.
//
// Threads: each server runs its goals on one thread of its own. It is not SimpleActionServer's
// execute thread, which wakes 10 times a second while idle (60 wake-ups a second for the driver's
// six actions, a tenth of its CPU at full telemetry): the server is used in its callback mode,
// whose goal and preempt callbacks wake this thread, which sleeps without a timeout while idle.
// The server is built with autostart=false and started by start(); shutdown() ends a running goal
// at once and joins the thread, so it must run before the PodDriver is stopped.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <type_traits>
#include <utility>

#include <actionlib/server/simple_action_server.h>
#include <ros/node_handle.h>

#include "k40t_driver/operations/shared_operation.h"
#include "k40t_driver/protocol/result.h"
#include "k40t_driver/session/session.h"

namespace k40t::driver {

inline double steady_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

template <class Action, class Op>
class OperationServer {
 public:
  using Goal = typename Action::_action_goal_type::_goal_type;
  using ResultMsg = typename Action::_action_result_type::_result_type;
  using FeedbackMsg = typename Action::_action_feedback_type::_feedback_type;
  using AckHandler = std::function<void(const session::AckResult&)>;

  struct Binding {
    std::function<Result<Op>(const Goal&, double now_s)> create;  // validates; nothing sent
    std::function<void(const Op&, AckHandler)> send;              // the request, asynchronously
    // The operation's figures; either may be empty where the message has no more fields.
    std::function<void(const Op&, FeedbackMsg&)> feedback;
    std::function<void(const Op&, ResultMsg&)> result;
    // Stops the pod on cancel and timeout and says how; empty where the pod cannot stop.
    std::function<std::string()> stop;
  };

  OperationServer(ros::NodeHandle nh, const std::string& name, Binding binding)
      : binding_(std::move(binding)), server_(nh, name, false) {
    // Both run under the server's lock: they only set a flag and wake the goal thread.
    server_.registerGoalCallback([this] {
      {
        std::lock_guard<std::mutex> lock(goal_mutex_);
        goal_pending_ = true;
      }
      goal_wakeup_.notify_one();
    });
    server_.registerPreemptCallback([this] { wake_active(); });
    goal_thread_ = std::thread([this] { serve_goals(); });
  }
  ~OperationServer() { shutdown(); }

  void start() { server_.start(); }
  // Idempotent; ends the running goal (cancelled: the driver is shutting down) and joins the
  // thread.
  void shutdown() {
    if (stopping_.exchange(true)) return;
    {
      std::lock_guard<std::mutex> lock(goal_mutex_);  // no lost wake-up between check and wait
    }
    goal_wakeup_.notify_one();
    wake_active();
    if (goal_thread_.joinable()) goal_thread_.join();
  }

  // Runs f(op) on the running goal's operation, if any (status frames, on the I/O thread).
  template <class F>
  void feed(F&& f) {
    if (auto op = active()) {
      op->update([&](Op& o) {
        f(o);
        return 0;
      });
    }
  }

 private:
  // Whether the action's Feedback has a `status` (the tracker's text goes there).
  template <class Msg, class = void>
  struct HasStatus : std::false_type {};
  template <class Msg>
  struct HasStatus<Msg, std::void_t<decltype(std::declval<Msg&>().status)>> : std::true_type {};
  static constexpr bool kFeedbackHasStatus = HasStatus<FeedbackMsg>::value;

  using Shared = operations::SharedOperation<Op>;

  // The goal thread: sleeps until a goal arrives or shutdown(), then runs the newest goal.
  void serve_goals() {
    for (;;) {
      {
        std::unique_lock<std::mutex> lock(goal_mutex_);
        goal_wakeup_.wait(lock, [this] { return goal_pending_ || stopping_; });
        if (stopping_) return;
        goal_pending_ = false;
      }
      // Only this thread accepts goals, so an available goal stays available until accepted.
      if (!server_.isNewGoalAvailable()) continue;
      const auto goal = server_.acceptNewGoal();
      if (goal) execute(*goal);
    }
  }

  void wake_active() {
    if (auto op = active()) op->update([](Op&) { return 0; });
  }

  std::shared_ptr<Shared> active() const {
    std::lock_guard<std::mutex> lock(active_mutex_);
    return active_;
  }
  void set_active(std::shared_ptr<Shared> op) {
    std::lock_guard<std::mutex> lock(active_mutex_);
    active_ = std::move(op);
  }

  void execute(const Goal& goal) {
    const double start_s = steady_seconds();
    Result<Op> created = binding_.create(goal, start_s);
    if (!created) {
      ResultMsg result;
      result.success = false;
      result.message = created.error();
      server_.setAborted(result, result.message);
      return;
    }
    auto op = std::make_shared<Shared>(std::move(created.value()));
    set_active(op);
    binding_.send(op->read([](const Op& o) { return o; }), [op](const session::AckResult& ack) {
      op->update([&](Op& o) {
        o.tracker().acknowledged(ack.ok(), ack.message);
        return 0;
      });
    });
    run(*op, start_s);
    set_active(nullptr);
  }

  // Publishes feedback on every change until the operation ends, then its result.
  void run(Shared& op, double start_s) {
    using operations::Phase;
    uint64_t seen = 0;
    uint64_t published = 0;
    for (;;) {
      if (stopping_) {
        op.inspect([](Op& o) {
          o.tracker().cancel("the driver is shutting down");
          return 0;
        });
        break;
      }
      if (server_.isPreemptRequested()) {
        const std::string how = server_.isNewGoalAvailable() ? "replaced by a new goal"
                                : binding_.stop              ? binding_.stop()
                                                : "the pod cannot stop it and carries on";
        op.inspect([&](Op& o) {
          o.tracker().cancel(how);
          return 0;
        });
        break;
      }
      const double now_s = steady_seconds();
      const Phase phase = op.inspect([&](Op& o) { return o.tracker().check(now_s); });
      if (phase != Phase::kRunning) break;
      if (seen != published) {  // a status frame, an ACK: whatever fed the operation
        FeedbackMsg feedback;
        op.inspect([&](Op& o) {
          if constexpr (kFeedbackHasStatus) feedback.status = o.tracker().status_text();
          if (binding_.feedback) binding_.feedback(o, feedback);
          return 0;
        });
        feedback.elapsed = now_s - start_s;
        server_.publishFeedback(feedback);
        published = seen;
      }
      seen = op.wait_for_change(seen, std::chrono::milliseconds(100));
    }
    finish(op, start_s);
  }

  void finish(Shared& op, double start_s) {
    using operations::Phase;
    ResultMsg result;
    const Phase phase = op.inspect([&](Op& o) {
      if (binding_.result) binding_.result(o, result);
      result.message = o.tracker().reason();
      return o.tracker().phase();
    });
    if (phase == Phase::kTimedOut && binding_.stop) result.message += "; " + binding_.stop();
    result.success = phase == Phase::kSucceeded;
    result.elapsed = steady_seconds() - start_s;
    if (phase == Phase::kSucceeded) {
      server_.setSucceeded(result, result.message);
    } else if (phase == Phase::kCancelled && !stopping_) {
      server_.setPreempted(result, result.message);
    } else {
      server_.setAborted(result, result.message);
    }
  }

  Binding binding_;
  // Declared before server_: its callbacks use them until the server is destroyed.
  std::atomic<bool> stopping_{false};
  std::mutex goal_mutex_;
  std::condition_variable goal_wakeup_;
  bool goal_pending_ = false;
  mutable std::mutex active_mutex_;
  std::shared_ptr<Shared> active_;
  actionlib::SimpleActionServer<Action> server_;
  std::thread goal_thread_;
};

}  // namespace k40t::driver
