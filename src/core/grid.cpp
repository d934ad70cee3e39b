// SPDX-License-Identifier: MIT
// The grid: the one snapping rule (Grid::toUnits) and the grid fitted to a call's operands
// (resolveGrid): the power-of-two grid, or a decimal one (10^k units per coordinate unit) when
// only that holds every coordinate exactly. docs/algorithm.md, "Grid", states the guarantee and
// its error bound.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <roiclip/roiclip.hpp>

#include "pipeline.hpp"

namespace roiclip {
namespace {

constexpr double kMaxOriginUnits = 0x1p100;     // |origin * scale|: the output stage's bit budget
constexpr double kMaxSpanUnits = 0x1p31 - 8.0;  // s * E: every vertex within 2^30 of the middle
// |v| * 10^k at most this: round(v * 10^k) is then the n with v = RN(n / 10^k) (the product is
// within 1/4 of n), and n is the only one (the lattice is at least 4 ulps apart).
constexpr double kMaxDecimalUnits = 0x1p50;
constexpr int kMaxDecimals = 22;  // 10^22 is the largest power of ten a double holds exactly
constexpr int kOriginTries = 64;  // grid points near the middle tried as a decimal grid's origin

inline double roundUnits(double u) { return detail::roundToUnits(u); }

void checkFixed(const Grid& grid) {
  if (!(grid.scale > 0.0) || !std::isfinite(grid.scale)) {
    throw InvalidInputError("grid scale must be positive and finite, got " +
                            std::to_string(grid.scale));
  }
  for (const double o : {grid.origin.x * grid.scale, grid.origin.y * grid.scale}) {
    if (!(std::fabs(o) <= kMaxOriginUnits) || o != std::floor(o)) {
      throw InvalidInputError(
          "grid origin must lie on the grid (origin * scale an integer of "
          "magnitude at most 2^100)");
    }
  }
}

// The origin units of one axis: the grid point nearest the middle of [lo, hi] at scale s.
double middleUnits(double lo, double hi, double s) {
  return roundUnits(roundUnits(lo * s) * 0.5 + roundUnits(hi * s) * 0.5);
}

// The corners in range means every coordinate is (rounding is monotonic).
bool holdsBox(const Grid& grid, const detail::Box& box) {
  return grid.toUnits(box.minX, grid.origin.x) && grid.toUnits(box.maxX, grid.origin.x) &&
         grid.toUnits(box.minY, grid.origin.y) && grid.toUnits(box.maxY, grid.origin.y);
}

double extentOf(const detail::Box& box) {
  return std::max(box.maxX - box.minX, box.maxY - box.minY);
}

double magnitudeOf(const detail::Box& box) {
  return std::max(
      {std::fabs(box.minX), std::fabs(box.maxX), std::fabs(box.minY), std::fabs(box.maxY)});
}

// 10^k, exact for k <= 22.
double powerOfTen(int k) {
  double p = 1.0;
  for (int i = 0; i < k; ++i) p *= 10.0;
  return p;
}

// v is the double nearest a multiple of 1/s (s = 10^k, |v| * s <= kMaxDecimalUnits): the
// grid point round(v * s) gives v back.
inline bool onDecimalLattice(double v, double s) { return roundUnits(v * s) / s == v; }

constexpr double kRound = 6755399441055744.0;  // 1.5 * 2^52, as detail::roundToUnits
constexpr std::uint64_t kSignBit = std::uint64_t{1} << 63;

inline std::uint64_t bitsOf(double d) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &d, sizeof bits);
  return bits;
}

// The bits left in v - (its grid point's coordinate) over n coordinates, or'ed (without the
// sign: -0.0 is a zero difference too): zero when scale s holds every one. One branch-free pass
// (it vectorises). (u + kRound) - kRound rounds u = v * s to its integer n when |u| < 2^51; for
// a power of two the grid point is v when u is that integer, for 10^k when n / s gives v back
// (v is the double nearest n / 10^k). Any bit left (NaN and infinity included) means a
// coordinate off the grid, or one too large for the short rounding.
template <bool kPowerOfTwo>
std::uint64_t offGridBits(const double* v, std::size_t n, double s) {
  const auto bitsOff = [s](double c) {
    const double u = c * s;
    return bitsOf(kPowerOfTwo ? u - ((u + kRound) - kRound) : c - ((u + kRound) - kRound) / s);
  };
  std::uint64_t a = 0, b = 0;
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4) {
    a |= bitsOff(v[i]) | bitsOff(v[i + 2]);  // (a, b) are the x and y lanes of two points
    b |= bitsOff(v[i + 1]) | bitsOff(v[i + 3]);
  }
  for (; i < n; ++i) a |= bitsOff(v[i]);
  return (a | b) & ~kSignBit;
}

