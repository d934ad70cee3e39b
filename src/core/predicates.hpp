// SPDX-License-Identifier: MIT
// roiclip private header: every numeric decision of the pipeline lives here.
//
// Robustness strategy (the one place it is decided):
// - Input coordinates are snapped to integers ("grid units") with |v| <= 2^30 (Grid::kMaxUnits).
// - Every vertex of the planar arrangement is either an input point (integer) or the crossing
//   of two input segments, represented exactly in homogeneous form (X/W, Y/W) with
//   |X|,|Y| < 2^96 and 0 < W < 2^64 (__int128).
// - Predicates (orientation, lexicographic order, direction order) are exact: a double filter
//   with a conservative error bound answers most calls; the rest are computed exactly in
//   128-bit integers, and where a product can exceed 128 bits (comparing two crossings' x or y)
//   in 256-bit integers (Boost.Multiprecision). There is no epsilon in any topological decision.
// - Every edge piece keeps the integer input segment it lies on ("supporting segment"), so
//   intersections are always computed from integer data and the bit sizes above never grow.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>

#include <boost/multiprecision/cpp_int.hpp>

#include <roiclip/error.hpp>
#include <roiclip/geometry.hpp>

namespace roiclip::detail {

using i128 = __int128;
using i256 = boost::multiprecision::int256_t;

/// A point on the integer grid.
struct IPoint {
  std::int64_t x = 0;
  std::int64_t y = 0;
  friend bool operator==(const IPoint& a, const IPoint& b) { return a.x == b.x && a.y == b.y; }
  friend bool operator!=(const IPoint& a, const IPoint& b) { return !(a == b); }
  friend bool operator<(const IPoint& a, const IPoint& b) {
    return a.x < b.x || (a.x == b.x && a.y < b.y);
  }
};

/// |v| converted to double after a right shift to its 63 leading bits, scaled back by 2^shift
/// (exact: a power of two, the result below 2^128). With kSticky, every dropped bit is ORed into
/// the lowest kept one: a 63-bit value has 10 bits below a double's 53, so the sticky bit sits
/// below the rounding bit and the one rounding of the conversion is the rounding of |v|. Without
/// it the dropped bits are truncated, an error below 2^-62 of |v| (|v| >= 2^62 there).
template <bool kSticky>
inline double toDoubleShifted(i128 v) {
  if (v == i128(std::int64_t(v))) return double(std::int64_t(v));
  using u128 = unsigned __int128;
  const u128 u = v < 0 ? -u128(v) : u128(v);  // -2^127 too: unsigned negation
  const auto high = std::uint64_t(u >> 64);
  // u >= 2^63, so the shift is 1..65.
  const int bits = high != 0 ? 128 - __builtin_clzll(high) : 64;
  const int shift = bits - 63;
  std::uint64_t m = std::uint64_t(u >> shift);
  if constexpr (kSticky) m |= std::uint64_t((u & ((u128(1) << shift) - 1)) != 0);
  const std::uint64_t scaleBits = std::uint64_t(1023 + shift) << 52;
  double scale;
  std::memcpy(&scale, &scaleBits, sizeof scale);
  const double r = double(std::int64_t(m)) * scale;
  return v < 0 ? -r : r;
}

/// The double nearest to v (ties to even), bit for bit what the compiler's conversion
/// (__floattidf) gives, inline.
inline double toDouble(i128 v) { return toDoubleShifted<true>(v); }

/// A double within (2^-53 + 2^-62) |v| of v: toDouble() without the sticky bit, for the cached
/// doubles of crossings (pointAlong()), where the 128-bit mask of the sticky bit was the largest
/// single cost of the conversion (truncation 2^-62, then the rounding to double 2^-53).
inline double toDoubleWithin(i128 v) { return toDoubleShifted<false>(v); }

/// An exact point (X/W, Y/W), W > 0. Grid points have W == 1. The nearest doubles are cached
/// for the floating-point filters.
struct XPoint {
  i128 x = 0;
  i128 y = 0;
  i128 w = 1;
  double fx = 0;
  double fy = 0;
  XPoint() = default;
  XPoint(i128 px, i128 py, i128 pw)
      : x(px),
        y(py),
        w(pw),
        fx(pw == 1 ? toDouble(px) : toDouble(px) / toDouble(pw)),
        fy(pw == 1 ? toDouble(py) : toDouble(py) / toDouble(pw)) {}
  explicit XPoint(IPoint p) : x(p.x), y(p.y), w(1), fx(double(p.x)), fy(double(p.y)) {}
};

/// An exact point as the arrangement keeps it: 32 bytes instead of XPoint's 64 (W3-1k even-odd
/// keeps 350k vertices through tracing, where it peaks). X and Y in 96 bits, W in 64, no cached
/// doubles. Every vertex the sweep makes is a grid point or the crossing of two grid segments
/// within the grid's range (coordinates within 2^30 units of the origin; pointAlong()): W =
/// |d1 x d2| <= 2^63, and |X|, |Y| <= 2^30 W + 2^31 W < 2^95.
struct PackedPoint {
  std::uint64_t xLow = 0, yLow = 0, w = 1;
  std::int32_t xHigh = 0, yHigh = 0;
  PackedPoint() = default;
  /// p must be representable (representable()).
  explicit PackedPoint(const XPoint& p)
      : xLow(std::uint64_t(p.x)),
        yLow(std::uint64_t(p.y)),
        w(std::uint64_t(p.w)),
        xHigh(std::int32_t(p.x >> 64)),
        yHigh(std::int32_t(p.y >> 64)) {}
  /// Whether X and Y fit 96 bits and W (> 0, as in every XPoint) 64: the high words alone.
  [[nodiscard]] static bool representable(const XPoint& p) {
    const auto fits32 = [](i128 v) {
      return (std::uint64_t(std::int64_t(v >> 64)) + 0x80000000U) >> 32 == 0;
    };
    return fits32(p.x) & fits32(p.y) & (std::uint64_t(p.w >> 64) == 0);
  }
  [[nodiscard]] i128 x() const { return join(xHigh, xLow); }
  [[nodiscard]] i128 y() const { return join(yHigh, yLow); }
  /// The point with its cached doubles (computed again: two divisions).
  [[nodiscard]] XPoint unpack() const { return XPoint(x(), y(), i128(w)); }

