#include "studies/side_thread.hpp"

#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>

namespace armstudy::studies {
namespace {
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
  void post(std::function<void()> task) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      tasks_.push_back(std::move(task));
    }
    wake_.notify_one();
  }

 private:
  void run() {
    for (;;) {
      std::function<void()> task;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, [this] { return stop_ || !tasks_.empty(); });
        if (tasks_.empty()) return;
        task = std::move(tasks_.front());
        tasks_.pop_front();
      }
      task();  // (a packaged_task: its exception goes to its future)
    }
  }
  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> tasks_;
  bool stop_ = false;
  std::thread thread_;  // (last: started once the members it reads exist)
};
}  // namespace

void post_to_side_thread(std::function<void()> task) {
  thread_local SideThread side;
  side.post(std::move(task));
}

}  // namespace armstudy::studies
