// SPDX-License-Identifier: MIT
// Output: exact points to correctly rounded doubles (see output.hpp).
#include "output.hpp"

#include <cfloat>
#include <cmath>
#include <cstring>

#include <roiclip/error.hpp>

namespace roiclip::detail {
namespace {

using u128 = unsigned __int128;
using u256 = boost::multiprecision::uint256_t;

int bitLength(u128 v) {
  const auto hi = std::uint64_t(v >> 64), lo = std::uint64_t(v);
  if (hi != 0) return 128 - __builtin_clzll(hi);
  return lo != 0 ? 64 - __builtin_clzll(lo) : 0;
}
int bitLength(const u256& v) { return v == 0 ? 0 : int(boost::multiprecision::msb(v)) + 1; }

u128 toU128(const u256& v) {
  const u256 mask = (u256(1) << 64) - 1;
  return (u128(static_cast<std::uint64_t>((v >> 64) & mask)) << 64) |
         u128(static_cast<std::uint64_t>(v & mask));
}

// n / d * 2^exp2 rounded to nearest, ties to even: q = floor(n * 2^sh / d) with 55 or 56 bits,
// then its 53 leading bits (fewer when the result is subnormal), rounded on the bits below them
// and on whether the division left a remainder.
template <class U>
double nearestUnsigned(U n, U d, int exp2) {
  const int nb = bitLength(n), db = bitLength(d);
  const int sh = 55 - (nb - db);
  if (sh >= 0) {
    n <<= sh;
  } else {
    d <<= -sh;
  }
  const U q = n / d;
  const bool sticky = q * d != n;
  const int qb = bitLength(q);              // 55 or 56
  const int exponent = qb - 1 + exp2 - sh;  // floor(log2(value))
  int precision = 53;
  if (exponent < -1022) precision -= -1022 - exponent;  // subnormal: fewer bits
  if (precision < 0) return 0.0;                        // below half the least subnormal
  const int drop = qb - precision;                      // 2 .. 56
  std::uint64_t m = drop < qb ? static_cast<std::uint64_t>(q >> drop) : 0;
  const auto rest = static_cast<std::uint64_t>(q - (U(m) << drop));  // < 2^56
  const std::uint64_t half = std::uint64_t{1} << (drop - 1);
  if (rest > half || (rest == half && (sticky || (m & 1) != 0))) ++m;
  return std::ldexp(double(m), exp2 - sh + drop);
}

std::uint64_t bitsOf(double v) {
  std::uint64_t b = 0;
  std::memcpy(&b, &v, sizeof b);
  return b;
}
double fromBits(std::uint64_t b) {
  double v = 0;
  std::memcpy(&v, &b, sizeof v);
  return v;
}

// v * 2^e for a positive normal v, by the exponent field (no libm call); false when the result
// would not be normal.
bool timesPow2(double v, int e, double& out) {
  const std::uint64_t b = bitsOf(v);
  const int field = int(b >> 52) + e;
  if (field < 1 || field > 2046) return false;
  out = fromBits((b & ((std::uint64_t{1} << 52) - 1)) | (std::uint64_t(field) << 52));
  return true;
}

// floor(n / d) and the remainder; the quotient must fit 64 bits. One instruction on x86-64.
std::uint64_t divide(u128 n, std::uint64_t d, std::uint64_t& remainder) {
#if defined(__x86_64__)
  std::uint64_t q = 0, r = 0;
  __asm__("divq %4"
          : "=a"(q), "=d"(r)
          : "a"(std::uint64_t(n)), "d"(std::uint64_t(n >> 64)), "rm"(d));
  remainder = r;
  return q;
#else
  const u128 q = n / d;
  remainder = std::uint64_t(n - q * d);
  return std::uint64_t(q);
#endif
}

// nearestUnsigned() for n < 2^119 and d < 2^64 (the common case: a crossing's coordinate and
// its W) in 64-bit words: the shifted dividend fits 128 bits, the shifted divisor 64 and the
// quotient 56, so one 128-by-64-bit division gives q and the remainder. False (the caller then
// takes nearestUnsigned()) for n >= 2^119 or a result that is not normal. n > 0.
[[gnu::always_inline]] inline bool nearestNarrow(u128 n, std::uint64_t d, int exp2, double& out) {
  const auto high = std::uint64_t(n >> 64);
  const int nb = high != 0 ? 128 - __builtin_clzll(high) : 64 - __builtin_clzll(std::uint64_t(n));
  if (nb > 119) return false;
  const int sh = 55 - (nb - (64 - __builtin_clzll(d)));  // n 2^sh / d lies in (2^54, 2^56)
  std::uint64_t rem = 0;
  const std::uint64_t q = sh >= 0 ? divide(n << sh, d, rem) : divide(n, d << -sh, rem);
  const int drop = (64 - __builtin_clzll(q)) - 53;  // 2 or 3
  std::uint64_t m = q >> drop;                      // in [2^52, 2^53)
  const std::uint64_t rest = q & ((std::uint64_t{1} << drop) - 1);
  const std::uint64_t half = std::uint64_t{1} << (drop - 1);
  if (rest > half || (rest == half && (rem != 0 || (m & 1) != 0))) ++m;  // ties to even
  // m 2^e as bits: the exponent field of 2^52 2^e, plus m - 2^52 (m = 2^53 after rounding up
  // carries into the exponent, as it should). Normal results only.
  const int field = exp2 - sh + drop + 1075;
  if (field < 1 || field + int(m >> 53) > 2046) return false;
  out = fromBits((std::uint64_t(field) << 52) + (m - (std::uint64_t{1} << 52)));
  return true;
}

bool fitsInt64(i128 v) { return v == i128(std::int64_t(v)); }

// Within 128 bits after the shift (the common case) in native integer division.
bool fits128(int nb, int db) {
  const int sh = 55 - (nb - db);
  return nb <= 127 && db <= 127 && (sh >= 0 ? nb + sh : db - sh) <= 127;
}

}  // namespace

double nearestDouble(const i256& num, const i256& den, int exp2) {
  if (num == 0) return 0.0;
  const bool negative = num < 0;
  const u256 n = u256(negative ? i256(-num) : num);
  const u256 d = u256(den);
  double v = 0;
  const bool narrow = bitLength(n) <= 119 && bitLength(d) <= 64;
  if (!(narrow && nearestNarrow(toU128(n), std::uint64_t(toU128(d)), exp2, v))) {
    v = fits128(bitLength(n), bitLength(d)) ? nearestUnsigned<u128>(toU128(n), toU128(d), exp2)
                                            : nearestUnsigned<u256>(n, d, exp2);
  }
  return negative ? -v : v;
}

OutputFrame::OutputFrame(const Grid& grid) {
  int e = 0;
  const double f = std::frexp(grid.scale, &e);  // scale = f * 2^e, f in [0.5, 1)
  // The mantissa as an odd integer: scale = m * 2^(e - 53) with m < 2^53, then the trailing zeros
  // moved to the exponent.
  auto m = std::int64_t(std::ldexp(f, 53));
  e -= 53;
  if (m != 0) {  // one count, not a loop: a power-of-two scale has 52 trailing zeros
    const int zeros = __builtin_ctzll(std::uint64_t(m));
    m >>= zeros;
    e += zeros;
  }
  scaleMantissa_ = m;
  scaleExponent_ = e;
  const double origin[2] = {grid.origin.x, grid.origin.y};
  for (int axis = 0; axis < 2; ++axis) {
    const double o = origin[axis] * grid.scale;  // an integer: the origin lies on the grid
    if (!(std::fabs(o) <= 0x1p100) || o != std::floor(o)) {
      throw InternalError("OutputFrame: the grid's origin is not on the grid");
    }
    originUnits_[axis] = i128(o);
  }
  constexpr i128 kOriginBound = i128(1) << 52;  // plus 2^30 grid units: below 2^53
  static_assert(Grid::kMaxUnits <= (std::int64_t{1} << 30), "the bound above assumes 2^30");
  if (scaleMantissa_ == 1 && -scaleExponent_ >= -1022 && 53 - scaleExponent_ <= 1023 &&
      originUnits_[0] > -kOriginBound && originUnits_[0] < kOriginBound &&
      originUnits_[1] > -kOriginBound && originUnits_[1] < kOriginBound) {
    gridFast_ = true;
    gridOrigin_[0] = std::int64_t(originUnits_[0]);
    gridOrigin_[1] = std::int64_t(originUnits_[1]);
    gridFactor_ = std::ldexp(1.0, -scaleExponent_);
  }
}

double OutputFrame::coordinate(i128 units, i128 w, int axis) const {
  const i128 o = originUnits_[axis];
  if (w == 1 && scaleMantissa_ == 1) {
    // A grid point on a power-of-two grid: one exact conversion when it fits 53 bits.
    const i128 n = units + o;
    constexpr i128 kExact = i128(1) << 53;
    if (n == 0) return 0.0;
    double v = 0;
    if (n > -kExact && n < kExact &&
        timesPow2(std::fabs(double(std::int64_t(n))), -scaleExponent_, v)) {
      return n < 0 ? -v : v;
    }
  }
  // (units / w + o) / (m * 2^e) = (units + o * w) / (w * m) * 2^-e. The common case (w a product
  // of two grid differences, the origin and the scale's mantissa within 64 bits) in 64-bit
  // factors, whose products are below 2^126, and one division (nearestNarrow()).
  if (fitsInt64(o) && fitsInt64(w) && fitsInt64(scaleMantissa_)) {
    const i128 d = i128(std::int64_t(w)) * std::int64_t(scaleMantissa_);
    i128 n = 0;
    if ((d >> 64) == 0 &&
        !__builtin_add_overflow(units, i128(std::int64_t(o)) * std::int64_t(w), &n)) {
      if (n == 0) return 0.0;
      double v = 0;
      if (nearestNarrow(n < 0 ? u128(-n) : u128(n), std::uint64_t(d), -scaleExponent_, v)) {
        return n < 0 ? -v : v;
      }
    }
  }
  return coordinateExact(units, w, o);
}

[[gnu::always_inline]] inline bool OutputFrame::quotientFast(i128 n, std::uint64_t d,
                                                             double& v) const {
  if (n == 0) {
    v = 0.0;
    return true;
  }
  if (!nearestNarrow(n < 0 ? u128(-n) : u128(n), d, -scaleExponent_, v)) return false;
  if (n < 0) v = -v;
  return true;
}

bool OutputFrame::offGridFast(i128 x, i128 y, i128 w, Point& out) const {
  // |v| < 2^100 or -2^100: v >> 100 is 0 or -1.
  const auto within = [](i128 v) { return u128((v >> 100) + 1) <= 1; };
  if (w <= 1 || (w >> 64) != 0 || !within(x) || !within(y)) return false;
  // |X| <= 2^100 and |origin| < 2^52 (gridFast_): each numerator lies within 2^117.
  const auto d = std::uint64_t(w);
  return quotientFast(x + i128(gridOrigin_[0]) * i128(d), d, out.x) &&
         quotientFast(y + i128(gridOrigin_[1]) * i128(d), d, out.y);
}

bool OutputFrame::alongFast(IPoint a, IPoint d, std::int64_t num, std::int64_t den,
                            Point& out) const {
  if (!gridFast_ || den <= 0) return false;
  // |a + origin| < 2^53 and den < 2^63, |d num| <= 2^94: each numerator lies within 2^117.
  return quotientFast(i128(a.x + gridOrigin_[0]) * den + i128(d.x) * num, std::uint64_t(den),
                      out.x) &&
         quotientFast(i128(a.y + gridOrigin_[1]) * den + i128(d.y) * num, std::uint64_t(den),
                      out.y);
}

double OutputFrame::coordinateExact(i128 units, i128 w, i128 o) const {
  i128 ow = 0, n = 0, d = 0;
  if (!__builtin_mul_overflow(o, w, &ow) && !__builtin_add_overflow(units, ow, &n) &&
      !__builtin_mul_overflow(w, scaleMantissa_, &d) && n > -(i128(1) << 126) &&
      n < (i128(1) << 126)) {
    if (n == 0) return 0.0;
    const u128 un = n < 0 ? u128(-n) : u128(n);
    if (fits128(bitLength(un), bitLength(u128(d)))) {
      const double v = nearestUnsigned<u128>(un, u128(d), -scaleExponent_);
      return n < 0 ? -v : v;
    }
  }
  const i256 num = wide(units) + wide(o) * wide(w);
  const i256 den = wide(w) * wide(scaleMantissa_);
  return nearestDouble(num, den, -scaleExponent_);
}

}  // namespace roiclip::detail

namespace roiclip {

double Grid::toCoordinate(std::int64_t units, double originCoordinate) const {
  Grid axisGrid = Grid::fixed(scale, {originCoordinate, originCoordinate});
  return detail::OutputFrame(axisGrid).coordinate(units, 1, 0);
}

}  // namespace roiclip
