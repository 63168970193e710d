// Threads carry names (transport/thread_name.h) so that `top -H` shows which one spends: a
// session's I/O thread is "k40t_io" and its timeout thread "k40t_sess" (issue 24); a
// ThreadNameScope gives the thread its previous name back.
#include <gtest/gtest.h>

#include <pthread.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "k40t_driver/transport/thread_name.h"
#include "session_test_link.h"
#include "transport_test_support.h"

namespace k40t::test {
namespace {

// The names of this process's threads, as `top -H` reads them.
std::multiset<std::string> thread_names() {
  std::multiset<std::string> names;
  for (const auto& task : std::filesystem::directory_iterator("/proc/self/task")) {
    std::ifstream comm(task.path() / "comm");
    std::string name;
    if (std::getline(comm, name)) names.insert(name);
  }
  return names;
}

std::string this_thread_name() {
  char name[16] = {};
  pthread_getname_np(pthread_self(), name, sizeof name);
  return name;
}

TEST(ThreadNames, ASessionsThreadsAreNamed) {
  EXPECT_EQ(thread_names().count("k40t_io"), 0u);
  transport::testing::ScratchDir dir;
  Result<std::unique_ptr<transport::Transport>> link =
      transport::make_transport("pty://" + dir.file("pod"));
  ASSERT_TRUE(link) << link.error();
  session::Session session(std::move(link.value()), pod_options());
  ASSERT_TRUE(session.start());
  EXPECT_TRUE(transport::testing::eventually([] {
    const auto names = thread_names();
    return names.count("k40t_io") == 1 && names.count("k40t_sess") == 1;
  }));
  session.stop();
}

TEST(ThreadNames, AScopeNamesTheThreadAndGivesItsNameBack) {
  transport::name_this_thread("k40t_test");
  {
    const transport::ThreadNameScope scope("k40t_scoped");
    EXPECT_EQ(this_thread_name(), "k40t_scoped");
  }
  EXPECT_EQ(this_thread_name(), "k40t_test");
}

}  // namespace
}  // namespace k40t::test
