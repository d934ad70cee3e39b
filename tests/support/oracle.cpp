// SPDX-License-Identifier: MIT
// The exact parts of the test oracle (see oracle.hpp), compiled once for every test and fuzz
// target.
#include "oracle.hpp"

#include <cstdlib>
#include <fstream>

#include <boost/multiprecision/cpp_int.hpp>

namespace roiclip::testing {
namespace {

// v as an integer count of 1/4096 px when it is one and small enough that the orientation
// products fit 128 bits (|v| < 2^48 px, far beyond roiclip's range).
bool onOracleGrid(double v, std::int64_t& units) {
  const double u = v * kOracleScale;  // exact: scaling by a power of two
  if (!(std::fabs(u) < 0x1p60) || u != std::floor(u)) return false;
  units = std::int64_t(u);
  return true;
}

int exactOrientation(Point a, Point b, Point p) {
  using boost::multiprecision::cpp_rational;
  const cpp_rational exact =
      (cpp_rational(b.x) - cpp_rational(a.x)) * (cpp_rational(p.y) - cpp_rational(a.y)) -
      (cpp_rational(b.y) - cpp_rational(a.y)) * (cpp_rational(p.x) - cpp_rational(a.x));
  return exact > 0 ? 1 : (exact < 0 ? -1 : 0);
}

// Sum of the winding numbers of `rings` around p. With `onBoundary` given, p on an edge sets it
// and ends the count; without, p must not lie on an edge.
long long windingSum(const Path* rings, std::size_t count, Point p, bool* onBoundary) {
  long long w = 0;
  for (std::size_t r = 0; r < count; ++r) {
    const Path& ring = rings[r];
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Point a = ring[i];
      const Point b = ring[(i + 1) % n];
      const bool straddles = a.y <= p.y ? b.y > p.y : b.y <= p.y;
      if (onBoundary != nullptr && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
          std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y)) {
        const int o = orientation(a, b, p);
        if (o == 0) {
          *onBoundary = true;
          return w;
        }
        if (straddles) w += a.y <= p.y ? (o > 0) : -(o < 0);
        continue;
      }
      if (!straddles) continue;
      if (a.y <= p.y) {
        if (orientation(a, b, p) > 0) ++w;
      } else if (orientation(a, b, p) < 0) {
        --w;
      }
    }
  }
  return w;
}

}  // namespace

int orientation(Point a, Point b, Point p) {
  std::int64_t ax, ay, bx, by, px, py;
  if (onOracleGrid(a.x, ax) && onOracleGrid(a.y, ay) && onOracleGrid(b.x, bx) &&
      onOracleGrid(b.y, by) && onOracleGrid(p.x, px) && onOracleGrid(p.y, py)) {
    const __int128 cr = __int128(bx - ax) * (py - ay) - __int128(by - ay) * (px - ax);
    return (cr > 0) - (cr < 0);
  }
  const double left = (b.x - a.x) * (p.y - a.y);
  const double right = (b.y - a.y) * (p.x - a.x);
  const double det = left - right;
  const double bound = 3.3306690738754716e-16 * (std::fabs(left) + std::fabs(right));
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return exactOrientation(a, b, p);
}

long long windingNumber(const Path& ring, Point p) { return windingSum(&ring, 1, p, nullptr); }

long long windingNumber(const Paths& rings, Point p) {
  return windingSum(rings.data(), rings.size(), p, nullptr);
}

std::optional<long long> exactWinding(const Paths& paths, Point p) {
  bool onBoundary = false;
  const long long w = windingSum(paths.data(), paths.size(), p, &onBoundary);
  if (onBoundary) return std::nullopt;
  return w;
}

