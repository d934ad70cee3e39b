// SPDX-License-Identifier: MIT
// The region-of-interest case without a sweep: a simple ring (ringIsSimple()) intersected with a
// strictly convex ring, by Weiler-Atherton on the two boundaries.
//
// When no vertex of the simple ring S lies on the boundary of the convex ring C, no edge of S
// runs along a side line of C and none passes through a vertex of C, every meeting of the two
// boundaries is a transversal crossing at a point of its own (S does not touch itself). Along S,
// the crossings alternate between entering and leaving C; along the boundary of C, between leaving
// and entering. Both rings taken counter-clockwise, the boundary of S AND C runs along S from each
// entering crossing to the next crossing (a leaving one), then along C to the next crossing on
// C's boundary (an entering one), and so on round. Each such ring is simple and the rings are
// disjoint; S AND C has no holes (a hole would be a bounded part of the complement of S or of
// C, and neither has one). Without crossings, S AND C is S, C or empty. O(n m + k log k) for n
// vertices of S, m of C and k crossings. A ring, simple or not, that lies on the outer side of
// one side line of C gives nothing. Any other configuration (a ring that is not simple, a vertex
// on C's boundary, an edge through a corner) returns false: the general path resolves it.
#include <algorithm>

#include "convex_sides.hpp"
#include "output.hpp"
#include "pipeline.hpp"
#include "workspace.hpp"

