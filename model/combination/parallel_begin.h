#pragma once
/// @file
/// The parallel option of the coupled step (issue 7): begin_step of units 1..N-1 on one worker
/// thread while the caller runs unit 0.

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include "model/solver/couplable_system.h"

namespace rig::model::combination {

/// Runs begin_step of units 1..N-1 on one worker thread while the caller runs unit 0 (the
/// option of issue 7). Hand-over: both sides spin briefly on atomics, then sleep on a condition
/// variable; the counters are changed under the mutex, so no wake-up is lost. (std::atomic::wait
/// / notify of libstdc++ 12 deadlocked here after a few thousand hand-overs.) Nothing allocates
/// after construction.
class ParallelBegin {
 public:
  explicit ParallelBegin(std::vector<solver::CouplableSystem*> units)
      : units_(std::move(units)), worker_([this] { run(); }) {}
  ~ParallelBegin() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
      epoch_.fetch_add(1, std::memory_order_release);
    }
    work_cv_.notify_one();
    worker_.join();
  }
  ParallelBegin(const ParallelBegin&) = delete;
  ParallelBegin& operator=(const ParallelBegin&) = delete;

  /// Starts begin_step(h) of the worker's units.
  void start(double h) noexcept {
    h_ = h;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      target_ = epoch_.fetch_add(1, std::memory_order_release) + 1;
    }
    work_cv_.notify_one();
  }
  /// Returns when the worker's units have finished their begin_step.
  void wait() noexcept {
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
      for (solver::CouplableSystem* u : units_) u->begin_step(h_);
      {
        const std::lock_guard<std::mutex> lock(mutex_);
        done_.store(e, std::memory_order_release);
      }
      done_cv_.notify_one();
    }
  }

  std::vector<solver::CouplableSystem*> units_;
  double h_ = 0;
  unsigned target_ = 0;
  bool stop_ = false;
  alignas(64) std::atomic<unsigned> epoch_{0};
  alignas(64) std::atomic<unsigned> done_{0};
  std::mutex mutex_;
  std::condition_variable work_cv_, done_cv_;
  std::thread worker_;
};

}  // namespace rig::model::combination
