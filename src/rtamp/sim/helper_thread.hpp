// A second thread for work that one frame can split in two: run(job) runs `job` there
// while the caller goes on, wait() returns once it is done. The thread is made once and
// waits between jobs, so a frame's split allocates nothing and starts no thread.
//
// Invariants: at most one job at a time (run while one is running is a logic error); the
// job must not throw (std::terminate); the destructor waits for a running job, then ends
// the thread.
#pragma once

#include <condition_variable>
#include <mutex>
#include <thread>

namespace rtamp::sim {

class HelperThread {
 public:
  HelperThread();
  ~HelperThread();
  HelperThread(const HelperThread&) = delete;
  HelperThread& operator=(const HelperThread&) = delete;

  // `job` (any callable; it must outlive the job) starts on the helper thread.
  template <class F>
  void run(F& job) {
    start(&call<F>, &job);
  }
  void wait();
  // wait() at the end of a scope.
  struct Join {
    explicit Join(HelperThread& h) : helper(h) {}
    ~Join() { helper.wait(); }
    Join(const Join&) = delete;
    Join& operator=(const Join&) = delete;
    HelperThread& helper;
  };

 private:
  template <class F>
  static void call(void* job) noexcept {
    (*static_cast<F*>(job))();
  }
  void start(void (*fn)(void*) noexcept, void* arg);
  void loop();

  std::mutex mutex_;
  std::condition_variable wake_, done_;
  void (*fn_)(void*) noexcept = nullptr;
  void* arg_ = nullptr;
  bool busy_ = false, stop_ = false;
  std::thread thread_;  // last: starts once the rest is made
};

}  // namespace rtamp::sim
