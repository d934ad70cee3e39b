// SPDX-License-Identifier: MIT
// The sweep's start events (src/core/workspace.hpp): the 64-bit key keeps the points'
// lexicographic order over the whole grid range, and sortByKey() (radix_sort.hpp) sorts like
// std::sort on random, duplicate-heavy, sorted and reversed keys.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <tuple>
#include <vector>

#include "radix_sort.hpp"
#include "workspace.hpp"

namespace roiclip::detail {
namespace {

constexpr std::int64_t kMax = Grid::kMaxUnits;

TEST(SweepStarts, KeyOrderIsPointOrderAcrossTheGrid) {
  const StartFrame frame{-kMax, -kMax};
  const std::vector<std::int64_t> values = {-kMax, -kMax + 1, -1, 0, 1, kMax - 1, kMax};
  std::vector<IPoint> points;
  for (std::int64_t x : values) {
    for (std::int64_t y : values) points.push_back({x, y});
  }
  for (const IPoint& a : points) {
    EXPECT_EQ(frame.point(frame.key(a)), a);
    for (const IPoint& b : points) EXPECT_EQ(a < b, frame.key(a) < frame.key(b));
  }
}

std::vector<SweepStart> randomStarts(std::mt19937_64& rng, std::size_t n, std::uint64_t range) {
  std::vector<SweepStart> starts;
  std::uniform_int_distribution<std::uint64_t> coord(0, range);
  const StartFrame frame{-kMax, -kMax};
  for (std::size_t i = 0; i < n; ++i) {
    const IPoint p{-kMax + std::int64_t(coord(rng)), -kMax + std::int64_t(coord(rng))};
    starts.push_back({frame.key(p), int(i), (i & 1) != 0});
  }
  return starts;
}

// Keys come out as std::sort orders them, and every event is still there once.
void expectSortedLikeStd(std::vector<SweepStart> starts) {
  std::vector<SweepStart> want = starts;
  const auto byKey = [](const SweepStart& a, const SweepStart& b) { return a.key < b.key; };
  std::sort(want.begin(), want.end(), byKey);
  std::vector<SweepStart> scratch;
  sortByKey(starts, scratch);
  ASSERT_EQ(starts.size(), want.size());
  for (std::size_t i = 0; i < starts.size(); ++i) ASSERT_EQ(starts[i].key, want[i].key) << i;
  const auto full = [](const SweepStart& a, const SweepStart& b) {
    return std::tie(a.key, a.piece, a.end) < std::tie(b.key, b.piece, b.end);
  };
  std::sort(want.begin(), want.end(), full);
  std::sort(starts.begin(), starts.end(), full);
  for (std::size_t i = 0; i < starts.size(); ++i) {
    ASSERT_EQ(starts[i].piece, want[i].piece);
    ASSERT_EQ(starts[i].end, want[i].end);
  }
}

TEST(SweepStarts, SortMatchesStdSort) {
  std::mt19937_64 rng(1302);
  for (const std::size_t n : {0, 1, 2, 17, 63, 64, 1000, 2047, 2048, 100000}) {
    SCOPED_TRACE(n);
    expectSortedLikeStd(randomStarts(rng, n, 2 * std::uint64_t(kMax)));  // whole grid
    expectSortedLikeStd(randomStarts(rng, n, 3));                        // duplicate-heavy
    expectSortedLikeStd(randomStarts(rng, n, 1000));
    std::vector<SweepStart> sorted = randomStarts(rng, n, 1 << 20);
    std::sort(sorted.begin(), sorted.end(),
              [](const SweepStart& a, const SweepStart& b) { return a.key < b.key; });
    expectSortedLikeStd(sorted);
    std::reverse(sorted.begin(), sorted.end());
    expectSortedLikeStd(sorted);
  }
}

}  // namespace
}  // namespace roiclip::detail