// The smallest k from `k` to `limit` such that every coordinate of `paths` is the double nearest
// a multiple of 10^-k (being one for k, it is one for every larger k), or limit + 1. A
// non-finite coordinate gives limit + 1: the snapping reports it. Blocks the current k holds
// pass in one vectorised check (offGridBits); only a block that needs a larger k, or the end of
// the search, is read one coordinate at a time.
int decimalsOf(const Paths& paths, int k, int limit, const double* powers) {
  constexpr std::size_t kBlock = 64;
  for (const Path& path : paths) {
    const double* v = path.empty() ? nullptr : &path.front().x;
    const std::size_t n = 2 * path.size();
    for (std::size_t start = 0; start < n; start += kBlock) {
      const std::size_t end = std::min(n, start + kBlock);
      if (offGridBits<false>(v + start, end - start, powers[k]) == 0) continue;
      for (std::size_t i = start; i < end; ++i) {
        if (!std::isfinite(v[i])) return limit + 1;
        while (!onDecimalLattice(v[i], powers[k])) {
          if (++k > limit) return k;
        }
      }
    }
  }
  return k;
}

// The origin of one axis for scale s = 10^k: a grid point near the middle whose coordinate
// (the double nearest it) multiplies back to it exactly, as Grid::toUnits and the output stage
// compute origin * scale. About one in eight does not; NaN when none of the tries does.
double decimalOrigin(double lo, double hi, double s) {
  const double middle = middleUnits(lo, hi, s);
  for (int i = 0; i < kOriginTries; ++i) {
    const double units = middle + ((i & 1) != 0 ? -double((i + 1) / 2) : double(i / 2));
    const double origin = units / s;
    if (origin * s == units) return origin;
  }
  return NAN;
}

}  // namespace

namespace detail {

void Box::add(const Paths& paths) {
  // One branch-free pass: minpd / maxpd on each point's (x, y) (NaN fails every comparison, so
  // it leaves the box as it is), and the bits of each coordinate's distance from its short
  // rounding to an integer or'ed (as offGridBits(); NaN and infinity leave bits too). Only an
  // infinite coordinate needs the second pass, which skips its point.
  static_assert(sizeof(Point) == 2 * sizeof(double), "a path is its coordinates in a row");
  double lo[2] = {minX, minY}, hi[2] = {maxX, maxY};
  std::uint64_t offInteger = 0;
#if defined(__SSE2__)
  __m128d low = _mm_loadu_pd(lo), high = _mm_loadu_pd(hi), off = _mm_setzero_pd();
  const __m128d round = _mm_set1_pd(kRound);
  const auto add = [&](const Point& p) {
    const __m128d v = _mm_loadu_pd(&p.x);
    low = _mm_min_pd(v, low);  // v < low ? v : low, lane by lane
    high = _mm_max_pd(v, high);
    off = _mm_or_pd(off, _mm_sub_pd(v, _mm_sub_pd(_mm_add_pd(v, round), round)));
  };
  for (const Path& path : paths) {
    const Point* p = path.data();
    const std::size_t n = path.size();
    std::size_t i = 0;
    for (; i + 4 <= n; i += 4) {  // four points a step: fewer loop tests
      add(p[i]);
      add(p[i + 1]);
      add(p[i + 2]);
      add(p[i + 3]);
    }
    for (; i < n; ++i) add(p[i]);
  }
  _mm_storeu_pd(lo, low);
  _mm_storeu_pd(hi, high);
  double offLanes[2];
  _mm_storeu_pd(offLanes, off);
  for (const double d : offLanes) offInteger |= bitsOf(d);
#else
  for (const Path& path : paths) {
    for (const Point& p : path) {
      const double v[2] = {p.x, p.y};
      for (int axis = 0; axis < 2; ++axis) {
        lo[axis] = v[axis] < lo[axis] ? v[axis] : lo[axis];
        hi[axis] = v[axis] > hi[axis] ? v[axis] : hi[axis];
        offInteger |= bitsOf(v[axis] - ((v[axis] + kRound) - kRound));
      }
    }
  }
#endif
  // The short rounding is exact below 2^51 in magnitude only (from -2^52 to -2^51 it keeps
  // halves): a larger box is not called integral. -0.0 is a zero distance.
  const bool small = std::max({-lo[0], -lo[1], hi[0], hi[1]}) < 0x1p51;
  integral = integral && (offInteger & ~kSignBit) == 0 && small;
  // Below 2^51, each distance is at most 1/2 (exponent field at most 0x3fe), and so is their or
  // (at most 0x3ff); NaN leaves 0x7ff. An infinity fails `small`, as does a larger box (then it
  // is not known: not called finite).
  finite = finite && small && (offInteger >> 52 & 0x7ff) != 0x7ff;
  if (std::isfinite(lo[0]) && std::isfinite(lo[1]) && std::isfinite(hi[0]) &&
      std::isfinite(hi[1])) {
    minX = lo[0], minY = lo[1], maxX = hi[0], maxY = hi[1];
    return;
  }
  for (const Path& path : paths) {
    for (const Point& p : path) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
      minX = std::min(minX, p.x);
      maxX = std::max(maxX, p.x);
      minY = std::min(minY, p.y);
      maxY = std::max(maxY, p.y);
    }
  }
}

