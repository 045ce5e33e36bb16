#pragma once
/// @file
/// The parallel option of the coupled step (issue 7): begin_step of units 1..N-1 on one worker
/// thread while the caller runs unit 0.

#include <atomic>
#include <thread>
#include <utility>
#include <vector>

#include "model/solver/couplable_system.h"

namespace rig::model::combination {

/// Runs begin_step of units 1..N-1 on one worker thread while the caller runs unit 0 (the
/// option of issue 7). Hand-over by atomics: the worker spins briefly, then sleeps in
/// std::atomic::wait (futex); nothing allocates after construction. notify_all, not
/// notify_one: libstdc++ 12 keeps the waiters of different atomics in shared buckets, and
/// notify_one could wake the wrong one (a lost wake-up that deadlocked the benchmark).
class ParallelBegin {
 public:
  explicit ParallelBegin(std::vector<solver::CouplableSystem*> units)
      : units_(std::move(units)), worker_([this] { run(); }) {}
  ~ParallelBegin() {
    stop_.store(true, std::memory_order_relaxed);
    epoch_.fetch_add(1, std::memory_order_release);
    epoch_.notify_all();
    worker_.join();
  }
  ParallelBegin(const ParallelBegin&) = delete;
  ParallelBegin& operator=(const ParallelBegin&) = delete;

  void start(double h) noexcept {
    h_ = h;
    const unsigned e = epoch_.fetch_add(1, std::memory_order_release) + 1;
    target_ = e;
    epoch_.notify_all();
  }
  void wait() noexcept {
    for (int spin = 0; done_.load(std::memory_order_acquire) != target_; ++spin) {
      if (spin > 20000) done_.wait(done_.load(std::memory_order_acquire));
    }
  }

 private:
  void run() noexcept {
    unsigned seen = 0;
    for (;;) {
      unsigned e = epoch_.load(std::memory_order_acquire);
      for (int spin = 0; e == seen; ++spin) {
        if (spin > 20000) epoch_.wait(seen, std::memory_order_acquire);
        e = epoch_.load(std::memory_order_acquire);
      }
      seen = e;
      if (stop_.load(std::memory_order_relaxed)) return;
      for (solver::CouplableSystem* u : units_) u->begin_step(h_);
      done_.store(e, std::memory_order_release);
      done_.notify_all();
    }
  }

  std::vector<solver::CouplableSystem*> units_;
  double h_ = 0;
  unsigned target_ = 0;
  alignas(64) std::atomic<unsigned> epoch_{0};
  alignas(64) std::atomic<unsigned> done_{0};
  std::atomic<bool> stop_{false};
  std::thread worker_;
};

}  // namespace rig::model::combination
