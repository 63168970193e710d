#include "k40t_driver/video/stall_guard.h"

#include <gst/gst.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "k40t_driver/transport/thread_name.h"

namespace k40t::video {

namespace {

using Clock = std::chrono::steady_clock;

// The element's instance: GObject wants a C struct whose first member is the parent instance.
// The C++ state lives behind a pointer created in init and deleted in finalize.
struct Watch {
  std::mutex mutex;
  std::condition_variable wake;
  bool running = false;  // the thread should keep going
  bool armed = false;    // PLAYING: a silence longer than the timeout ends the stream
  Clock::time_point last_activity;
  std::thread thread;
};

struct StallGuard {
  GstElement parent;
  GstPad* sinkpad;
  GstPad* srcpad;
  std::atomic<gint64> timeout_ms;
  std::atomic<bool> ended;  // EOS pushed by us: later buffers are refused
  Watch* watch;
};

struct StallGuardClass {
  GstElementClass parent_class;
};

enum { kPropTimeout = 1 };
constexpr gint64 kDefaultTimeoutMs = 2000;

GType stall_guard_get_type();
#define K40T_STALL_GUARD(obj) \
  (G_TYPE_CHECK_INSTANCE_CAST((obj), stall_guard_get_type(), StallGuard))

G_DEFINE_TYPE(StallGuard, stall_guard, GST_TYPE_ELEMENT)

GstStaticPadTemplate sink_template =
    GST_STATIC_PAD_TEMPLATE("sink", GST_PAD_SINK, GST_PAD_ALWAYS, GST_STATIC_CAPS_ANY);
GstStaticPadTemplate src_template =
    GST_STATIC_PAD_TEMPLATE("src", GST_PAD_SRC, GST_PAD_ALWAYS, GST_STATIC_CAPS_ANY);

void touch(StallGuard* self) {
  std::lock_guard<std::mutex> lock(self->watch->mutex);
  self->watch->last_activity = Clock::now();
}

GstFlowReturn chain(GstPad*, GstObject* parent, GstBuffer* buffer) {
  StallGuard* self = K40T_STALL_GUARD(parent);
  if (self->ended) {
    gst_buffer_unref(buffer);
    return GST_FLOW_EOS;
  }
  touch(self);
  return gst_pad_push(self->srcpad, buffer);
}

// Whether the element is still in a pipeline. A pipeline dropped without going back to NULL
// (OpenCV 4.6 does that when a start fails) unparents its elements as it is disposed; the guard
// then has nobody to tell and its thread ends.
bool in_pipeline(StallGuard* self) {
  GstObject* parent = gst_object_get_parent(GST_OBJECT(self));
  if (!parent) return false;
  gst_object_unref(parent);
  return true;
}

// Pushes EOS downstream once. The reference on the parent keeps the pipeline, and the peers the
// event goes through, alive; the sink pad's stream lock serialises it with the streaming thread.
void end_stream(StallGuard* self) {
  GstObject* parent = gst_object_get_parent(GST_OBJECT(self));
  if (!parent) return;
  GST_PAD_STREAM_LOCK(self->sinkpad);
  if (!self->ended.exchange(true)) {
    GST_ELEMENT_WARNING(self, STREAM, FAILED,
                        ("no video for %" G_GINT64_FORMAT " ms", self->timeout_ms.load()),
                        (nullptr));
    gst_pad_push_event(self->srcpad, gst_event_new_eos());
  }
  GST_PAD_STREAM_UNLOCK(self->sinkpad);
  gst_object_unref(parent);
}

// Runs from PLAYING until the element is back in READY or out of its pipeline; ends the stream
// if it goes quiet while PLAYING. The thread holds a reference on the element, so the element
// outlives it even if a push never returns.
void watch_loop(StallGuard* self) {
  transport::name_this_thread("k40t_vstall");
  constexpr auto kPoll = std::chrono::milliseconds(100);
  Watch* watch = self->watch;
  std::unique_lock<std::mutex> lock(watch->mutex);
  while (watch->running) {
    const auto deadline = watch->last_activity + std::chrono::milliseconds(self->timeout_ms.load());
    const bool due = watch->armed && !self->ended && Clock::now() >= deadline;
    lock.unlock();
    const bool attached = in_pipeline(self);
    if (attached && due) end_stream(self);
    lock.lock();
    if (!attached) break;
    const bool counting = watch->armed && !self->ended;
    const auto poll = Clock::now() + kPoll;
    if (!due) watch->wake.wait_until(lock, counting ? std::min(deadline, poll) : poll);
  }
  watch->running = false;
  lock.unlock();
  gst_object_unref(self);
}

// PAUSED -> PLAYING: (re)arm the timeout from now.
void arm(StallGuard* self) {
  std::lock_guard<std::mutex> lock(self->watch->mutex);
  self->ended = false;
  self->watch->armed = true;
  self->watch->last_activity = Clock::now();
  if (!self->watch->running) {
    self->watch->running = true;
    if (self->watch->thread.joinable()) self->watch->thread.join();
    self->watch->thread = std::thread(watch_loop, K40T_STALL_GUARD(gst_object_ref(self)));
  }
  self->watch->wake.notify_all();
}

// PLAYING -> PAUSED: no EOS from now on (the sinks are pausing; an EOS could wait for preroll).
void disarm(StallGuard* self) {
  std::lock_guard<std::mutex> lock(self->watch->mutex);
  self->watch->armed = false;
}

// PAUSED -> READY: the sinks downstream are already flushing, so a push in progress returns and
// the thread can end.
void stop_watch(StallGuard* self) {
  {
    std::lock_guard<std::mutex> lock(self->watch->mutex);
    self->watch->armed = false;
    self->watch->running = false;
  }
  self->watch->wake.notify_all();
  if (self->watch->thread.joinable()) self->watch->thread.join();
}

GstStateChangeReturn change_state(GstElement* element, GstStateChange transition) {
  StallGuard* self = K40T_STALL_GUARD(element);
  if (transition == GST_STATE_CHANGE_PAUSED_TO_PLAYING) arm(self);
  if (transition == GST_STATE_CHANGE_PLAYING_TO_PAUSED) disarm(self);
  if (transition == GST_STATE_CHANGE_PAUSED_TO_READY) stop_watch(self);
  return GST_ELEMENT_CLASS(stall_guard_parent_class)->change_state(element, transition);
}

void set_property(GObject* object, guint id, const GValue* value, GParamSpec* spec) {
  if (id == kPropTimeout) {
    K40T_STALL_GUARD(object)->timeout_ms = g_value_get_int64(value);
  } else {
    G_OBJECT_WARN_INVALID_PROPERTY_ID(object, id, spec);
  }
}

void get_property(GObject* object, guint id, GValue* value, GParamSpec* spec) {
  if (id == kPropTimeout) {
    g_value_set_int64(value, K40T_STALL_GUARD(object)->timeout_ms);
  } else {
    G_OBJECT_WARN_INVALID_PROPERTY_ID(object, id, spec);
  }
}

void finalize(GObject* object) {
  StallGuard* self = K40T_STALL_GUARD(object);
  // The thread held a reference until its last line, so it is finished or finishing; if its own
  // unref is what finalizes the element, it cannot join itself.
  std::thread& thread = self->watch->thread;
  if (thread.joinable()) {
    if (thread.get_id() == std::this_thread::get_id()) {
      thread.detach();
    } else {
      thread.join();
    }
  }
  delete self->watch;
  G_OBJECT_CLASS(stall_guard_parent_class)->finalize(object);
}

void stall_guard_class_init(StallGuardClass* klass) {
  GObjectClass* object_class = G_OBJECT_CLASS(klass);
  object_class->set_property = set_property;
  object_class->get_property = get_property;
  object_class->finalize = finalize;
  g_object_class_install_property(
      object_class, kPropTimeout,
      g_param_spec_int64("timeout", "Timeout", "Milliseconds without a buffer before EOS", 1,
                         G_MAXINT64, kDefaultTimeoutMs,
                         static_cast<GParamFlags>(G_PARAM_READWRITE | G_PARAM_STATIC_STRINGS)));
  GstElementClass* element_class = GST_ELEMENT_CLASS(klass);
  element_class->change_state = change_state;
  gst_element_class_add_static_pad_template(element_class, &sink_template);
  gst_element_class_add_static_pad_template(element_class, &src_template);
  gst_element_class_set_static_metadata(element_class, "k40t stall guard", "Generic",
                                        "Pushes EOS when no buffer arrives within a timeout",
                                        "k40t_driver");
}

void stall_guard_init(StallGuard* self) {
  self->watch = new Watch();
  self->timeout_ms = kDefaultTimeoutMs;
  self->ended = false;
  self->sinkpad = gst_pad_new_from_static_template(&sink_template, "sink");
  gst_pad_set_chain_function(self->sinkpad, chain);
  GST_PAD_SET_PROXY_CAPS(self->sinkpad);
  GST_PAD_SET_PROXY_ALLOCATION(self->sinkpad);
  gst_element_add_pad(GST_ELEMENT(self), self->sinkpad);
  self->srcpad = gst_pad_new_from_static_template(&src_template, "src");
  GST_PAD_SET_PROXY_CAPS(self->srcpad);
  gst_element_add_pad(GST_ELEMENT(self), self->srcpad);
}

}  // namespace

Status register_stall_guard() {
  static std::once_flag once;
  static bool registered = false;
  std::call_once(once, [] {
    if (!gst_is_initialized()) gst_init(nullptr, nullptr);
    registered =
        gst_element_register(nullptr, kStallGuardElement, GST_RANK_NONE, stall_guard_get_type());
  });
  if (!registered)
    return Status::fail(std::string("cannot register GStreamer element ") + kStallGuardElement);
  return Status::ok();
}

}  // namespace k40t::video
