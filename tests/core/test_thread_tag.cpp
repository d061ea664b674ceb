// The thread tag (core/thread_tag.hpp) is what the crash guard names a crashing thread's building
// by: tasks wrapped by with_thread_tag carry their creator's tag to whichever thread runs them,
// and a thread's own tag comes back after.
#include "core/thread_tag.hpp"

#include <gtest/gtest.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <string>
#include <thread>

namespace mc {
namespace {

TEST(ThreadTag, ScopesNestAndRestore) {
  EXPECT_EQ(thread_tag(), nullptr);
  {
    const ThreadTagScope a("building A");
    EXPECT_STREQ(thread_tag(), "building A");
    {
      const ThreadTagScope b("building B");
      EXPECT_STREQ(thread_tag(), "building B");
    }
    EXPECT_STREQ(thread_tag(), "building A");
  }
  EXPECT_EQ(thread_tag(), nullptr);
}

TEST(ThreadTag, TasksOnOtherThreadsCarryTheirCreatorsTag) {
  tbb::task_arena arena(2);
  const std::thread::id caller = std::this_thread::get_id();
  std::mutex m;
  std::set<std::string> seen_elsewhere, seen_here;
  std::atomic<int> untagged{0};
  arena.execute([&] {
    const ThreadTagScope tag("NL.IMBAG.Pand.0503100000019275");
    tbb::parallel_for(0, 200, 1, with_thread_tag([&](int) {
                        std::this_thread::sleep_for(std::chrono::microseconds(200));  // lets the worker join
                        const char* t = thread_tag();
                        if (!t) {
                          ++untagged;
                          return;
                        }
                        const std::lock_guard lock(m);
                        (std::this_thread::get_id() == caller ? seen_here : seen_elsewhere).insert(t);
                      }));
  });
  EXPECT_EQ(untagged.load(), 0);
  EXPECT_EQ(seen_here, std::set<std::string>{"NL.IMBAG.Pand.0503100000019275"});
  EXPECT_EQ(seen_elsewhere, std::set<std::string>{"NL.IMBAG.Pand.0503100000019275"});  // a worker ran some
  EXPECT_EQ(thread_tag(), nullptr);
}

}  // namespace
}  // namespace mc
