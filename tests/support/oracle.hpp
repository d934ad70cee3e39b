// SPDX-License-Identifier: MIT
// The one test oracle of roiclip (tests/core, tests/conformance, tests/fuzz): exact winding
// numbers of any double input at sample points, point-in-result of the output, area by vertical
// slabs, and structural checks of output rings. Nothing here uses the library's own snapping,
// predicates or pipeline, so it can judge roiclip's results and other engines' expectations.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <boost/pending/disjoint_sets.hpp>
#include <glm/common.hpp>

#include <roiclip/roiclip.hpp>

namespace roiclip::testing {

/// Sample points of the tests live on multiples of 1/4096 px and their inputs on multiples of
/// 1/256 px: scaled by kOracleScale every coordinate is an integer, and orientation() takes an
/// exact 128-bit shortcut. Any other double is handled exactly too, only more slowly.
constexpr double kOracleScale = 4096.0;

/// Exact sign of the orientation of (a, b, p): +1 when p is left of a->b in (x, y) maths axes,
/// 0 when collinear. Exact for any finite doubles: integers on the 1/4096 px grid in 128 bits,
/// otherwise a floating-point filter (Shewchuk's bound for orient2d), then exact rationals
/// (every double is a dyadic rational).
int orientation(Point a, Point b, Point p);

/// Exact winding number of a closed ring, or of all rings together, around p; p must not lie on
/// a ring (callers keep sample points away from every edge, or use exactWinding()).
long long windingNumber(const Path& ring, Point p);
long long windingNumber(const Paths& rings, Point p);

/// Exact winding number of `paths` around `p`, or nothing when p lies on an edge.
std::optional<long long> exactWinding(const Paths& paths, Point p);

/// The boolean operation on two memberships, written out here so that the oracle does not
/// share code with the library.
inline bool combine(ClipOp op, bool s, bool c) {
  switch (op) {
    case ClipOp::Intersection:
      return s && c;
    case ClipOp::Union:
      return s || c;
    case ClipOp::Difference:
      return s && !c;
    case ClipOp::Xor:
      return s != c;
  }
  return false;
}

/// Winding number of one ring around p in floating point (for output rings).
inline int ringWinding(const Path& ring, Point p) {
  int w = 0;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point a = ring[i], b = ring[(i + 1) % n];
    const double cr = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
    if (a.y <= p.y) {
      if (b.y > p.y && cr > 0) ++w;
    } else if (b.y <= p.y && cr < 0) {
      --w;
    }
  }
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

/// Distance from p to the nearest edge of any path (closed rings).
inline double distanceToEdges(const Paths& paths, Point p) {
  double best = INFINITY;
  for (const Path& path : paths) {
    const std::size_t n = path.size();
    for (std::size_t i = 0; i < n; ++i) {
      best = std::min(best, distanceToSegment(p, path[i], path[(i + 1) % n]));
    }
  }
  return best;
}

/// The edges of closed rings in a bucket grid, to find quickly whether a point is within
/// `margin` of any of them (large inputs, where distanceToEdges() would be quadratic).
class SegmentProximity {
 public:
  SegmentProximity(const Paths& rings, double margin);

  /// True when p is within the margin of some segment.
  [[nodiscard]] bool near(Point p) const;

 private:
  struct Segment {
    Point a, b;
  };
  [[nodiscard]] std::pair<std::size_t, std::size_t> cell(Point p) const;

