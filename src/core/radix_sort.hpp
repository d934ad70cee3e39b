// SPDX-License-Identifier: MIT
// The sweeps' vertex orders: events sorted by their 64-bit keys (StartFrame::key(), x << 32 | y)
// with a least-significant-digit radix sort over only the bits in which the keys differ. A
// pixel contour's x and y span 11 bits or less each (a fitted grid's units have their low bits
// all zero, which are skipped), so a few passes do: no comparison, and no branch that the data
// decides, where a comparison sort of a few hundred events mispredicts about one comparison in
// two (W5: the two sweeps' sorts were 12% of the time and 3% of the instructions).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace roiclip::detail {
namespace radix {

constexpr unsigned kWideDigitBits = 11;  // from kWideFrom events: 2,048 buckets a pass
constexpr unsigned kNarrowDigitBits = 8;
constexpr std::size_t kRadixFrom = 64;  // fewer events: std::sort
constexpr std::size_t kWideFrom = 2048;
constexpr std::size_t kSplitFrom = std::size_t{1} << 20;

// The digits of the sort, lowest first: a shift and a mask each.
struct Digits {
  std::array<std::pair<unsigned, std::uint64_t>, 16> at;
  std::size_t count = 0;
};
// Cuts key bits [low, high) into digits of equal width, `widest` bits at most.
inline void cutIntoDigits(unsigned low, unsigned high, unsigned widest, Digits& digits) {
  if (high <= low) return;
  const unsigned passes = (high - low + widest - 1) / widest;
  const unsigned width = (high - low + passes - 1) / passes;
  for (unsigned shift = low; shift < high; shift += width) {
    const unsigned bits = std::min(width, high - shift);
    digits.at[digits.count++] = {shift, (std::uint64_t{1} << bits) - 1};
  }
}
// Sorts `count` items at `data` by the digits, through `scratch`. Whether they end in `data`
// (an even number of digits) rather than in `scratch`.
template <class T>
bool sortDigits(T* data, T* scratch, std::size_t count, const Digits& digits) {
  for (std::size_t d = 0; d < digits.count; ++d) {
    const auto [shift, mask] = digits.at[d];
    std::array<std::uint32_t, std::size_t{1} << kWideDigitBits> start;
    std::fill_n(start.begin(), mask + 1, 0U);
    const T* const end = data + count;
    for (const T* e = data; e != end; ++e) ++start[(e->key >> shift) & mask];
    std::uint32_t sum = 0;
    for (std::size_t b = 0; b <= mask; ++b) {
      const std::uint32_t c = start[b];
      start[b] = sum;
      sum += c;
    }
    for (const T* e = data; e != end; ++e) scratch[start[(e->key >> shift) & mask]++] = *e;
    std::swap(data, scratch);
  }
  return digits.count % 2 == 0;
}

}  // namespace radix

/// Sorts `items` (each with a `std::uint64_t key` laid out as StartFrame::key()) by key, equal
/// keys in any order, with `scratch` as the second array. Fewer than 64: std::sort. Up to 2,047:
/// digits of 8 bits or less (256 buckets). More: 11 bits or less. From 2^20, the items are first
/// split by the top 8 bits of x, and each part sorted by the other digits while it lies in the
/// cache: a pass over all of them costs a memory round trip per item (10M: 100 ms a pass).
template <class T>
void sortByKey(std::vector<T>& items, std::vector<T>& scratch) {
  const std::size_t n = items.size();
  if (n < radix::kRadixFrom) {
    std::sort(items.begin(), items.end(), [](const T& a, const T& b) { return a.key < b.key; });
    return;
  }
  std::uint64_t differ = 0;  // the bits in which some key differs from the first
  for (const T& e : items) differ |= e.key ^ items.front().key;
  // The digits run over the bits in which y varies, then those in which x does.
  const auto span = [](std::uint64_t bits) {
    return bits == 0 ? std::pair{0U, 0U}
                     : std::pair{unsigned(__builtin_ctzll(bits)), 64U - __builtin_clzll(bits)};
  };
  const auto [yLow, yHigh] = span(differ & 0xffffffffU);
  auto [xLow, xHigh] = span(differ & ~std::uint64_t{0xffffffffU});
  const unsigned topBits = n >= radix::kSplitFrom ? std::min(8U, xHigh - xLow) : 0;
  xHigh -= topBits;
  const unsigned widest = n >= radix::kWideFrom ? radix::kWideDigitBits : radix::kNarrowDigitBits;
  radix::Digits digits;
  radix::cutIntoDigits(yLow, yHigh, widest, digits);
  radix::cutIntoDigits(xLow, xHigh, widest, digits);
  scratch.resize(n);
  if (topBits == 0) {
    if (!radix::sortDigits(items.data(), scratch.data(), n, digits)) items.swap(scratch);
    return;
  }
  // The split: by x's top bits into `scratch`, then each part in place there.
  const std::uint64_t mask = (std::uint64_t{1} << topBits) - 1;
  std::array<std::uint32_t, 257> start{};
  for (const T& e : items) ++start[((e.key >> xHigh) & mask) + 1];
  for (std::size_t b = 1; b < start.size(); ++b) start[b] += start[b - 1];
  std::array<std::uint32_t, 257> next = start;
  for (const T& e : items) scratch[next[(e.key >> xHigh) & mask]++] = e;
  bool inScratch = true;
  for (std::size_t b = 0; b <= mask; ++b) {
    const std::size_t from = start[b], count = start[b + 1] - from;
    inScratch = radix::sortDigits(scratch.data() + from, items.data() + from, count, digits);
  }
  if (inScratch) items.swap(scratch);
}

}  // namespace roiclip::detail
