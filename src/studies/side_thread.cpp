// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/side_thread.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>

namespace armstudy::studies {
namespace {
thread_local int awake_waits = 0;  // (a side thread's: SideThread::run counts)

class SideThread {
 public:
  SideThread() : thread_([this] { run(); }) {}
  ~SideThread() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_one();
    thread_.join();  // (after the tasks already posted)
  }
  void post(std::function<void()> task, AfterTask after) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      tasks_.push_back({std::move(task), after});
      posted_.fetch_add(1, std::memory_order_release);
    }
    wake_.notify_one();
  }

 private:
  void run() {
    AfterTask after = AfterTask::kSleep;
    for (;;) {
      Task task;
      // a study posts its next task a fraction of a millisecond after the last one ended:
      // waiting for it awake saves the wake-up of a sleeping thread (measured 0.04-0.06 ms
      // on this project's 2-core VM, a tenth of the time-optimal study's halved-grid solve);
      // after a study's last task it would only burn a core
      if (after == AfterTask::kStayAwake) {
        ++awake_waits;
        spin_until([this] { return posted_.load(std::memory_order_acquire) != taken_; });
      }
      {
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, [this] { return stop_ || !tasks_.empty(); });
        if (tasks_.empty()) return;
        task = std::move(tasks_.front());
        tasks_.pop_front();
        ++taken_;
      }
      task.run();  // (a packaged_task: its exception goes to its future)
      after = task.after;
    }
  }
  std::mutex mutex_;
  std::condition_variable wake_;
  struct Task {
    std::function<void()> run;
    AfterTask after = AfterTask::kStayAwake;
  };
  std::deque<Task> tasks_;
  bool stop_ = false;
  std::atomic<unsigned> posted_{0};  // tasks posted so far
  unsigned taken_ = 0;               // tasks taken so far (this thread's alone)
  std::thread thread_;               // (last: started once the members it reads exist)
};
}  // namespace

void spin_until(const std::function<bool()>& done) {
  using clock = std::chrono::steady_clock;
  const auto end = clock::now() + std::chrono::microseconds(kSpinMicroseconds);
  for (int k = 0; !done(); ++k) {
    if (k % 64 == 63 && clock::now() > end) return;
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
  }
}

int side_thread_awake_waits() { return awake_waits; }

void post_to_side_thread(std::function<void()> task, AfterTask after) {
  thread_local SideThread side;
  side.post(std::move(task), after);
}

}  // namespace armstudy::studies