  double margin_;
  std::vector<Segment> segments_;
  Point lo_{0}, hi_{0};
  std::size_t cells_ = 1;
  std::vector<std::vector<std::size_t>> buckets_;
};

/// Structural problems of a result, empty when there are none: ring sizes, orientations,
/// repeated vertices, crossing edges, parent links.
inline std::string structureProblems(const PolygonSet& set) {
  std::ostringstream out;
  std::vector<const Path*> rings;
  for (std::size_t i = 0; i < set.polygons.size(); ++i) {
    const Polygon& p = set.polygons[i];
    if (p.outer.size() < 3) out << "polygon " << i << ": outer ring has < 3 vertices\n";
    if (!(signedArea(p.outer) < 0)) out << "polygon " << i << ": outer ring not negative\n";
    for (std::size_t h = 0; h < p.holes.size(); ++h) {
      if (p.holes[h].size() < 3) out << "polygon " << i << " hole " << h << ": < 3 vertices\n";
      if (!(signedArea(p.holes[h]) > 0))
        out << "polygon " << i << " hole " << h << ": not positive\n";
    }
    if (p.parent >= int(i)) out << "polygon " << i << ": parent does not come first\n";
    if (p.parent >= 0 &&
        (p.parentHole < 0 || p.parentHole >= int(set.polygons[p.parent].holes.size()))) {
      out << "polygon " << i << ": bad parentHole\n";
    }
    rings.push_back(&p.outer);
    for (const Path& h : p.holes) rings.push_back(&h);
    // A connected interior (OGC): the polygon's rings touching at vertices join in a forest
    // (around a cycle of touches, the interior falls apart).
    const std::size_t ringCount = 1 + p.holes.size();
    boost::disjoint_sets_with_storage<> joined(ringCount);
    std::map<std::pair<double, double>, std::size_t> firstRing;
    bool cycle = false;
    for (std::size_t r = 0; r < ringCount && !cycle; ++r) {
      for (const Point& v : r == 0 ? p.outer : p.holes[r - 1]) {
        const auto [at, fresh] = firstRing.emplace(std::make_pair(v.x, v.y), r);
        if (fresh || at->second == r) continue;
        const std::size_t a = joined.find_set(at->second), b = joined.find_set(r);
        cycle = a == b;
        if (cycle) break;
        joined.link(a, b);
      }
    }
    if (cycle) out << "polygon " << i << ": interior not connected (rings touch in a cycle)\n";
  }
  // Every ring simple: no repeated vertex, no two edges crossing or overlapping (all rings
  // against all, since rings may only touch at vertices). Quadratic: small results only.
  struct Seg {
    Point a, b;
    std::size_t ring;
  };
  std::vector<Seg> segs;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const Path& ring = *rings[r];
    for (std::size_t i = 0; i < ring.size(); ++i) {
      for (std::size_t j = i + 1; j < ring.size(); ++j) {
        if (ring[i] == ring[j]) out << "ring " << r << ": vertex " << i << " repeats\n";
      }
      segs.push_back({ring[i], ring[(i + 1) % ring.size()], r});
    }
  }
  if (segs.size() > 4000) return out.str();
  auto orient = [](Point a, Point b, Point c) {
    const double v = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    const double tol = 1e-9 * (std::fabs(b.x - a.x) + std::fabs(b.y - a.y)) *
                       (std::fabs(c.x - a.x) + std::fabs(c.y - a.y) + 1.0);
    return v > tol ? 1 : (v < -tol ? -1 : 0);
  };
  for (std::size_t i = 0; i < segs.size(); ++i) {
    for (std::size_t j = i + 1; j < segs.size(); ++j) {
      const Seg& s = segs[i];
      const Seg& t = segs[j];
      const int o1 = orient(s.a, s.b, t.a), o2 = orient(s.a, s.b, t.b);
      const int o3 = orient(t.a, t.b, s.a), o4 = orient(t.a, t.b, s.b);
      if (o1 * o2 < 0 && o3 * o4 < 0) {
        out << "edges cross: ring " << s.ring << " and ring " << t.ring << "\n";
        return out.str();
      }
      // Collinear overlap of positive length.
      if (o1 == 0 && o2 == 0) {
        const Point d = s.b - s.a;
        auto proj = [&](Point q) { return (q - s.a).x * d.x + (q - s.a).y * d.y; };
        const double len = proj(s.b);
        const double lo = std::max(0.0, std::min(proj(t.a), proj(t.b)));
        const double hi = std::min(len, std::max(proj(t.a), proj(t.b)));
        if (hi - lo > 1e-9 * len) {
          out << "edges overlap: ring " << s.ring << " and ring " << t.ring << "\n";
          return out.str();
        }
      }
    }
  }
  return out.str();
}

