// SPDX-License-Identifier: MIT
// The exact parts of the test oracle (see oracle.hpp), compiled once for every test and fuzz
// target.
#include "oracle.hpp"

#include <cstdlib>
#include <fstream>
#include <optional>

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

namespace {

using Rational = boost::multiprecision::cpp_rational;

// An input edge of exactRegionArea(), left to right (vertical edges bound no area).
struct RegionEdge {
  Point a, b;  // a.x < b.x
  int operand, dir;
  std::size_t first = 0, last = 0;  // active in the slabs [first, last) of the x list
  // Bound on |double y(xm) - exact y(xm)| per unit of the slab's midpoint error, and absolute.
  double slope = 0, yError = 0;
};

// The exact y of edge e at x.
Rational yAt(const RegionEdge& e, const Rational& x) {
  if (x == Rational(e.a.x)) return Rational(e.a.y);
  if (x == Rational(e.b.x)) return Rational(e.b.y);
  return Rational(e.a.y) + (Rational(e.b.y) - Rational(e.a.y)) * (x - Rational(e.a.x)) /
                               (Rational(e.b.x) - Rational(e.a.x));
}

// x of the proper crossing of e and f (each one's endpoints strictly on both sides of the
// other), if any; touching and overlapping edges meet at an endpoint, whose x is listed anyway.
std::optional<Rational> properCrossingX(const RegionEdge& e, const RegionEdge& f) {
  if (orientation(e.a, e.b, f.a) * orientation(e.a, e.b, f.b) >= 0) return std::nullopt;
  if (orientation(f.a, f.b, e.a) * orientation(f.a, f.b, e.b) >= 0) return std::nullopt;
  const Rational ax(e.a.x), ay(e.a.y), rx = Rational(e.b.x) - ax, ry = Rational(e.b.y) - ay;
  const Rational cx(f.a.x), cy(f.a.y), sx = Rational(f.b.x) - cx, sy = Rational(f.b.y) - cy;
  const Rational t = ((cx - ax) * sy - (cy - ay) * sx) / (rx * sy - ry * sx);
  return ax + t * rx;
}

}  // namespace