SegmentProximity::SegmentProximity(const Paths& rings, double margin) : margin_(margin) {
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

bool SegmentProximity::near(Point p) const {
  if (segments_.empty() || p.x < lo_.x || p.y < lo_.y || p.x > hi_.x || p.y > hi_.y) {
    return false;
  }
  const auto [x, y] = cell(p);
  for (std::size_t i : buckets_[y * cells_ + x]) {
    if (distanceToSegment(p, segments_[i].a, segments_[i].b) <= margin_) return true;
  }
  return false;
}

std::pair<std::size_t, std::size_t> SegmentProximity::cell(Point p) const {
  const Point size = hi_ - lo_;
  auto index = [&](double v, double lo, double extent) {
    if (!(extent > 0)) return std::size_t{0};
    const double f = (v - lo) / extent * double(cells_);
    return std::min(cells_ - 1, std::size_t(std::clamp(f, 0.0, double(cells_ - 1))));
  };
  return {index(p.x, lo_.x, size.x), index(p.y, lo_.y, size.y)};
}

void saveFixture(const std::string& file, const std::string& note, const Paths& subject,
                 const Paths* clipPaths, const char* op, FillRule subjectRule, FillRule clipRule) {
  std::ofstream f(file);
  f << "{\"note\": \"" << note << "\",\n \"subject\": " << describe(subject);
  if (clipPaths != nullptr) f << ",\n \"clip\": " << describe(*clipPaths);
  f << ",\n \"op\": \"" << op << "\", \"subjectFillRule\": \"" << toString(subjectRule)
    << "\", \"clipFillRule\": \"" << toString(clipRule) << "\"}\n";
}

std::string fixtureDir() {
  const char* env = std::getenv("ROICLIP_FIXTURE_OUT");
  return env != nullptr ? std::string(env) : std::string(ROICLIP_TEST_DATA) + "/core";
}

double exactSlabArea(const std::vector<const Paths*>& inputs,
                     const std::function<bool(const std::vector<long long>&)>& inside) {
  using Q = boost::multiprecision::cpp_rational;
  struct Edge {
    Q ax, ay, bx, by;  // a.x < b.x
    int operand, dir;
  };
  std::vector<Edge> edges;
  std::vector<Q> xs;
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    for (const Path& path : *inputs[k]) {
      for (std::size_t i = 0; i < path.size(); ++i) {
        const Point a = path[i], b = path[(i + 1) % path.size()];
        xs.emplace_back(a.x);
        if (a.x < b.x) edges.push_back({Q(a.x), Q(a.y), Q(b.x), Q(b.y), int(k), +1});
        if (a.x > b.x) edges.push_back({Q(b.x), Q(b.y), Q(a.x), Q(a.y), int(k), -1});
      }
    }
  }
  for (std::size_t i = 0; i < edges.size(); ++i) {
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const Edge& e = edges[i];
      const Edge& f = edges[j];
      const Q rx = e.bx - e.ax, ry = e.by - e.ay, sx = f.bx - f.ax, sy = f.by - f.ay;
      const Q den = rx * sy - ry * sx;
      if (den == 0) continue;
      const Q t = ((f.ax - e.ax) * sy - (f.ay - e.ay) * sx) / den;
      const Q u = ((f.ax - e.ax) * ry - (f.ay - e.ay) * rx) / den;
      if (t > 0 && t < 1 && u > 0 && u < 1) xs.push_back(e.ax + t * rx);
    }
  }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  Q area = 0;
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    const Q& x0 = xs[i];
    const Q& x1 = xs[i + 1];
    const Q xm = (x0 + x1) / 2;
    struct Cut {
      Q y0, ym, y1;
      int operand, dir;
    };
    std::vector<Cut> cuts;
    for (const Edge& e : edges) {
      if (e.ax <= xm && xm < e.bx) {
        const auto y = [&](const Q& x) {
          return e.ay + (e.by - e.ay) * (x - e.ax) / (e.bx - e.ax);
        };
        cuts.push_back({y(x0), y(xm), y(x1), e.operand, e.dir});
      }
    }
    std::sort(cuts.begin(), cuts.end(), [](const Cut& a, const Cut& b) { return a.ym < b.ym; });
    std::vector<long long> w(inputs.size(), 0);
    for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
      w[std::size_t(cuts[c].operand)] += cuts[c].dir;
      if (inside(w)) {
        area += ((cuts[c + 1].y0 - cuts[c].y0) + (cuts[c + 1].y1 - cuts[c].y1)) * (x1 - x0) / 2;
      }
    }
  }
  return area.convert_to<double>();
}

}  // namespace roiclip::testing
