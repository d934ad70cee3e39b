// SPDX-License-Identifier: MIT
// roiclip private header: an array that grows without copying what it holds once it is large.
//
// The arrangement's vertices are appended one crossing at a time, and how many there will be is
// known only when the sweep ends. A std::vector doubled its way there: on W3-1k even-odd 349,951
// vertices of 64 bytes sat in a capacity of 672,640 (43 MB, 21 MB of it never written) through
// tracing, where that call peaks, and the growth before held the old and the new array at once.
// Here the first chunk grows by half like a small vector (a small call allocates little); from
// one full chunk on, fixed chunks of the same size are added and nothing moves: at most one
// chunk is unused, and growing never holds two copies.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <iterator>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace roiclip::detail {

template <class T, unsigned kChunkBits>
class ChunkedArray {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                "elements are copied as bytes and never destroyed");

 public:
  static constexpr std::size_t kChunk = std::size_t{1} << kChunkBits;
  using value_type = T;

  class const_iterator {
   public:
    using iterator_category = std::forward_iterator_tag;
    using value_type = T;
    using difference_type = std::ptrdiff_t;
    using pointer = const T*;
    using reference = const T&;
    const_iterator() = default;
    const_iterator(const ChunkedArray* a, std::size_t i) : a_(a), i_(i) {}
    reference operator*() const { return (*a_)[i_]; }
    pointer operator->() const { return &(*a_)[i_]; }
    const_iterator& operator++() {
      ++i_;
      return *this;
    }
    const_iterator operator++(int) {
      const const_iterator old = *this;
      ++i_;
      return old;
    }
    bool operator==(const const_iterator& o) const { return i_ == o.i_; }
    bool operator!=(const const_iterator& o) const { return i_ != o.i_; }

   private:
    const ChunkedArray* a_ = nullptr;
    std::size_t i_ = 0;
  };

  ChunkedArray() = default;
  ChunkedArray(const ChunkedArray& other) {
    for (std::size_t i = 0; i < other.size_; ++i) push_back(other[i]);
  }
  ChunkedArray(ChunkedArray&& other) noexcept { swap(other); }
  ChunkedArray& operator=(ChunkedArray other) noexcept {
    swap(other);
    return *this;
  }
  ~ChunkedArray() {
    for (std::size_t c = 0; c < chunks_.size(); ++c) free(c);
  }

  [[nodiscard]] std::size_t size() const { return size_; }
  [[nodiscard]] bool empty() const { return size_ == 0; }
  /// Elements the chunks hold room for (what keeping or freeing them is decided by).
  [[nodiscard]] std::size_t capacity() const {
    return chunks_.empty() ? 0 : (chunks_.size() - 1) * kChunk + first_;
  }
  const T& operator[](std::size_t i) const { return chunks_[i >> kChunkBits][i & (kChunk - 1)]; }
  T& operator[](std::size_t i) { return chunks_[i >> kChunkBits][i & (kChunk - 1)]; }
  [[nodiscard]] const T& back() const { return end_[-1]; }
  /// The elements as one array when they fit the first chunk, else null.
  [[nodiscard]] const T* contiguous() const { return chunks_.size() == 1 ? chunks_[0] : nullptr; }
  [[nodiscard]] const_iterator begin() const { return {this, 0}; }
  [[nodiscard]] const_iterator end() const { return {this, size_}; }

  /// Room for `n` in the first chunk (at most a chunk).
  void reserve(std::size_t n) {
    if (chunks_.size() <= 1 && std::min(n, kChunk) > first_) growFirst(std::min(n, kChunk));
  }
  [[gnu::always_inline]] void push_back(const T& v) {
    if (size_ == room_) addRoom();
    std::memcpy(static_cast<void*>(end_), &v, sizeof(T));
    ++end_;
    ++size_;
  }
  /// Empties it; the first chunk keeps its capacity, the others are freed.
  void clear() {
    while (chunks_.size() > 1) {
      free(chunks_.size() - 1);
      chunks_.pop_back();
    }
    size_ = 0;
    end_ = chunks_.empty() ? nullptr : chunks_[0];
    room_ = first_;
  }
  void swap(ChunkedArray& other) noexcept {
    chunks_.swap(other.chunks_);
    std::swap(first_, other.first_);
    std::swap(size_, other.size_);
    std::swap(room_, other.room_);
    std::swap(end_, other.end_);
  }

 private:
  static T* allocate(std::size_t n) { return std::allocator<T>().allocate(n); }
  void free(std::size_t c) { std::allocator<T>().deallocate(chunks_[c], c == 0 ? first_ : kChunk); }
  // The first chunk grown to `n` (its elements copied): as a vector grows, while it is the only
  // one.
  void growFirst(std::size_t n) {
    T* bigger = allocate(n);
    if (!chunks_.empty()) {
      if (size_ > 0) std::memcpy(static_cast<void*>(bigger), chunks_[0], size_ * sizeof(T));
      free(0);
      chunks_[0] = bigger;
    } else {
      chunks_.push_back(bigger);
    }
    first_ = n;
    room_ = n;
    end_ = bigger + size_;
  }
  // The last chunk is full: the first grows by half up to a chunk, then a chunk is added.
  void addRoom() {
    if (first_ < kChunk) {
      growFirst(std::min(kChunk, first_ + first_ / 2 + 16));
      return;
    }
    chunks_.reserve(chunks_.size() + 1);
    chunks_.push_back(allocate(kChunk));
    end_ = chunks_.back();
    room_ += kChunk;
  }

  std::vector<T*> chunks_;
  std::size_t first_ = 0;  // the first chunk's capacity
  std::size_t size_ = 0;
  std::size_t room_ = 0;  // capacity(): push_back() adds room when size_ reaches it
  T* end_ = nullptr;      // where the next element goes
};

}  // namespace roiclip::detail
