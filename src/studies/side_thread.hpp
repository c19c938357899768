// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// A second thread for work a study can do beside its own: the calling thread's helper,
/// started on its first task and kept (with its thread_local buffers warm) until the
/// calling thread ends. A fresh std::thread per task would start with cold buffers and a
/// new allocation arena: measured ~0.6 ms more for the halved-grid solve of the
/// time-optimal study, two thirds of the work itself.

#include <atomic>
#include <functional>
#include <future>
#include <memory>
#include <utility>

namespace armstudy::studies {

/// What the side thread does once a task has run: wait awake for the next one for up to
/// kSpinMicroseconds (a study about to post another), or sleep at once (its last task: a
/// wait awake would only burn a core until the next study).
enum class AfterTask { kStayAwake, kSleep };

/// Runs `task` on the calling thread's helper, after the tasks posted before it.
void post_to_side_thread(std::function<void()> task, AfterTask after = AfterTask::kStayAwake);

/// How long a thread waiting for the other stays awake, checking, before it sleeps.
inline constexpr int kSpinMicroseconds = 200;
/// Returns once `done()` is true, or after kSpinMicroseconds.
void spin_until(const std::function<bool()>& done);

/// How many times the calling thread, a side thread, has waited awake for a task so far
/// (0 on any other thread): read inside a task, it tells whether the side thread waited
/// awake after the task before (AfterTask).
int side_thread_awake_waits();

/// A value computed on the side thread. It is waited for when read and when it goes out of
/// scope (so a task may refer to the caller's locals declared before it); an exception of
/// the task is rethrown by get(). A task must not wait for another side task.
template <class T>
class SideTask {
 public:
  SideTask() = default;
  template <class F>
  explicit SideTask(F f, AfterTask after = AfterTask::kStayAwake)
      : done_(std::make_shared<std::atomic<bool>>(false)) {
    auto task = std::make_shared<std::packaged_task<T()>>(std::move(f));
    result_ = task->get_future();
    post_to_side_thread(
        [task, done = done_] {
          (*task)();
          done->store(true, std::memory_order_release);
        },
        after);
  }
  SideTask(SideTask&&) noexcept = default;
  SideTask& operator=(SideTask&& other) noexcept {
    wait();
    result_ = std::move(other.result_);
    done_ = std::move(other.done_);
    return *this;
  }
  SideTask(const SideTask&) = delete;
  SideTask& operator=(const SideTask&) = delete;
  ~SideTask() { wait(); }

  bool valid() const { return result_.valid(); }
  void wait() const {
    if (!result_.valid()) return;
    spin_until([this] { return done_->load(std::memory_order_acquire); });
    result_.wait();
  }
  T get() {
    wait();
    return result_.get();
  }

 private:
  std::future<T> result_;
  std::shared_ptr<std::atomic<bool>> done_;  // set once the task has run
};

}  // namespace armstudy::studies
