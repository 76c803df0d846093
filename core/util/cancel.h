// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <atomic>
#include <functional>
#include <stdexcept>
#include <string_view>

namespace bs {

// Shared between the thread doing long work and the one that may cancel it. Long operations poll
// cancelled() at least every few milliseconds of work and then throw Cancelled, leaving nothing half-written.
class CancelToken {
 public:
  void cancel() noexcept { flag_.store(true, std::memory_order_relaxed); }
  bool cancelled() const noexcept { return flag_.load(std::memory_order_relaxed); }
  void throw_if_cancelled() const;

 private:
  std::atomic<bool> flag_{false};
};

class Cancelled : public std::runtime_error {
 public:
  Cancelled() : std::runtime_error("cancelled by the user") {}
};

inline void CancelToken::throw_if_cancelled() const {
  if (cancelled()) throw Cancelled();
}

// Progress in [0, 1] with a short description of the current step. May be empty.
using ProgressFn = std::function<void(double fraction, std::string_view step)>;

}  // namespace bs