 private:
  static i128 join(std::int32_t high, std::uint64_t low) {
    return i128(high) * (i128(1) << 64) + i128(low);
  }
};
static_assert(sizeof(PackedPoint) == 32);

inline i256 wide(i128 v) { return i256(v); }
inline int signOf(i128 v) { return (v > 0) - (v < 0); }
inline int signOf(const i256& v) { return v.sign(); }

/// Sign of (b - a) x (c - a): +1 when c is to the left of a->b (counter-clockwise in the raw
/// (x, y) frame), 0 when collinear. Exact for grid points.
inline int orient(IPoint a, IPoint b, IPoint c) {
  const i128 v = i128(b.x - a.x) * (c.y - a.y) - i128(b.y - a.y) * (c.x - a.x);
  return signOf(v);
}

/// orient() for grid points within the grid's range, |x|, |y| <= Grid::kMaxUnits = 2^30 units
/// of the origin (every snapped point): the differences are at most 2^31 and each product at
/// most 2^62 in magnitude, so both products fit int64 and comparing them (no subtraction, which
/// could reach 2^63) gives the exact sign.
inline int orientInGrid(IPoint a, IPoint b, IPoint c) {
  static_assert(Grid::kMaxUnits <= (std::int64_t{1} << 30), "the bound above assumes 2^30");
  const std::int64_t l = (b.x - a.x) * (c.y - a.y);
  const std::int64_t r = (b.y - a.y) * (c.x - a.x);
  return (l > r) - (l < r);
}

/// The exact part of orient(a, b, c) for an off-grid c.
[[gnu::noinline]] inline int orientExact(IPoint a, IPoint b, const XPoint& c) {
  // Exact in 128 bits: |X|, |Y| < 3 * 2^93 and |a * W| <= 2^93, so |ex|, |ey| < 2^95.4, and
  // with |b - a| <= 2^31 each product stays below 2^126.4. The check guards that reasoning.
  const i128 ex = c.x - i128(a.x) * c.w;
  const i128 ey = c.y - i128(a.y) * c.w;
  i128 l, r;
  if (__builtin_mul_overflow(i128(b.x - a.x), ey, &l) ||
      __builtin_mul_overflow(i128(b.y - a.y), ex, &r)) {
    throw InternalError("orient: coordinate bound violated");
  }
  return (l > r) - (l < r);
}

/// Orientation of an exact point against the line through grid points a, b.
inline int orient(IPoint a, IPoint b, const XPoint& c) {
  if (c.w == 1) return orient(a, b, IPoint{std::int64_t(c.x), std::int64_t(c.y)});
  const double ux = double(b.x - a.x), uy = double(b.y - a.y);
  const double cx = c.fx - double(a.x), cy = c.fy - double(a.y);
  const double v = ux * cy - uy * cx;
  // c.fx, c.fy carry a relative error below 2^-51; the bound covers that and the rounding of
  // the subtractions and products with a wide margin.
  const double bound = 1e-13 * (std::fabs(ux) * (std::fabs(c.fy) + std::fabs(double(a.y))) +
                                std::fabs(uy) * (std::fabs(c.fx) + std::fabs(double(a.x))) + 1.0);
  if (v > bound) return 1;
  if (v < -bound) return -1;
  return orientExact(a, b, c);
}

/// orient() for a, b and c within the grid's range (|coordinates| <= Grid::kMaxUnits = 2^30), as
/// every point of the sweep is. The filter's bound is static per line: ux, uy (|.| <= 2^31) are
/// exact; c's cached doubles are within 2^-51 * 2^30 = 2^-21 of c, and subtracting a.x, a.y
/// (|result| < 2^31.1) rounds by at most 2^-21.9 more, so |cx - exact| < 2^-20. Then each product
/// is off by |u| 2^-20 from cx, cy and by 2^-53 |u| 2^31.1 < |u| 2^-21.9 from its rounding, and
/// the difference's rounding adds at most (|ux| + |uy|) 2^-21.9: in all below
/// (|ux| + |uy|) (2^-20 + 2^-21) < (|ux| + |uy|) 2^-19.4. The bound (|ux| + |uy|) 2^-18 is 2.6
/// times that (its own rounding, one addition, is 2^-53 of it).
inline int orientInBox(IPoint a, IPoint b, const XPoint& c) {
  static_assert(Grid::kMaxUnits <= (std::int64_t{1} << 30), "the bound below assumes 2^30");
  if (c.w == 1) return orientInGrid(a, b, IPoint{std::int64_t(c.x), std::int64_t(c.y)});
  const double ux = double(b.x - a.x), uy = double(b.y - a.y);
  const double cx = c.fx - double(a.x), cy = c.fy - double(a.y);
  const double v = ux * cy - uy * cx;
  const double bound = (std::fabs(ux) + std::fabs(uy)) * 0x1p-18;
  if (v > bound) return 1;
  if (v < -bound) return -1;
  return orientExact(a, b, c);
}

/// Exact lexicographic comparison (x first, then y): -1, 0, +1.
[[gnu::noinline]] inline int compareCoord(i128 a, i128 aw, i128 b, i128 bw) {
  if (aw == bw) return (a > b) - (a < b);
  i128 l, r;
  if (!__builtin_mul_overflow(a, bw, &l) && !__builtin_mul_overflow(b, aw, &r)) {
    return (l > r) - (l < r);
  }
  const i256 lw = wide(a) * wide(bw), rw = wide(b) * wide(aw);
  return (lw > rw) - (lw < rw);
}

/// The order of two exact coordinates a, b from their cached doubles da, db: -1 or +1 when the
/// doubles decide it, 0 when only the exact values can. Each cached double is within 2^-51 of
/// its exact value relative (X / W: three roundings of 2^-53), so |(a - b) - (da - db)| <=
/// 2^-51 (|da| + |db|) (1 + 2^-50), and the rounded difference is off by another 2^-53 of itself:
/// a difference beyond 1e-14 (|da| + |db|) (about 45x that) has the sign of a - b.
inline int compareCached(double da, double db) {
  const double bound = 1e-14 * (std::fabs(da) + std::fabs(db));
  if (da - db > bound) return 1;
  if (db - da > bound) return -1;
  return 0;
}

/// compareCached() for coordinates known to lie within the grid's range, |a|, |b| <=
/// Grid::kMaxUnits = 2^30, as every point of the sweep does (input points, and crossings of
/// segments between them): a static bound, two subtractions and two comparisons. Each cached
/// double is then within 2^-51 * 2^30 = 2^-21 of its exact value; a slab crossing's (the sweep's
/// slabCrossing(), from the parameter along a line) within 2^-20 + 2^-23. So |(a - b) - (da -
/// db)| <= 2.25 * 2^-20, the rounding of da - db (below 2^31 + 1) adds at most 2^-22, and a
/// rounded difference beyond 2^-18 = 4 * 2^-20 has the sign of a - b.
constexpr double kCachedInBoxBound = 0x1p-18;
inline int compareCachedInBox(double da, double db) {
  static_assert(Grid::kMaxUnits <= (std::int64_t{1} << 30), "the bound below assumes 2^30");
  if (da - db > kCachedInBoxBound) return 1;
  if (db - da > kCachedInBoxBound) return -1;
  return 0;
}

// da, db: the cached doubles of a / aw and b / bw (relative error below 2^-51).
inline int compareCoordFiltered(i128 a, i128 aw, double da, i128 b, i128 bw, double db) {
  const int c = compareCached(da, db);
  return c != 0 ? c : compareCoord(a, aw, b, bw);
}

inline int compare(const XPoint& a, const XPoint& b) {
  // Same denominator (both on the grid, the common case, or copies of one crossing): the
  // numerators decide, W > 0.
  if (a.w == b.w) {
    if (a.x != b.x) return a.x < b.x ? -1 : 1;
    return (a.y > b.y) - (a.y < b.y);
  }
  const int cx = compareCoordFiltered(a.x, a.w, a.fx, b.x, b.w, b.fx);
  return cx != 0 ? cx : compareCoordFiltered(a.y, a.w, a.fy, b.y, b.w, b.fy);
}
inline bool equal(const XPoint& a, const XPoint& b) { return compare(a, b) == 0; }
inline bool less(const XPoint& a, const XPoint& b) { return compare(a, b) < 0; }

/// compare() for points within the grid's range (|coordinates| <= Grid::kMaxUnits = 2^30), as
/// every point of the sweep is (input points, and crossings of segments between them): the
/// cached doubles are filtered with compareCachedInBox()'s static bound instead of a relative
/// one. Exact: the filter answers only beyond its proven bound, the numerators otherwise.
[[gnu::always_inline]] inline int compareInBox(const XPoint& a, const XPoint& b) {
  if (a.w == b.w) {
    if (a.x != b.x) return a.x < b.x ? -1 : 1;
    return (a.y > b.y) - (a.y < b.y);
  }
  int c = compareCachedInBox(a.fx, b.fx);
  if (c == 0) c = compareCoord(a.x, a.w, b.x, b.w);
  if (c != 0) return c;
  c = compareCachedInBox(a.fy, b.fy);
  return c != 0 ? c : compareCoord(a.y, a.w, b.y, b.w);
}
/// compareInBox() asking the cached x first: the same answer, cheaper where a is mostly off the
/// grid and rarely shares b's x (a new crossing against the sweep point and the pieces' ends),
/// dearer where grid points share an x (the plain order asks the denominators first).
inline int compareInBoxCachedFirst(const XPoint& a, const XPoint& b) {
  const int c = compareCachedInBox(a.fx, b.fx);
  return c != 0 ? c : compareInBox(a, b);
}
inline bool equalInBox(const XPoint& a, const XPoint& b) { return compareInBox(a, b) == 0; }
inline bool lessInBox(const XPoint& a, const XPoint& b) { return compareInBox(a, b) < 0; }

/// Sign of d1 x d2 for direction vectors of grid segments: +1 when d2 turns counter-clockwise
/// from d1. Grid points lie within 2^30 units of the origin, so each component is at most 2^31
/// and each product at most 2^62 in magnitude: both fit int64, and comparing them (no
/// subtraction, which could reach 2^63) gives the exact sign, as orientInGrid() does.
inline int crossSign(IPoint d1, IPoint d2) {
  static_assert(Grid::kMaxUnits <= (std::int64_t{1} << 30), "the bound above assumes 2^30");
  const std::int64_t l = d1.x * d2.y;
  const std::int64_t r = d1.y * d2.x;
  return (l > r) - (l < r);
}

/// Whether direction d (not zero) points into the lower half-turn [pi, 2 pi) of angles from the
/// positive x axis; with crossSign(), the order of directions by angle.
inline bool inLowerHalfTurn(IPoint d) { return d.y < 0 || (d.y == 0 && d.x < 0); }

/// Directions (not zero) in counter-clockwise order of their angle from the positive x axis
/// (exact): whether a comes before b.
inline bool ccwBefore(IPoint a, IPoint b) {
  const bool la = inLowerHalfTurn(a), lb = inLowerHalfTurn(b);
  if (la != lb) return lb;
  return crossSign(a, b) > 0;
}

/// Whether direction c lies strictly inside the counter-clockwise sector from a to b (three
/// distinct directions).
inline bool inSectorCcw(IPoint a, IPoint b, IPoint c) {
  return ccwBefore(a, b) ? ccwBefore(a, c) && ccwBefore(c, b) : ccwBefore(a, c) || ccwBefore(c, b);
}

/// Whether directions u and w (not zero) point the same way (parallel, components of one sign:
/// a dot product of two 2^31 vectors would not fit).
inline bool sameDirection(IPoint u, IPoint w) {
  if (crossSign(u, w) != 0) return false;
  return u.x != 0 ? (u.x > 0) == (w.x > 0) : (u.y > 0) == (w.y > 0);
}

/// The direction from b to a (grid points lie within 2^30 units of the origin: it fits).
inline IPoint minus(IPoint a, IPoint b) { return {a.x - b.x, a.y - b.y}; }

/// A hash of grid point p whose coordinates have k low zero bits (shifted out, so that points
/// of a coarse lattice spread): an open-addressing table of 2^bits slots starts at
/// pointHash(p, k) >> (64 - bits).
inline std::uint64_t pointHash(IPoint p, int k) {
  return std::uint64_t(p.x >> k) * 0x9E3779B97F4A7C15ULL ^
         std::uint64_t(p.y >> k) * 0xC2B2AE3D27D4EB4FULL;
}
/// The bits of an open-addressing table with at least two slots per entry (16 at least).
inline int tableBits(std::size_t count) {
  int bits = 4;
  while ((std::size_t{1} << bits) < 2 * count) ++bits;
  return bits;
}

/// The point a + (num / den) * (b - a) on the line through grid points a, b; den > 0. Crossings
/// on the grid come back with W == 1.
[[gnu::always_inline]] inline void pointAlong(IPoint a, IPoint b, i128 num, i128 den, XPoint& out) {
  // Both mostly fit 64 bits (grid points within 2^30 of the origin: each is a difference of two
  // products below 2^62): then each coordinate takes two 64-by-64-bit products, not 128-by-128.
  i128 x, y;
  if (num == i128(std::int64_t(num)) && den == i128(std::int64_t(den))) {
    const std::int64_t n = std::int64_t(num), d = std::int64_t(den);
    x = i128(a.x) * d + i128(b.x - a.x) * n;
    y = i128(a.y) * d + i128(b.y - a.y) * n;
  } else {
    x = i128(a.x) * den + i128(b.x - a.x) * num;
    y = i128(a.y) * den + i128(b.y - a.y) * num;
  }
  // Not reduced by gcds (that cost more than the rest of the crossing): comparisons are exact
  // for any representation. Crossings on the grid are stored with W == 1 for the fast paths;
  // the double quotient is within 2^-50 relative of the exact one, so a grid point is always
  // caught, and the exact product check rejects near misses.
  // Each quotient is within 2^-51 of x / den relative, as every cached double: x within
  // 2^-53 + 2^-62 (toDoubleWithin()), den and the division within 2^-53 each.
  const double fden = toDouble(den);
  const double fx = toDoubleWithin(x) / fden, fy = toDoubleWithin(y) / fden;
  const double rx = double(std::int64_t(fx + (fx >= 0 ? 0.5 : -0.5)));
  const double ry = double(std::int64_t(fy + (fy >= 0 ? 0.5 : -0.5)));
  if (std::fabs(fx - rx) < 1e-3 && std::fabs(fy - ry) < 1e-3 && i128(rx) * den == x &&
      i128(ry) * den == y) {
    out = XPoint(IPoint{std::int64_t(rx), std::int64_t(ry)});
    return;
  }
  out.x = x;  // XPoint(x, y, den) without converting x, y and den to double again
  out.y = y;
  out.w = den;
  out.fx = fx;
  out.fy = fy;
}

/// Crossing point of the lines through grid segments (a, b) and (c, d). Returns false when the
/// lines are parallel. Crossings on the grid come back with W == 1.
inline bool lineIntersection(IPoint a, IPoint b, IPoint c, IPoint d, XPoint& out) {
  const i128 d1x = b.x - a.x, d1y = b.y - a.y, d2x = d.x - c.x, d2y = d.y - c.y;
  i128 den = d1x * d2y - d1y * d2x;
  if (den == 0) return false;
  i128 num = i128(c.x - a.x) * d2y - i128(c.y - a.y) * d2x;
  if (den < 0) {
    den = -den;
    num = -num;
  }
  pointAlong(a, b, num, den, out);
  return true;
}

/// The exact coordinates of an XPoint without its cached doubles (a sweep event and an
/// arrangement vertex keep those apart or not at all).
struct ExactCoords {
  i128 x, y, w;
};

/// Whether the closed grid segments (a, b) and (c, d) meet in exactly one point (not parallel,
/// so not collinear), and that point (lineIntersection()). The same answer as the four
/// orientation tests orient(a, b, c), orient(a, b, d), orient(c, d, a), orient(c, d, b) followed
/// by lineIntersection(), from three cross products instead of six (the sweep's crossing test):
/// with d1 = b - a, d2 = d - c, den = d1 x d2, e = d1 x (c - a) and num = (c - a) x d2, those
/// orientations are the signs of e, e + den, num and num - den.
inline bool segmentCrossing(IPoint a, IPoint b, IPoint c, IPoint d, XPoint& out) {
  const i128 d1x = b.x - a.x, d1y = b.y - a.y, d2x = d.x - c.x, d2y = d.y - c.y;
  const i128 cax = c.x - a.x, cay = c.y - a.y;
  i128 den = d1x * d2y - d1y * d2x;
  if (den == 0) return false;  // parallel or collinear
  const i128 e = d1x * cay - d1y * cax;
  const int o1 = signOf(e), o2 = signOf(e + den);
  if (o1 * o2 > 0) return false;  // c and d strictly on one side of line ab
  i128 num = cax * d2y - cay * d2x;
  const int o3 = signOf(num), o4 = signOf(num - den);
  if (o3 * o4 > 0) return false;  // a and b strictly on one side of line cd
  if (den < 0) {
    den = -den;
    num = -num;
  }
  pointAlong(a, b, num, den, out);
  return true;
}

}  // namespace roiclip::detail