/// Result of checking a result against the expected region at sample points.
struct SampleReport {
  int checked = 0;
  int mismatches = 0;
  std::string firstMismatch;
};

/// Compares, at `samples` random points in the box [lo, hi]^2 (multiples of 1/4096 px, off
/// every input edge), whether p is in the result with what `expected(p)` says, where the
/// expected function gets exact winding numbers. Also checks per-polygon windings are 0 or 1
/// and that islands lie in their parent hole.
template <class Expected>
SampleReport sampleRegion(const PolygonSet& result, const std::vector<const Paths*>& inputs,
                          Expected expected, double lo, double hi, int samples,
                          std::uint32_t seed) {
  SampleReport report;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coord(lo, hi);
  for (int s = 0; s < samples; ++s) {
    const Point p{std::round(coord(rng) * kOracleScale) / kOracleScale,
                  std::round(coord(rng) * kOracleScale) / kOracleScale};
    std::vector<long long> w;
    bool onEdge = false;
    for (const Paths* in : inputs) {
      const auto wi = exactWinding(*in, p);
      if (!wi) {
        onEdge = true;
        break;
      }
      if (distanceToEdges(*in, p) < 1e-6) onEdge = true;
      w.push_back(*wi);
    }
    if (onEdge) continue;
    ++report.checked;
    int inside = 0;
    for (std::size_t i = 0; i < result.polygons.size(); ++i) {
      const Polygon& poly = result.polygons[i];
      int wp = -ringWinding(poly.outer, p);
      for (const Path& h : poly.holes) wp -= ringWinding(h, p);
      if (wp != 0 && wp != 1) {
        ++report.mismatches;
        report.firstMismatch = "polygon winding not 0/1";
      }
      if (wp == 1 && poly.parent >= 0) {
        const Path& hole = result.polygons[poly.parent].holes[poly.parentHole];
        if (ringWinding(hole, p) == 0) {
          ++report.mismatches;
          report.firstMismatch = "island outside its parent hole";
        }
      }
      inside += wp;
    }
    const bool want = expected(w);
    if ((inside == 1) != want || (inside != 0 && inside != 1)) {
      ++report.mismatches;
      if (report.firstMismatch.empty()) {
        std::ostringstream m;
        m << "at (" << p.x << ", " << p.y << ") expected " << want << " got winding " << inside;
        report.firstMismatch = m.str();
      }
    }
  }
  return report;
}

/// Area of { p : inside(w_0(p), w_1(p), ...) } computed independently of roiclip by vertical
/// slabs: between consecutive x of vertices and pairwise crossings no two edges cross, so each
/// slab is a stack of trapezoids whose winding numbers are counted from the bottom. O(n^3):
/// small inputs only.
template <class Inside>
double slabArea(const std::vector<const Paths*>& inputs, Inside inside) {
  struct Edge {
    Point a, b;  // a.x < b.x
    int operand, dir;
  };
  std::vector<Edge> edges;
  std::vector<double> xs;
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    for (const Path& path : *inputs[k]) {
      for (std::size_t i = 0; i < path.size(); ++i) {
        const Point a = path[i], b = path[(i + 1) % path.size()];
        xs.push_back(a.x);
        if (a.x < b.x) edges.push_back({a, b, int(k), +1});
        if (a.x > b.x) edges.push_back({b, a, int(k), -1});
      }
    }
  }
  for (std::size_t i = 0; i < edges.size(); ++i) {
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const Point p = edges[i].a, r = edges[i].b - edges[i].a;
      const Point q = edges[j].a, s = edges[j].b - edges[j].a;
      const double den = r.x * s.y - r.y * s.x;
      if (den == 0) continue;
      const double t = ((q.x - p.x) * s.y - (q.y - p.y) * s.x) / den;
      const double u = ((q.x - p.x) * r.y - (q.y - p.y) * r.x) / den;
      if (t > 0 && t < 1 && u > 0 && u < 1) xs.push_back(p.x + t * r.x);
    }
  }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  double area = 0;
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    const double x0 = xs[i], x1 = xs[i + 1], xm = 0.5 * (x0 + x1);
    if (!(x1 > x0)) continue;
    struct Cut {
      double y0, ym, y1;
      int operand, dir;
    };
    std::vector<Cut> cuts;
    for (const Edge& e : edges) {
      if (e.a.x <= xm && xm < e.b.x) {
        auto y = [&](double x) { return e.a.y + (e.b.y - e.a.y) * (x - e.a.x) / (e.b.x - e.a.x); };
        cuts.push_back({y(x0), y(xm), y(x1), e.operand, e.dir});
      }
    }
    std::sort(cuts.begin(), cuts.end(), [](const Cut& a, const Cut& b) { return a.ym < b.ym; });
    std::vector<long long> w(inputs.size(), 0);
    for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
      w[cuts[c].operand] += cuts[c].dir;
      if (inside(w)) {
        area += 0.5 * ((cuts[c + 1].y0 - cuts[c].y0) + (cuts[c + 1].y1 - cuts[c].y1)) * (x1 - x0);
      }
    }
  }
  return area;
}

