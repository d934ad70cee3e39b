// SPDX-License-Identifier: MIT
// Global operator new/delete replacement that counts allocations and tracks the peak live heap.
// Sizes come from malloc_usable_size (glibc), so no header is prepended and sized/unsized delete
// both work; the counts are therefore in usable bytes, a few percent above the requested size.
#include "alloc_counter.hpp"

#include <malloc.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <new>

namespace roiclip::bench {
namespace {

// Relaxed atomics: the benchmarks are single-threaded, the atomics only keep a stray library
// thread from corrupting the totals.
std::atomic<std::int64_t> gLive{0};
std::atomic<std::int64_t> gBaseline{0};
std::atomic<std::int64_t> gPeak{0};
std::atomic<std::uint64_t> gAllocations{0};
std::atomic<std::uint64_t> gBytes{0};

void noteAllocation(void* p) {
  const auto size = std::int64_t(malloc_usable_size(p));
  gAllocations.fetch_add(1, std::memory_order_relaxed);
  gBytes.fetch_add(std::uint64_t(size), std::memory_order_relaxed);
  const std::int64_t live = gLive.fetch_add(size, std::memory_order_relaxed) + size;
  std::int64_t peak = gPeak.load(std::memory_order_relaxed);
  while (live > peak && !gPeak.compare_exchange_weak(peak, live, std::memory_order_relaxed)) {
  }
}

void noteRelease(void* p) {
  if (p == nullptr) return;
  gLive.fetch_sub(std::int64_t(malloc_usable_size(p)), std::memory_order_relaxed);
}

void* allocate(std::size_t size) {
  void* p = std::malloc(size == 0 ? 1 : size);
  if (p == nullptr) throw std::bad_alloc();
  noteAllocation(p);
  return p;
}

void* allocateAligned(std::size_t size, std::align_val_t align) {
  void* p = nullptr;
  const std::size_t alignment = std::max(std::size_t(align), sizeof(void*));
  if (posix_memalign(&p, alignment, size == 0 ? 1 : size) != 0) throw std::bad_alloc();
  noteAllocation(p);
  return p;
}

void release(void* p) noexcept {
  noteRelease(p);
  std::free(p);
}

}  // namespace

void resetAllocStats() {
  const std::int64_t live = gLive.load(std::memory_order_relaxed);
  gBaseline.store(live, std::memory_order_relaxed);
  gPeak.store(live, std::memory_order_relaxed);
  gAllocations.store(0, std::memory_order_relaxed);
  gBytes.store(0, std::memory_order_relaxed);
}

AllocStats allocStats() {
  AllocStats stats;
  stats.allocations = gAllocations.load(std::memory_order_relaxed);
  stats.bytes = gBytes.load(std::memory_order_relaxed);
  stats.peakLive = std::uint64_t(gPeak.load(std::memory_order_relaxed) -
                                 gBaseline.load(std::memory_order_relaxed));
  return stats;
}

}  // namespace roiclip::bench

// The replaceable global allocation functions ([new.delete]); all variants route through the
// counting helpers so that no allocation escapes the totals.
void* operator new(std::size_t size) { return roiclip::bench::allocate(size); }
void* operator new[](std::size_t size) { return roiclip::bench::allocate(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return roiclip::bench::allocate(size);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return roiclip::bench::allocate(size);
  } catch (...) {
    return nullptr;
  }
}
void* operator new(std::size_t size, std::align_val_t align) {
  return roiclip::bench::allocateAligned(size, align);
}
void* operator new[](std::size_t size, std::align_val_t align) {
  return roiclip::bench::allocateAligned(size, align);
}
void operator delete(void* p) noexcept { roiclip::bench::release(p); }
void operator delete[](void* p) noexcept { roiclip::bench::release(p); }
void operator delete(void* p, std::size_t) noexcept { roiclip::bench::release(p); }
void operator delete[](void* p, std::size_t) noexcept { roiclip::bench::release(p); }
void operator delete(void* p, std::align_val_t) noexcept { roiclip::bench::release(p); }
void operator delete[](void* p, std::align_val_t) noexcept { roiclip::bench::release(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
  roiclip::bench::release(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
  roiclip::bench::release(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept { roiclip::bench::release(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { roiclip::bench::release(p); }