Grid fitBinaryGrid(const Box& box) {
  const double extent = extentOf(box);
  if (!std::isfinite(extent)) {
    throw InvalidInputError("the input's bounding box (x " + std::to_string(box.minX) + " to " +
                            std::to_string(box.maxX) + ", y " + std::to_string(box.minY) + " to " +
                            std::to_string(box.maxY) +
                            ") is too large for doubles: its side overflows");
  }
  // A side of zero (all points on one line) would allow any scale; one that keeps the
  // coordinates' units below 2^92 keeps origin * scale within the output's bit budget. (Two
  // distinct doubles differ by at least 2^-54 of the larger, so this changes nothing otherwise.)
  double span = std::max(extent, magnitudeOf(box) * 0x1p-60);
  if (!(span > 0.0)) span = 1.0;
  // The largest power of two s with s * span <= 2^31 - 8: with the origin in the middle, every
  // coordinate lies within span * s / 2 + 1 <= 2^30 units of it.
  int exponent = std::ilogb(kMaxSpanUnits / span);
  exponent = std::clamp(exponent, -1022, 1000);
  for (;; --exponent) {
    const double s = std::ldexp(1.0, exponent);
    const Grid candidate = Grid::fixed(
        s, {middleUnits(box.minX, box.maxX, s) / s, middleUnits(box.minY, box.maxY, s) / s});
    // Only boxes a few doubles wide, where the middle is not exact, ever need a second round.
    if (holdsBox(candidate, box)) return candidate;
  }
}

bool holdsExactly(const Grid& grid, const Paths& paths) {
  constexpr std::size_t kBlock = 256;  // coordinates checked at once: data off the grid stops soon
  const double s = grid.scale;
  int exponent = 0;
  const bool powerOfTwo = std::frexp(s, &exponent) == 0.5;
  for (const Path& path : paths) {
    static_assert(sizeof(Point) == 2 * sizeof(double), "a path is its coordinates in a row");
    const double* v = path.empty() ? nullptr : &path.front().x;
    const std::size_t n = 2 * path.size();
    for (std::size_t start = 0; start < n; start += kBlock) {
      const std::size_t end = std::min(n, start + kBlock);
      const std::size_t count = end - start;
      if ((powerOfTwo ? offGridBits<true>(v + start, count, s)
                      : offGridBits<false>(v + start, count, s)) == 0) {
        continue;
      }
      for (std::size_t i = start; i < end; ++i) {  // the exact test (only large units pass here)
        if (std::isfinite(v[i]) && roundUnits(v[i] * s) / s != v[i]) return false;
      }
    }
  }
  return true;
}

std::optional<Grid> fitDecimalGrid(const Box& range, const Paths& a, const Paths& b,
                                   DecimalPick pick) {
  if (range.empty()) return std::nullopt;
  const double extent = extentOf(range);
  const double magnitude = magnitudeOf(range);
  if (!std::isfinite(extent)) return std::nullopt;
  double powers[kMaxDecimals + 1];
  int limit = -1;  // the largest k whose grid can hold the box
  for (int k = 0; k <= kMaxDecimals; ++k) {
    powers[k] = powerOfTen(k);
    if (!(powers[k] * extent <= kMaxSpanUnits - 2 * kOriginTries) ||
        !(powers[k] * magnitude <= kMaxDecimalUnits)) {
      break;
    }
    limit = k;
  }
  if (limit < 0) return std::nullopt;
  const int needed = decimalsOf(b, decimalsOf(a, 0, limit, powers), limit, powers);
  if (needed > limit) return std::nullopt;
  for (int k = pick == DecimalPick::Finest ? limit : needed; k >= needed; --k) {
    const double s = powers[k];
    const Grid grid = Grid::fixed(
        s, {decimalOrigin(range.minX, range.maxX, s), decimalOrigin(range.minY, range.maxY, s)});
    if (std::isfinite(grid.origin.x) && std::isfinite(grid.origin.y) && holdsBox(grid, range)) {
      return grid;
    }
  }
  return std::nullopt;
}

}  // namespace detail

Grid resolveGrid(const Grid& grid, const Paths& subject, const Paths& clip) {
  detail::Box subjectBox;
  return detail::resolveGrid(grid, subject, clip, subjectBox);
}

Grid detail::resolveGrid(const Grid& grid, const Paths& subject, const Paths& clip,
                         Box& subjectBox) {
  subjectBox = {};
  if (!grid.isFitted()) {
    checkFixed(grid);
    return grid;
  }
  subjectBox.add(subject);
  detail::Box box = subjectBox;
  box.add(clip);
  if (box.empty()) return Grid::fixed(1.0);
  const Grid binary = detail::fitBinaryGrid(box);
  // Data the power-of-two grid holds (pixels, binary fractions) keeps it; only data it would
  // move looks for a decimal grid that holds it.
  if (box.integral && binary.scale >= 1.0) return binary;  // pixels: no second pass
  if (detail::holdsExactly(binary, subject) && detail::holdsExactly(binary, clip)) return binary;
  return detail::fitDecimalGrid(box, subject, clip, detail::DecimalPick::Coarsest).value_or(binary);
}

}  // namespace roiclip