/// The same slab integration in exact rationals (Boost cpp_rational): every vertex, crossing and
/// trapezoid exactly as the input doubles say, rounded to double once at the end. For map
/// coordinates (5e6 offsets, longitude/latitude), where slabArea()'s doubles cancel. O(n^3).
double exactSlabArea(const std::vector<const Paths*>& inputs,
                     const std::function<bool(const std::vector<long long>&)>& inside);

/// The same exact area as exactSlabArea(), bit for bit, fast enough for inputs of a few thousand
/// edges (the conformance suites): crossings are looked for only between edges whose boxes
/// overlap, by exact orientation signs, and computed as rationals only where two edges properly
/// cross; within each slab the edges are ordered by doubles wherever their error bounds keep them
/// apart (exactly otherwise); and since the slab area is the sum over its edges of +-(integral
/// of the edge's y), each edge's integral is taken exactly over the whole run of slabs in which
/// it bounds the region the same way, so rational y values are computed at run ends only.
double exactRegionArea(const std::vector<const Paths*>& inputs,
                       const std::function<bool(const std::vector<long long>&)>& inside);

/// Random polygon generators (fixed seeds by the caller).
inline Path randomPolygon(std::mt19937& rng, int n, int size) {
  std::uniform_int_distribution<int> c(0, size);
  Path p;
  for (int i = 0; i < n; ++i) p.emplace_back(c(rng), c(rng));
  return p;
}

/// A random walk on the integer grid: steps of -1/0/+1 scaled by `step`; many collinear,
/// touching and overlapping edges. Closed implicitly.
inline Path randomGridWalk(std::mt19937& rng, int n, int step, int size) {
  std::uniform_int_distribution<int> d(-1, 1);
  Path p;
  int x = size / 2, y = size / 2;
  for (int i = 0; i < n; ++i) {
    x = std::max(0, std::min(size, x + step * d(rng)));
    y = std::max(0, std::min(size, y + step * d(rng)));
    p.emplace_back(x, y);
  }
  return p;
}

/// An OpenCV-like closed pixel chain: 8-connected unit steps with a drift back to the start.
inline Path pixelChain(std::mt19937& rng, int n) {
  Path p;
  int x = 0, y = 0;
  std::uniform_int_distribution<int> d(-1, 1);
  for (int i = 0; i < n; ++i) {
    int dx = d(rng), dy = d(rng);
    const int remaining = n - i;
    if (std::abs(x) >= remaining - 1) dx = x > 0 ? -1 : (x < 0 ? 1 : 0);
    if (std::abs(y) >= remaining - 1) dy = y > 0 ? -1 : (y < 0 ? 1 : 0);
    x += dx;
    y += dy;
    p.emplace_back(x, y);
  }
  return p;
}

