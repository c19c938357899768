// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
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

TEST(SideThread, AfterALastTaskTheSideThreadSleepsInsteadOfWaitingAwake) {
  // after a task posted with AfterTask::kSleep the side thread does not wait awake for the
  // next one (kSpinMicroseconds of a core otherwise), after any other task it does; each
  // task reads the side thread's count of its waits awake so far. The next task runs.
  SideTask<int> first(side_thread_awake_waits);
  const int before = first.get();
  SideTask<int> last(side_thread_awake_waits, AfterTask::kSleep);
  const int at_last = last.get();
  EXPECT_EQ(at_last, before + 1);  // (it waited awake after `first`)
  std::this_thread::sleep_for(std::chrono::microseconds(10 * kSpinMicroseconds));
  SideTask<int> next(side_thread_awake_waits);
  EXPECT_EQ(next.get(), at_last);  // (it did not after `last`)
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
