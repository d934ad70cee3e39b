// SPDX-License-Identifier: MIT
// toDouble() (src/core/predicates.hpp), the inline i128 -> double conversion, bit for bit against
// the compiler's conversion on edge values (+-2^127, powers of two and their neighbours, halfway
// cases with and without a sticky bit) and on random values of every bit length.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "predicates.hpp"

namespace roiclip::detail {
namespace {

using u128 = unsigned __int128;

std::uint64_t bitsOf(double d) {
  std::uint64_t b;
  std::memcpy(&b, &d, sizeof b);
  return b;
}

// The compiler's conversion, kept from being folded or replaced.
[[gnu::noinline]] double reference(i128 v) {
  volatile i128 copy = v;
  return static_cast<double>(copy);
}

void expectSame(i128 v) {
  const double want = reference(v), got = toDouble(v);
  EXPECT_EQ(bitsOf(want), bitsOf(got)) << "high " << std::uint64_t(u128(v) >> 64) << " low "
                                       << std::uint64_t(v) << ": want " << want << " got " << got;
}

void expectBothSigns(u128 u) {
  expectSame(i128(u));
  expectSame(-i128(u));
}

TEST(ToDouble, ExtremesAndPowersOfTwo) {
  expectSame(i128(u128(1) << 127));  // -2^127
  expectSame(i128((u128(1) << 127) - 1));
  expectSame(-i128((u128(1) << 127) - 1));
  expectSame(0);
  for (int k = 0; k < 127; ++k) {
    const u128 p = u128(1) << k;
    expectBothSigns(p);
    expectBothSigns(p - 1);
    expectBothSigns(p + 1);
  }
}

// m * 2^s + offset around the halfway point between two doubles: m odd with 54 bits puts the
// value exactly between two neighbours (ties to even go down for m = 2^53 + 1, up for 2^53 + 3);
// +-1 below (a sticky bit far from the rounding bit) moves it off the tie.
TEST(ToDouble, HalfwayCases) {
  const std::vector<std::uint64_t> mantissas = {
      (std::uint64_t(1) << 53) + 1, (std::uint64_t(1) << 53) + 3, (std::uint64_t(1) << 54) - 1,
      (std::uint64_t(1) << 53) | 0x5555555555555ULL};
  for (const std::uint64_t m : mantissas) {
    for (int s = 0; s + 54 <= 127; ++s) {
      const u128 v = u128(m) << s;
      expectBothSigns(v);
      expectBothSigns(v + 1);
      if (v > 0) expectBothSigns(v - 1);
    }
  }
}

TEST(ToDouble, RandomValuesOfEveryLength) {
  std::mt19937_64 rng(20261202);
  for (int bits = 1; bits <= 127; ++bits) {
    for (int i = 0; i < 2000; ++i) {
      u128 v = (u128(rng()) << 64) | rng();
      v >>= 128 - bits;
      v |= u128(1) << (bits - 1);  // exactly `bits` bits
      expectBothSigns(v);
    }
  }
}

// toDoubleWithin() (the crossings' cached doubles): within (2^-53 + 2^-62) |v| of v, checked in
// integers, and the same as toDouble() for values that fit 64 bits.
void expectWithin(i128 v) {
  const double got = toDoubleWithin(v);
  const u128 magnitude = v < 0 ? -u128(v) : u128(v);
  ASSERT_EQ(got < 0, v < 0);
  // |got| is an integer (|v| >= 2^63 here, or the conversion is exact) below 2^128.
  const u128 g = u128(got < 0 ? -got : got);
  const u128 error = g > magnitude ? g - magnitude : magnitude - g;
  EXPECT_LE(error, (magnitude >> 53) + (magnitude >> 62))
      << "high " << std::uint64_t(u128(v) >> 64) << " low " << std::uint64_t(v);
  if (v == i128(std::int64_t(v))) {
    EXPECT_EQ(bitsOf(got), bitsOf(toDouble(v)));
  }
}

TEST(ToDoubleWithin, ErrorBoundOnEdgesHalfwayCasesAndRandomValues) {
  expectWithin(i128((u128(1) << 127) - 1));
  expectWithin(-i128((u128(1) << 127) - 1));
  expectWithin(0);
  for (int k = 0; k < 127; ++k) {
    const u128 p = u128(1) << k;
    for (const u128 v : {p - 1, p, p + 1}) {
      expectWithin(i128(v));
      expectWithin(-i128(v));
    }
  }
  std::mt19937_64 rng(20261203);
  for (int bits = 1; bits <= 127; ++bits) {
    for (int i = 0; i < 2000; ++i) {
      u128 v = (u128(rng()) << 64) | rng();
      v >>= 128 - bits;
      v |= u128(1) << (bits - 1);
      expectWithin(i128(v));
      expectWithin(-i128(v));
    }
  }
}

// The arrangement's 32-byte vertex: every crossing of two grid segments within the grid's range
// round-trips exactly, the extremes of its range included; beyond them it reports so.
TEST(PackedPoint, CrossingsAcrossTheGridRangeRoundTrip) {
  constexpr std::int64_t kMax = Grid::kMaxUnits;
  const auto roundTrips = [](const XPoint& p) {
    if (!PackedPoint::representable(p)) return false;
    const PackedPoint packed(p);
    const XPoint q = packed.unpack();
    return q.x == p.x && q.y == p.y && q.w == p.w && packed.w == std::uint64_t(p.w);
  };
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<std::int64_t> coord(-kMax, kMax);
  std::uniform_int_distribution<int> pick(0, 3);
  const auto extreme = [&]() {
    const std::int64_t values[] = {-kMax, kMax, coord(rng), pick(rng) == 0 ? 0 : kMax - 1};
    return values[pick(rng)];
  };
  int crossings = 0;
  for (int k = 0; k < 200000; ++k) {
    const IPoint a{extreme(), extreme()}, b{extreme(), extreme()}, c{extreme(), extreme()},
        d{extreme(), extreme()};
    XPoint x;
    if (!segmentCrossing(a, b, c, d, x)) continue;
    ++crossings;
    ASSERT_TRUE(roundTrips(x)) << k;
  }
  EXPECT_GT(crossings, 10000);
  // The bound itself: |X| < 2^95, 0 < W < 2^64.
  const i128 big = i128(1) << 95;
  EXPECT_TRUE(roundTrips(XPoint(big - 1, -big, i128(1) << 63)));
  EXPECT_TRUE(roundTrips(XPoint(-7, 5, (i128(1) << 64) - 1)));
  EXPECT_FALSE(PackedPoint::representable(XPoint(big, 0, 1)));
  EXPECT_FALSE(PackedPoint::representable(XPoint(0, -big - 1, 1)));
  EXPECT_FALSE(PackedPoint::representable(XPoint(1, 1, i128(1) << 64)));
}

}  // namespace
}  // namespace roiclip::detail
