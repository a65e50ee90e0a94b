#include "rtamp/sim/helper_thread.hpp"

#include <cassert>

namespace rtamp::sim {

HelperThread::HelperThread() : thread_([this] { loop(); }) {}

HelperThread::~HelperThread() {
  {
    std::unique_lock lock(mutex_);
    done_.wait(lock, [this] { return !busy_; });
    stop_ = true;
  }
  wake_.notify_one();
  thread_.join();
}

void HelperThread::start(void (*fn)(void*) noexcept, void* arg) {
  {
    const std::lock_guard lock(mutex_);
    assert(!busy_);
    fn_ = fn, arg_ = arg, busy_ = true;
  }
  wake_.notify_one();
}

void HelperThread::wait() {
  std::unique_lock lock(mutex_);
  done_.wait(lock, [this] { return !busy_; });
}

void HelperThread::loop() {
  std::unique_lock lock(mutex_);
  for (;;) {
    wake_.wait(lock, [this] { return busy_ || stop_; });
    if (busy_) {
      lock.unlock();
      fn_(arg_);
      lock.lock();
      busy_ = false;
      done_.notify_all();
      continue;
    }
    return;  // stop_, nothing to do
  }
}

}  // namespace rtamp::sim