namespace roiclip::detail {
namespace {

using Crossing = BoundaryCrossing;

// Orders two points on the segment a -> b by their distance from a.
bool beforeAlong(IPoint a, IPoint b, const XPoint& p, const XPoint& q) {
  const int c = compareInBox(p, q);
  return a < b ? c < 0 : c > 0;
}

// Output as stages 1 to 4 emit it: each ring counter-clockwise from its lexicographically smallest
// vertex, reversed (roiclip's orientation); polygons in the order of those smallest vertices.
PolygonSet emit(WeilerScratch& w, const Grid& grid) {
  const std::size_t ringCount = w.ringStart.size() - 1;
  w.lowest.clear();
  w.order.clear();
  for (std::size_t r = 0; r < ringCount; ++r) {
    std::size_t first = w.ringStart[r];
    for (std::size_t i = first + 1; i < w.ringStart[r + 1]; ++i) {
      if (lessInBox(w.points[i], w.points[first])) first = i;
    }
    w.lowest.push_back(first);
    w.order.push_back(r);
  }
  std::sort(w.order.begin(), w.order.end(), [&](std::size_t a, std::size_t b) {
    return lessInBox(w.points[w.lowest[a]], w.points[w.lowest[b]]);
  });
  const OutputFrame frame(grid);
  PolygonSet result;
  result.polygons.reserve(ringCount);
  for (const std::size_t r : w.order) {
    const std::size_t begin = w.ringStart[r], n = w.ringStart[r + 1] - begin;
    const std::size_t first = w.lowest[r] - begin;
    Path path = outputRing(
        n, [&](std::size_t k) { return frame.point(w.points[begin + (first + n - 1 - k) % n]); });
    if (path.size() >= 3) result.polygons.emplace_back().outer = std::move(path);
  }
  return result;
}

// Whether grid point p lies inside the simple ring (p on no edge of it): crossing parity.
bool insideRing(const CcwRing& s, IPoint p) {
  bool in = false;
  for (int k = 0, n = s.size(); k < n; ++k) {
    IPoint a = s[k], b = s[(k + 1) % n];
    if ((a.y > p.y) == (b.y > p.y)) continue;
    if (a.y > b.y) std::swap(a, b);
    if (orientInGrid(a, b, p) > 0) in = !in;  // the edge passes right of p, upwards
  }
  return in;
}

}  // namespace

bool ringsInsideConvex(const Rings& rings, const std::vector<IPoint>& convex,
                       int convexOrientation) {
  if (convex.size() > std::size_t(kMaxSides)) return false;
  const SideLines sides(convex, convexOrientation);
  for (const std::vector<IPoint>& ring : rings) {
    for (const IPoint& p : ring) {
      const auto [left, zeros] = sides.classify(p);
      if ((left | zeros) != sides.all()) return false;
    }
  }
  return true;
}

bool intersectSimpleConvex(const std::vector<IPoint>& ring, FillRule rule,
                           const std::vector<IPoint>& convex, int convexOrientation,
                           const Grid& grid, ChainScratch& chains, WeilerScratch& w,
                           PolygonSet& out) {
  out = {};
  const int n = int(ring.size()), m = int(convex.size());
  // A ring that crosses itself with a loop (rotation index not +-1) leaves at once, before the
  // vertex test; one outside C does after it, and the rotation index costs it less.
  if (n < 3 || m > kMaxSides || !turnsOnce(ring)) return false;
  // The orientation, if S is simple (asked below, after the cheaper test of its vertices).
  const bool ccw = lowestVertex(ring).ccw;
  const CcwRing s{&ring, !ccw}, c{&convex, convexOrientation < 0};

  // Which side of each side line of C every vertex of S lies on: bit j of left[k] when strictly
  // left of side j, bit j of onLine[k] when on its line. A vertex on a side line outside C (on
  // the line's extension: strictly right of another side) counts as right of it; an edge from
  // it crosses that line only there, outside the side.
  std::vector<unsigned>& left = w.left;
  std::vector<unsigned>& onLine = w.onLine;
  left.resize(std::size_t(n));
  onLine.resize(std::size_t(n));
  const SideLines sides(convex, convexOrientation);
  const unsigned all = sides.all();
  unsigned anyLeft = 0;  // the sides some vertex lies strictly left of
  unsigned anyOn = 0;    // the side lines some vertex lies on
  for (int k = 0; k < n; ++k) {
    const auto [bits, zeros] = sides.classify(ring[std::size_t(ccw ? k : n - 1 - k)]);
    left[std::size_t(k)] = bits;
    onLine[std::size_t(k)] = zeros;
    anyLeft |= bits;
    anyOn |= zeros;
  }
  // No vertex strictly left of some side: the ring lies in that side's closed outer half-plane,
  // and so does every point it winds around, simple or not. Nothing of it is in C.
  if (anyLeft != all) return true;
  bool onBoundary = false;    // some vertex on C's boundary
  bool everyInClosed = true;  // every vertex in C or on its boundary
  for (int k = 0; anyOn != 0 && k < n; ++k) {
    const bool inClosed = (left[std::size_t(k)] | onLine[std::size_t(k)]) == all;
    onBoundary = onBoundary || (onLine[std::size_t(k)] != 0 && inClosed);
    everyInClosed = everyInClosed && inClosed;
  }
  if (onBoundary) {
    // A simple ring in C that touches its boundary (a tag's square at a corner of the ROI): it
    // fills what it fills. Crossing C there: the general path.
    if (!everyInClosed || !ringIsSimple(ring, chains, /*turnsChecked=*/true)) return false;
    out = simpleRingRegion(ring, rule, grid);
    return true;
  }
  if (!ringIsSimple(ring, chains, /*turnsChecked=*/true)) return false;
  if (!isFilled(rule, ccw ? 1 : -1)) return true;  // S fills nothing under its rule

  std::vector<Crossing>& crossings = w.crossings;
  crossings.clear();
  for (int k = 0; k < n; ++k) {
    const std::size_t kq = std::size_t((k + 1) % n);
    const unsigned lp = left[std::size_t(k)], lq = left[kq];
    if (lp == all && lq == all) continue;  // both ends in C: the edge lies in C
    if ((onLine[std::size_t(k)] & onLine[kq]) != 0) return false;  // along a side's line
    const IPoint p = s[k], q = s[(k + 1) % n];
    const std::size_t before = crossings.size();
    for (unsigned changed = lp ^ lq; changed != 0; changed &= changed - 1) {
      const int j = __builtin_ctz(changed);
      const IPoint a = c[j], b = c[(j + 1) % m];
      const int oa = orientInGrid(p, q, a), ob = orientInGrid(p, q, b);
      if (oa == 0 || ob == 0) return false;  // through a corner of C
      if (oa == ob) continue;                // crosses the side's line outside the side
      Crossing x;
      if (!lineIntersection(p, q, a, b, x.x)) return false;
      x.edge = k;
      x.side = j;
      x.entering = ((lq >> j) & 1U) != 0;
      crossings.push_back(x);
    }
    std::sort(crossings.begin() + std::ptrdiff_t(before), crossings.end(),
              [&](const Crossing& u, const Crossing& v) { return beforeAlong(p, q, u.x, v.x); });
  }

  if (crossings.empty()) {
    if (left[0] == all) {
      out = simpleRingRegion(ring, FillRule::NonZero, grid);  // S lies in C
    } else if (insideRing(s, c[0])) {
      out = simpleRingRegion(convex, FillRule::NonZero, grid);  // C lies in S
    }
    return true;
  }
  const std::size_t kCount = crossings.size();
  if (kCount % 2 != 0) return false;
  // Crossings along C's boundary: by side, then along it.
  std::vector<int>& alongC = w.alongC;
  alongC.resize(kCount);
  for (std::size_t i = 0; i < kCount; ++i) alongC[i] = int(i);
  std::sort(alongC.begin(), alongC.end(), [&](int u, int v) {
    const Crossing &a = crossings[std::size_t(u)], &b = crossings[std::size_t(v)];
    if (a.side != b.side) return a.side < b.side;
    return beforeAlong(c[a.side], c[(a.side + 1) % m], a.x, b.x);
  });
  std::vector<int>& rankOnC = w.rankOnC;
  rankOnC.resize(kCount);
  for (std::size_t i = 0; i < kCount; ++i) rankOnC[std::size_t(alongC[i])] = int(i);

  w.used.assign(kCount, 0);
  w.points.clear();
  w.ringStart.assign(1, 0);
  for (std::size_t start = 0; start < kCount; ++start) {
    if (!crossings[start].entering || w.used[start]) continue;
    std::size_t at = start;
    do {
      // Entering at `at`: along S to the next crossing, which leaves C.
      w.used[at] = 1;
      const Crossing& in = crossings[at];
      const std::size_t leaveAt = (at + 1) % kCount;
      const Crossing& leave = crossings[leaveAt];
      if (leave.entering) return false;
      w.points.push_back(in.x);
      int steps = (leave.edge - in.edge + n) % n;
      if (steps == 0 && leaveAt <= at) steps = n;  // round the whole ring on one edge
      for (int t = 1; t <= steps; ++t) w.points.emplace_back(s[(in.edge + t) % n]);
      w.points.push_back(leave.x);
      // Along C from the leaving crossing to the next crossing on C, which enters.
      const std::size_t rank = std::size_t(rankOnC[leaveAt]);
      const std::size_t nextRank = (rank + 1) % kCount;
      const std::size_t enterAt = std::size_t(alongC[nextRank]);
      const Crossing& enter = crossings[enterAt];
      if (!enter.entering) return false;
      int corners = (enter.side - leave.side + m) % m;
      if (corners == 0 && nextRank <= rank) corners = m;
      for (int t = 1; t <= corners; ++t) w.points.emplace_back(c[(leave.side + t) % m]);
      at = enterAt;
    } while (at != start);
    w.ringStart.push_back(w.points.size());
  }
  out = emit(w, grid);
  return true;
}

}  // namespace roiclip::detail
