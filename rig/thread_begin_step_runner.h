#pragma once
/// @file
/// The rig's BeginStepRunner for the parallel option of the coupled step (issue 7): one worker
/// thread that takes over the scheduling policy and priority of the thread that first calls
/// start() (the SCHED_FIFO loop thread), so that the loop never waits on a normal-priority thread.

#include <pthread.h>
#include <sched.h>

#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include "model/combination/begin_step_runner.h"
#include "model/solver/couplable_system.h"
#include "rig/signals.h"

namespace rig {

/// Runs begin_step of units 1..N-1 on one worker thread while the caller runs unit 0 (the
/// option of issue 7). Hand-over: both sides spin briefly on atomics, then sleep on a condition
/// variable; the counters are changed under the mutex, so no wake-up is lost. (std::atomic::wait
/// / notify of libstdc++ 12 deadlocked here after a few thousand hand-overs.) Nothing allocates
/// after construction.
class ThreadBeginStepRunner final : public model::combination::BeginStepRunner {
 public:
  explicit ThreadBeginStepRunner(std::vector<model::solver::CouplableSystem*> units)
      : units_(std::move(units)), worker_(start_thread([this] { run(); })) {}
  ~ThreadBeginStepRunner() override {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
      epoch_.fetch_add(1, std::memory_order_release);
    }
    work_cv_.notify_one();
    worker_.join();
  }

  /// Starts begin_step(h) of the worker's units.
  void start(double h) noexcept override {
    if (!sched_taken_) {  // the caller's policy and priority, handed to the worker once
      sched_taken_ = true;
      (void)pthread_getschedparam(pthread_self(), &policy_, &sched_);
    }
    h_ = h;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      target_ = epoch_.fetch_add(1, std::memory_order_release) + 1;
    }
    work_cv_.notify_one();
  }
  /// Returns when the worker's units have finished their begin_step.
  void wait() noexcept override {
    for (int spin = 0; spin < kSpins; ++spin) {
      if (done_.load(std::memory_order_acquire) == target_) return;
    }
    std::unique_lock<std::mutex> lock(mutex_);
    done_cv_.wait(lock, [this] { return done_.load(std::memory_order_acquire) == target_; });
  }

 private:
  static constexpr int kSpins = 20000;

  void run() noexcept {
    unsigned seen = 0;
    bool sched_applied = false;
    for (;;) {
      unsigned e = epoch_.load(std::memory_order_acquire);
      for (int spin = 0; e == seen && spin < kSpins; ++spin)
        e = epoch_.load(std::memory_order_acquire);
      if (e == seen) {
        std::unique_lock<std::mutex> lock(mutex_);
        work_cv_.wait(lock, [&] { return epoch_.load(std::memory_order_acquire) != seen; });
        e = epoch_.load(std::memory_order_acquire);
      }
      seen = e;
      {
        const std::lock_guard<std::mutex> lock(mutex_);
        if (stop_) return;
      }
      if (!sched_applied) {  // start() wrote policy_/sched_ before the epoch it published
        sched_applied = true;
        // Refused without privilege: then both threads have the default policy anyway.
        (void)pthread_setschedparam(pthread_self(), policy_, &sched_);
      }
      for (model::solver::CouplableSystem* u : units_) u->begin_step(h_);
      {
        const std::lock_guard<std::mutex> lock(mutex_);
        done_.store(e, std::memory_order_release);
      }
      done_cv_.notify_one();
    }
  }

  std::vector<model::solver::CouplableSystem*> units_;
  double h_ = 0;
  bool sched_taken_ = false;
  int policy_ = SCHED_OTHER;
  sched_param sched_{};
  unsigned target_ = 0;
  bool stop_ = false;
  alignas(64) std::atomic<unsigned> epoch_{0};
  alignas(64) std::atomic<unsigned> done_{0};
  std::mutex mutex_;
  std::condition_variable work_cv_, done_cv_;
  std::thread worker_;
};

/// The factory for CombinationParams::begin_step_runner.
inline std::unique_ptr<model::combination::BeginStepRunner> make_thread_begin_step_runner(
    std::vector<model::solver::CouplableSystem*> units) {
  return std::make_unique<ThreadBeginStepRunner>(std::move(units));
}

}  // namespace rig
