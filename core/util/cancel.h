// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <atomic>
#include <functional>
#include <stdexcept>
#include <string_view>

namespace bs {

// Progress in [0, 1] with a short description of the current step. May be empty.
using ProgressFn = std::function<void(double fraction, std::string_view step)>;

// Shared between the thread doing long work and the one that may cancel it. Long operations poll
// cancelled() at least every few milliseconds of work and then throw Cancelled, leaving nothing half-written.
class CancelToken {
 public:
  void cancel() noexcept { flag_.store(true, std::memory_order_relaxed); }
  bool cancelled() const noexcept { return flag_.load(std::memory_order_relaxed); }
  void throw_if_cancelled() const;
  // The same long work's progress: the owner sets a receiver before the work starts (never during it); the worker
  // reports through the token it already holds, so a step deep inside (a 100-million-row log, its chunks being
  // stored) shows progress without every layer in between passing a callback along.
  void set_progress(ProgressFn fn) { progress_ = std::move(fn); }
  void report(double fraction, std::string_view step) const {
    if (progress_) progress_(fraction, step);
  }

 private:
  std::atomic<bool> flag_{false};
  ProgressFn progress_;
};

class Cancelled : public std::runtime_error {
 public:
  Cancelled() : std::runtime_error("cancelled by the user") {}
};

inline void CancelToken::throw_if_cancelled() const {
  if (cancelled()) throw Cancelled();
}

}  // namespace bs
