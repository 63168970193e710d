// Names threads, so that `top -H`, perf and gdb show which of them spends (otherwise every thread
// carries the program's name). The kernel keeps at most 15 characters; a longer name does not
// compile. A thread created while a name is set inherits it, which is how threads created inside a
// library (roscpp's, the ROS spinner's, actionlib's goal threads) get one: ThreadNameScope around
// their creation.
#pragma once

#include <pthread.h>

#include <cstddef>

namespace k40t::transport {

template <size_t N>
void name_this_thread(const char (&name)[N]) {
  static_assert(N <= 16, "a thread name has at most 15 characters");
  pthread_setname_np(pthread_self(), name);
}

// The calling thread's name now, to give back later: main() saves the program's name before naming
// the threads it creates and takes it back, since the main thread's name is the process name
// that ps, pkill and the device lock's "in use by pid N (NAME)" show.
class SavedThreadName {
 public:
  SavedThreadName() { pthread_getname_np(pthread_self(), name_, sizeof name_); }
  void restore() const { pthread_setname_np(pthread_self(), name_); }

 private:
  char name_[16] = {};
};

// Names the calling thread for its lifetime and gives it its previous name back.
class ThreadNameScope {
 public:
  template <size_t N>
  explicit ThreadNameScope(const char (&name)[N]) {
    pthread_getname_np(pthread_self(), previous_, sizeof previous_);
    name_this_thread(name);
  }
  ~ThreadNameScope() { pthread_setname_np(pthread_self(), previous_); }
  ThreadNameScope(const ThreadNameScope&) = delete;
  ThreadNameScope& operator=(const ThreadNameScope&) = delete;

 private:
  char previous_[16] = {};
};

}  // namespace k40t::transport
