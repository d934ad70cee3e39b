// Independent oracle for the conformance suites: exact winding numbers of arbitrary double
// coordinates (the suites' data is not on roiclip's grid), computed without roiclip's snapping,
// predicates or pipeline, so it can judge both our result and the suite's expectation.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include <boost/multiprecision/cpp_int.hpp>
#include <glm/common.hpp>

#include <roiclip/geometry.hpp>

namespace roiclip::conformance {

/// Exact sign of the orientation of (a, b, p): +1 when p is left of a->b in (x, y) maths axes.
/// Floating-point filter (Shewchuk's bound for orient2d), then exact rationals: every double is
/// a dyadic rational, so the fallback is exact for any input.
inline int orientation(Point a, Point b, Point p) {
  const double left = (b.x - a.x) * (p.y - a.y);
  const double right = (b.y - a.y) * (p.x - a.x);
  const double det = left - right;
  const double bound = 3.3306690738754716e-16 * (std::fabs(left) + std::fabs(right));
  if (det > bound) return 1;
  if (-det > bound) return -1;
  using boost::multiprecision::cpp_rational;
  const cpp_rational exact =
      (cpp_rational(b.x) - cpp_rational(a.x)) * (cpp_rational(p.y) - cpp_rational(a.y)) -
      (cpp_rational(b.y) - cpp_rational(a.y)) * (cpp_rational(p.x) - cpp_rational(a.x));
  return exact > 0 ? 1 : (exact < 0 ? -1 : 0);
}

/// Exact winding number of a closed ring around p (p must not lie on the ring; callers keep
/// sample points away from every edge).
inline long long windingNumber(const Path& ring, Point p) {
  long long w = 0;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point a = ring[i];
    const Point b = ring[(i + 1) % n];
    if (a.y <= p.y) {
      if (b.y > p.y && orientation(a, b, p) > 0) ++w;
    } else if (b.y <= p.y && orientation(a, b, p) < 0) {
      --w;
    }
  }
  return w;
}

/// Sum of the winding numbers of all rings around p.
inline long long windingNumber(const Paths& rings, Point p) {
  long long w = 0;
  for (const Path& ring : rings) w += windingNumber(ring, p);
  return w;
}

/// Euclidean distance from p to segment ab (approximate: only used to keep samples away from
/// edges by a margin much larger than its rounding error).
inline double distanceToSegment(Point p, Point a, Point b) {
  const Point ab = b - a;
  const double len2 = ab.x * ab.x + ab.y * ab.y;
  double t = len2 > 0 ? ((p.x - a.x) * ab.x + (p.y - a.y) * ab.y) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const Point q = a + t * ab;
  return std::hypot(p.x - q.x, p.y - q.y);
}

/// Segments with a bucket grid, to find quickly whether a point is within `margin` of any of them.
class SegmentProximity {
 public:
  SegmentProximity(const Paths& rings, double margin) : margin_(margin) {
    for (const Path& ring : rings) {
      for (std::size_t i = 0; i < ring.size(); ++i) {
        segments_.push_back({ring[i], ring[(i + 1) % ring.size()]});
      }
    }
    if (segments_.empty()) return;
    lo_ = hi_ = segments_[0].a;
    for (const Segment& s : segments_) {
      for (Point q : {s.a, s.b}) {
        lo_ = glm::min(lo_, q);
        hi_ = glm::max(hi_, q);
      }
    }
    lo_ -= Point(margin_);
    hi_ += Point(margin_);
    cells_ = std::max<std::size_t>(1, std::size_t(std::sqrt(double(segments_.size()))));
    buckets_.assign(cells_ * cells_, {});
    for (std::size_t i = 0; i < segments_.size(); ++i) {
      const Segment& s = segments_[i];
      const auto [x0, y0] = cell(glm::min(s.a, s.b) - Point(margin_));
      const auto [x1, y1] = cell(glm::max(s.a, s.b) + Point(margin_));
      for (std::size_t y = y0; y <= y1; ++y) {
        for (std::size_t x = x0; x <= x1; ++x) buckets_[y * cells_ + x].push_back(i);
      }
    }
  }

  /// True when p is within the margin of some segment.
  [[nodiscard]] bool near(Point p) const {
    if (segments_.empty() || p.x < lo_.x || p.y < lo_.y || p.x > hi_.x || p.y > hi_.y) {
      return false;
    }
    const auto [x, y] = cell(p);
    for (std::size_t i : buckets_[y * cells_ + x]) {
      if (distanceToSegment(p, segments_[i].a, segments_[i].b) <= margin_) return true;
    }
    return false;
  }

 private:
  struct Segment {
    Point a, b;
  };
  [[nodiscard]] std::pair<std::size_t, std::size_t> cell(Point p) const {
    const Point size = hi_ - lo_;
    auto index = [&](double v, double lo, double extent) {
      if (!(extent > 0)) return std::size_t{0};
      const double f = (v - lo) / extent * double(cells_);
      return std::min(cells_ - 1, std::size_t(std::clamp(f, 0.0, double(cells_ - 1))));
    };
    return {index(p.x, lo_.x, size.x), index(p.y, lo_.y, size.y)};
  }

  double margin_;
  std::vector<Segment> segments_;
  Point lo_{0}, hi_{0};
  std::size_t cells_ = 1;
  std::vector<std::vector<std::size_t>> buckets_;
};

}  // namespace roiclip::conformance
