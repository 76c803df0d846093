// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A bounded FIFO between two pipeline stages. When full, push() either waits for room (Block: every frame is
// processed, the producer slows down) or discards the oldest queued item (DropOldest: a camera that cannot wait;
// the consumer always gets the newest frames). close() wakes everyone; pop() then drains what is left.
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>
#include <optional>

namespace bs::vision {

enum class QueuePolicy { Block, DropOldest };

template <class T>
class BoundedQueue {
 public:
  BoundedQueue(std::size_t capacity, QueuePolicy policy) : capacity_(capacity < 1 ? 1 : capacity), policy_(policy) {}

  // Returns how many items were dropped to make room (0 or 1); false-y push after close() drops the item.
  std::size_t push(T item) {
    std::unique_lock lock(mutex_);
    std::size_t dropped = 0;
    if (policy_ == QueuePolicy::Block) {
      not_full_.wait(lock, [&] { return closed_ || items_.size() < capacity_; });
    } else if (items_.size() >= capacity_) {
      items_.pop_front();
      dropped = 1;
    }
    if (closed_) return dropped;
    items_.push_back(std::move(item));
    high_water_ = std::max(high_water_, items_.size());
    not_empty_.notify_one();
    return dropped;
  }

  // Waits for an item; nullopt once the queue is closed and empty.
  std::optional<T> pop() {
    std::unique_lock lock(mutex_);
    not_empty_.wait(lock, [&] { return closed_ || !items_.empty(); });
    if (items_.empty()) return std::nullopt;
    T item = std::move(items_.front());
    items_.pop_front();
    not_full_.notify_one();
    return item;
  }

  void close() {
    std::lock_guard lock(mutex_);
    closed_ = true;
    not_empty_.notify_all();
    not_full_.notify_all();
  }

  std::size_t high_water() const {
    std::lock_guard lock(mutex_);
    return high_water_;
  }
  std::size_t capacity() const { return capacity_; }

 private:
  const std::size_t capacity_;
  const QueuePolicy policy_;
  mutable std::mutex mutex_;
  std::condition_variable not_empty_, not_full_;
  std::deque<T> items_;
  std::size_t high_water_ = 0;
  bool closed_ = false;
};

}  // namespace bs::vision