double exactRegionArea(const std::vector<const Paths*>& inputs,
                       const std::function<bool(const std::vector<long long>&)>& inside) {
  constexpr double kEps = 0x1p-52;
  std::vector<RegionEdge> edges;
  std::vector<double> vertexXs;
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    for (const Path& path : *inputs[k]) {
      for (std::size_t i = 0; i < path.size(); ++i) {
        const Point a = path[i], b = path[(i + 1) % path.size()];
        vertexXs.push_back(a.x);
        if (a.x < b.x) edges.push_back({a, b, int(k), +1});
        if (a.x > b.x) edges.push_back({b, a, int(k), -1});
      }
    }
  }
  // Every x where the order of the edges may change: vertices and proper crossings.
  std::vector<Rational> xs;
  std::sort(vertexXs.begin(), vertexXs.end());
  vertexXs.erase(std::unique(vertexXs.begin(), vertexXs.end()), vertexXs.end());
  for (double x : vertexXs) xs.emplace_back(x);
  std::vector<std::size_t> byLeft(edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i) byLeft[i] = i;
  std::sort(byLeft.begin(), byLeft.end(),
            [&](std::size_t i, std::size_t j) { return edges[i].a.x < edges[j].a.x; });
  for (std::size_t n = 0; n < byLeft.size(); ++n) {
    const RegionEdge& e = edges[byLeft[n]];
    const double eLo = std::min(e.a.y, e.b.y), eHi = std::max(e.a.y, e.b.y);
    for (std::size_t m = n + 1; m < byLeft.size() && edges[byLeft[m]].a.x <= e.b.x; ++m) {
      const RegionEdge& f = edges[byLeft[m]];
      if (std::max(f.a.y, f.b.y) < eLo || std::min(f.a.y, f.b.y) > eHi) continue;
      if (auto x = properCrossingX(e, f)) xs.push_back(std::move(*x));
    }
  }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  std::vector<double> xd(xs.size());
  for (std::size_t i = 0; i < xs.size(); ++i) xd[i] = xs[i].convert_to<double>();

  for (RegionEdge& e : edges) {
    // a.x and b.x are listed exactly; their doubles are themselves.
    e.first = std::size_t(std::lower_bound(xs.begin(), xs.end(), Rational(e.a.x)) - xs.begin());
    e.last = std::size_t(std::lower_bound(xs.begin(), xs.end(), Rational(e.b.x)) - xs.begin());
    const double dy = e.b.y - e.a.y;
    e.slope = std::fabs(dy / (e.b.x - e.a.x));
    e.yError = 8 * kEps * (std::fabs(e.a.y) + std::fabs(e.b.y) + std::fabs(dy));
  }
  std::sort(byLeft.begin(), byLeft.end(),
            [&](std::size_t i, std::size_t j) { return edges[i].first < edges[j].first; });

  // Per edge: the sign with which it bounds the region in the current run of slabs, and where
  // the run began.
  std::vector<int> runSign(edges.size(), 0);
  std::vector<std::size_t> runStart(edges.size(), 0);
  Rational area = 0;
  const auto closeRun = [&](std::size_t e, std::size_t end) {
    if (runSign[e] == 0) return;
    const Rational &x0 = xs[runStart[e]], &x1 = xs[end];
    area += runSign[e] * (x1 - x0) * (yAt(edges[e], x0) + yAt(edges[e], x1)) / 2;
  };

  std::vector<std::size_t> active;
  std::size_t nextEdge = 0;
  struct Cut {
    std::size_t edge;
    double y, error;
  };
  std::vector<Cut> cuts;
  // y at the slab's exact midpoint, per edge, computed only where the doubles cannot tell.
  std::vector<std::optional<Rational>> exactY(edges.size());
  std::vector<long long> w(inputs.size(), 0);
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    for (std::size_t e : active) {
      if (edges[e].last == i) closeRun(e, i);
    }
    active.erase(std::remove_if(active.begin(), active.end(),
                                [&](std::size_t e) { return edges[e].last == i; }),
                 active.end());
    for (; nextEdge < byLeft.size() && edges[byLeft[nextEdge]].first == i; ++nextEdge) {
      active.push_back(byLeft[nextEdge]);
    }
    // Order at the slab's midpoint xm (no two edges cross inside the slab). The double xmd is
    // within 4 eps |xm| of xm; each edge's double y within yError + slope * that of its y(xm).
    const double xmd = 0.5 * (xd[i] + xd[i + 1]);
    const double xError = 4 * kEps * std::max(std::fabs(xd[i]), std::fabs(xd[i + 1])) + 0x1p-1074;
    const Rational xm = (xs[i] + xs[i + 1]) / 2;
    cuts.clear();
    for (std::size_t e : active) {
      const RegionEdge& edge = edges[e];
      const double y =
          edge.a.y + (edge.b.y - edge.a.y) * ((xmd - edge.a.x) / (edge.b.x - edge.a.x));
      cuts.push_back({e, y, edge.yError + 2 * edge.slope * xError});
      exactY[e].reset();
    }
    const auto exact = [&](const Cut& c) -> const Rational& {
      if (!exactY[c.edge]) exactY[c.edge] = yAt(edges[c.edge], xm);
      return *exactY[c.edge];
    };
    std::sort(cuts.begin(), cuts.end(), [&](const Cut& p, const Cut& q) {
      const double error = p.error + q.error;
      if (std::isfinite(error) && std::fabs(p.y - q.y) > error) return p.y < q.y;
      return exact(p) < exact(q);
    });
    // Edge c bounds the region from above where the interval below it is filled, from below
    // where the interval above it is: sign f(below) - f(above). Outside every edge w = 0.
    std::fill(w.begin(), w.end(), 0);
    bool below = false;
    for (std::size_t c = 0; c < cuts.size(); ++c) {
      const RegionEdge& edge = edges[cuts[c].edge];
      w[std::size_t(edge.operand)] += edge.dir;
      const bool above = c + 1 < cuts.size() && inside(w);
      const int sign = int(below) - int(above);
      const std::size_t e = cuts[c].edge;
      if (i == edge.first) {
        runSign[e] = sign;
        runStart[e] = i;
      } else if (sign != runSign[e]) {
        closeRun(e, i);
        runSign[e] = sign;
        runStart[e] = i;
      }
      below = above;
    }
  }
  for (std::size_t e : active) closeRun(e, xs.size() - 1);
  return area.convert_to<double>();
}

}  // namespace roiclip::testing