inline std::string describe(const Paths& paths) {
  std::ostringstream out;
  out << "[";
  for (std::size_t i = 0; i < paths.size(); ++i) {
    out << (i ? "," : "") << "[";
    for (std::size_t j = 0; j < paths[i].size(); ++j) {
      out << (j ? "," : "") << "[" << paths[i][j].x << "," << paths[i][j].y << "]";
    }
    out << "]";
  }
  out << "]";
  return out.str();
}

/// Writes a case as a fixture file in the format tests/core/fixture_test.cpp replays:
/// {"note": ..., "subject": paths, "clip": paths (optional), "op": ..., "subjectFillRule": ...,
///  "clipFillRule": ...}.
void saveFixture(const std::string& file, const std::string& note, const Paths& subject,
                 const Paths* clipPaths, const char* op, FillRule subjectRule, FillRule clipRule);

/// Folder for new failure fixtures: $ROICLIP_FIXTURE_OUT if set, else tests/data/core.
std::string fixtureDir();

/// Length of open polylines.
inline double length(const Path& line) {
  double l = 0;
  for (std::size_t i = 1; i < line.size(); ++i) {
    l += std::hypot(line[i].x - line[i - 1].x, line[i].y - line[i - 1].y);
  }
  return l;
}
inline double length(const Paths& lines) {
  double l = 0;
  for (const Path& line : lines) l += length(line);
  return l;
}

// Whether q lies on one of the polylines (within a distance far below any sample spacing).
inline bool onPolylines(const Paths& lines, Point q) {
  for (const Path& line : lines) {
    for (std::size_t i = 1; i < line.size(); ++i) {
      if (distanceToEdges({{line[i - 1], line[i]}}, q) < 1e-7) return true;
    }
  }
  return false;
}

// For q on exactly one region edge (not at a vertex): whether a side of that edge is filled,
// from the exact winding numbers one oracle unit (1/4096 px) away along the axes. Nothing when
// q is elsewhere or the neighbours do not settle it, or when another edge passes within two
// oracle units of q (the neighbours could lie beyond it: found by fuzz_clip_lines on 1/256 px
// coordinates).
inline std::optional<bool> inClosure(const Paths& region, FillRule rule, Point q) {
  if (exactWinding(region, q).has_value()) return std::nullopt;
  // Two region edges crossing at q make four sectors the axis neighbours may not all reach.
  std::optional<Point> line;
  for (const Path& path : region) {
    for (std::size_t i = 0; i < path.size(); ++i) {
      const Point a = path[i], b = path[(i + 1) % path.size()];
      if (a == q || b == q) return std::nullopt;
      if (exactWinding({{a, b}}, q).has_value()) {
        if (distanceToEdges({{a, b}}, q) < 2.0 / 4096) return std::nullopt;
        continue;
      }
      if (line && line->x * (b - a).y - line->y * (b - a).x != 0) return std::nullopt;
      line = b - a;
    }
  }
  constexpr double d = 1.0 / 4096;
  int sides = 0;
  bool filled = false;
  for (const Point offset : {Point(d, 0), Point(-d, 0), Point(0, d), Point(0, -d)}) {
    const auto w = exactWinding(region, q + offset);
    if (!w) continue;
    ++sides;
    filled = filled || isFilled(rule, *w);
  }
  if (sides < 2) return std::nullopt;
  return filled;
}

/// Strictly convex hull (monotone chain, collinear points dropped) of every vertex of `paths`,
/// as one ring; exact for coordinates on a binary grid (the tests' and fuzzers' inputs). Used to
/// send inputs down the convex fast paths.
inline Paths convexHull(const Paths& paths, bool reverse) {
  const auto cross = [](Point o, Point a, Point b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  std::vector<Point> pts;
  for (const Path& p : paths) pts.insert(pts.end(), p.begin(), p.end());
  std::sort(pts.begin(), pts.end(),
            [](Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() < 3) return {Path(pts.begin(), pts.end())};
  Path hull(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  hull.resize(k - 1);
  if (reverse) std::reverse(hull.begin(), hull.end());
  return {hull};
}

}  // namespace roiclip::testing
