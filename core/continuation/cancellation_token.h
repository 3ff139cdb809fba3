// Stopping and pausing a run from outside it, between Newton iterations.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <optional>

namespace drape {

// Set from another thread (or a signal handler) to stop a run between Newton
// iterations; the run keeps every step converged so far. A run can also be
// paused between Newton iterations (from another thread, not a signal
// handler): the solver then waits in WaitWhilePaused until resumed or
// cancelled.
class CancellationToken {
 public:
  // Only an atomic store, so a signal handler may call it; a paused solver
  // sees it within WaitWhilePaused's polling interval.
  void Cancel() { cancelled_.store(true, std::memory_order_relaxed); }
  // Cancelled, or its parent is, or its deadline has passed.
  bool IsCancelled() const {
    return cancelled_.load(std::memory_order_relaxed) || (parent_ && parent_->IsCancelled()) ||
           DeadlinePassed();
  }

  // A token for one run: it also stops when `parent` (may be null) is
  // cancelled, waits while the parent is paused, and stops at `deadline`.
  // Set both before the run starts.
  void Follow(const CancellationToken* parent) { parent_ = parent; }
  void SetDeadline(std::chrono::steady_clock::time_point deadline) { deadline_ = deadline; }
  bool DeadlinePassed() const {
    return deadline_ && std::chrono::steady_clock::now() >= *deadline_;
  }

  void Pause() {
    std::lock_guard lock(mutex_);
    paused_ = true;
  }
  void Resume() {
    {
      std::lock_guard lock(mutex_);
      paused_ = false;
    }
    wake_.notify_all();
  }
  bool IsPaused() const {
    std::lock_guard lock(mutex_);
    return paused_;
  }
  // The solver's side: blocks while paused (returns at once otherwise),
  // until resumed or cancelled.
  void WaitWhilePaused() const {
    if (parent_) parent_->WaitWhilePaused();
    std::unique_lock lock(mutex_);
    while (paused_ && !IsCancelled()) wake_.wait_for(lock, std::chrono::milliseconds(20));
  }

 private:
  std::atomic<bool> cancelled_{false};
  const CancellationToken* parent_ = nullptr;
  std::optional<std::chrono::steady_clock::time_point> deadline_;
  mutable std::mutex mutex_;
  mutable std::condition_variable wake_;
  bool paused_ = false;
};

}  // namespace drape
