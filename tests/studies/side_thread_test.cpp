// The study's side thread: a task runs on another thread, the same one for every task of a
// caller (its thread_local buffers stay warm), a task runs whether the side thread is awake
// or asleep when it comes, after a study's last task it sleeps at once, its exception
// reaches get(), and a task is finished before its SideTask goes out of scope.
#include "studies/side_thread.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

#include <time.h>

namespace armstudy::studies {
namespace {

TEST(SideThread, TasksOfOneCallerRunOnOneOtherThread) {
  SideTask<std::thread::id> a([] { return std::this_thread::get_id(); });
  SideTask<std::thread::id> b([] { return std::this_thread::get_id(); });
  const std::thread::id ia = a.get(), ib = b.get();
  EXPECT_NE(ia, std::this_thread::get_id());
  EXPECT_EQ(ia, ib);
}

TEST(SideThread, ATaskPostedAfterTheSideThreadHasGoneToSleepRuns) {
  // a task within kSpinMicroseconds of the last finds the side thread awake; one long after
  // wakes it
  SideTask<int> a([] { return 1; });
  EXPECT_EQ(a.get(), 1);
  SideTask<int> b([] { return 2; });
  EXPECT_EQ(b.get(), 2);
  std::this_thread::sleep_for(std::chrono::microseconds(20 * kSpinMicroseconds));
  SideTask<int> c([] { return 3; });
  EXPECT_EQ(c.get(), 3);
}

// the side thread's own CPU time (s)
double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

TEST(SideThread, AfterALastTaskTheSideThreadSleepsInsteadOfWaitingAwake) {
  // after a task posted with AfterTask::kSleep the side thread does not spin for the next
  // one (kSpinMicroseconds of a core otherwise): between the end of that task and the next
  // task, 10 spins' time later, it spends well under one spin's CPU time; the next task runs
  SideTask<double> last(thread_cpu_seconds, AfterTask::kSleep);
  const double at_end = last.get();
  std::this_thread::sleep_for(std::chrono::microseconds(10 * kSpinMicroseconds));
  SideTask<double> next(thread_cpu_seconds);
  const double at_next = next.get();
  EXPECT_LT(at_next - at_end, 0.5e-6 * kSpinMicroseconds);
}

TEST(SideThread, TheTasksExceptionReachesGet) {
  SideTask<int> t([]() -> int { throw std::runtime_error("side failure"); });
  EXPECT_THROW(t.get(), std::runtime_error);
}

TEST(SideThread, ATaskIsDoneBeforeItsSideTaskGoesOutOfScope) {
  std::atomic<bool> done{false};
  {
    SideTask<int> t([&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      done = true;
      return 1;
    });
  }
  EXPECT_TRUE(done.load());
}

}  // namespace
}  // namespace armstudy::studies
