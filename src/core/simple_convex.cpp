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
// one side line of C gives nothing. A vertex of S on C's boundary (on a side, or at a corner) is
// a crossing, a touch from inside (leaving and entering there) or a touch from outside, by the
// edges at it (appendCrossings()). Any other configuration (a ring that is not simple, an edge
// along a side's line or through a corner, two parts of the result meeting at a point, a ring
// around C touching every corner) returns false: the general path resolves it.
#include <algorithm>

#include "convex_sides.hpp"
#include "output.hpp"
#include "pipeline.hpp"
#include "workspace.hpp"

namespace roiclip::detail {
namespace {

using Crossing = BoundaryCrossing;

// Two points on the segment a -> b by their distance from a: -1 when p comes first, 0 at one
// point, +1 when q does.
int orderAlong(IPoint a, IPoint b, const XPoint& p, const XPoint& q) {
  const int c = compareInBox(p, q);
  return a < b ? c : -c;
}

constexpr std::size_t kBoxFirstUpTo = 512;  // vertices

// Which side of each side line of C every vertex of s lies on (into w.left and w.onLine, in s's
// order): bit j of left[k] when strictly left of side j, bit j of onLine[k] when on its line. A
// vertex on a side line outside C (on the line's extension: strictly right of another side) counts
// as right of it; an edge from it crosses that line only there, outside the side. Returns the
// sides some vertex lies strictly left of, and in `anyOn` the side lines some vertex lies on.
// A ring of up to kBoxFirstUpTo vertices is first placed by its bounding box
// (SideLines::placeBox()); outside C it returns 0 with the arrays unset.
template <int kSides>
unsigned classifyEach(const CcwRing& s, const SideLines& sides, WeilerScratch& w, unsigned& anyOn) {
  const std::size_t n = std::size_t(s.size());
  const IPoint* points = s.ring->data();
  unsigned* left = w.left.data();
  unsigned* onLine = w.onLine.data();
  // A short ring (a blob of a mask, a tag's square) most often lies wholly inside C or outside
  // one side line, which its bounding box tells at 13 instructions a vertex (W4: -7%). A long
  // one most often crosses C, where the box only adds them (W1-100k: +1.8%).
  anyOn = 0;
  if (n <= kBoxFirstUpTo) {
    IPoint lo = points[0], hi = points[0];
    for (std::size_t i = 1; i < n; ++i) {
      lo = {std::min(lo.x, points[i].x), std::min(lo.y, points[i].y)};
      hi = {std::max(hi.x, points[i].x), std::max(hi.y, points[i].y)};
    }
    const BoxPlace place = sides.placeBox<kSides>(lo, hi);
    if (place == BoxPlace::Outside) return 0;  // arrays left unset: nothing is in C
    if (place == BoxPlace::Inside) {
      std::fill(left, left + n, sides.all());
      std::fill(onLine, onLine + n, 0U);
      return sides.all();
    }
  }
  unsigned anyLeft = 0, on = 0;
  // Vertex i of the stored ring is vertex k of the counter-clockwise order.
  classifyPath(
      points, n, [&](IPoint p, std::int64_t& reach) { return sides.classify<kSides>(p, reach); },
      [&](std::size_t i, SideLines::Masks m) {
        const std::size_t k = s.reversed ? n - 1 - i : i;
        left[k] = m.left;
        onLine[k] = m.zeros;
        anyLeft |= m.left;
        on |= m.zeros;
      });
  anyOn = on;
  return anyLeft;
}

// What the grouping already knows of the vertices (`known`) put into place, as classifyEach()
// leaves it. Kept out of classifyVertices(): inlined there, it made the vertex loop of W1-100k
// 1.8% dearer (50k instructions).
[[gnu::noinline]] unsigned takeKnown(const CcwRing& s, const SideLines& sides, WeilerScratch& w,
                                     unsigned& anyOn, const KnownSides& known) {
  const std::size_t n = std::size_t(s.size());
  if (known.inside) {
    std::fill(w.left.begin(), w.left.end(), sides.all());
    std::fill(w.onLine.begin(), w.onLine.end(), 0U);
    anyOn = 0;
    return sides.all();
  }
  if (s.reversed) {
    std::reverse_copy(known.left, known.left + n, w.left.begin());
    std::reverse_copy(known.onLine, known.onLine + n, w.onLine.begin());
  } else {
    std::copy(known.left, known.left + n, w.left.begin());
    std::copy(known.onLine, known.onLine + n, w.onLine.begin());
  }
  unsigned anyLeft = 0, on = 0;
  for (std::size_t i = 0; i < n; ++i) {
    anyLeft |= known.left[i];
    on |= known.onLine[i];
  }
  anyOn = on;
  return anyLeft;
}

// classifyEach(), or takeKnown() where the grouping knows the vertices.
unsigned classifyVertices(const CcwRing& s, const SideLines& sides, WeilerScratch& w,
                          unsigned& anyOn, const KnownSides& known) {
  w.left.resize(std::size_t(s.size()), boost::container::default_init);
  w.onLine.resize(std::size_t(s.size()), boost::container::default_init);
  if (known.inside || known.left != nullptr) return takeKnown(s, sides, w, anyOn, known);
  return withSideCount(sides, [&](auto k) { return classifyEach<k()>(s, sides, w, anyOn); });
}

// The corner of C at vertex k of s (classified by classifyVertices()), or -1. A vertex in C's
// closed region on two side lines is a corner (C is strictly convex): sides j - 1 and j meet at
// corner j.
int cornerAt(const WeilerScratch& w, std::size_t k, unsigned all) {
  const unsigned on = w.onLine[k];
  if (__builtin_expect((on & (on - 1)) == 0, 1) || (w.left[k] | on) != all) return -1;
  const int low = __builtin_ctz(on), high = 31 - __builtin_clz(on);
  return high == low + 1 ? high : 0;  // sides m - 1 and 0 meet at corner 0
}

// How the vertices classified by classifyVertices() meet C's boundary.
struct BoundaryTouch {
  bool onBoundary = false;    // some vertex lies on C's boundary
  bool everyInClosed = true;  // every vertex lies in C or on its boundary
  unsigned corners = 0;       // bit j: some vertex lies at corner j
  /// A corner of C that is no vertex of s, or -1.
  [[nodiscard]] int freeCorner(unsigned all) const {
    return corners == all ? -1 : __builtin_ctz(~corners & all);
  }
};
BoundaryTouch boundaryVertices(const WeilerScratch& w, unsigned all, std::size_t n) {
  BoundaryTouch t;
  for (std::size_t k = 0; k < n; ++k) {
    const bool inClosed = (w.left[k] | w.onLine[k]) == all;
    t.onBoundary = t.onBoundary || (w.onLine[k] != 0 && inClosed);
    t.everyInClosed = t.everyInClosed && inClosed;
    const int corner = cornerAt(w, k, all);
    if (corner >= 0) t.corners |= 1U << corner;
  }
  return t;
}

// The crossings of edge k (vertex k to vertex kq, p to q) at its ends where they lie at corners
// of C: from a corner into its wedge (the other end strictly left of both its sides) entering,
// into a corner from the wedge leaving. Returns the sides whose lines the edge crosses elsewhere.
[[gnu::noinline]] unsigned cornerCrossings(int k, std::size_t kq, IPoint p, IPoint q, int ring,
                                           unsigned all, WeilerScratch& w) {
  const unsigned lp = w.left[std::size_t(k)], lq = w.left[kq];
  const unsigned onP = w.onLine[std::size_t(k)], onQ = w.onLine[kq];
  unsigned changed = lp ^ lq;
  const auto add = [&](IPoint v, int corner, bool entering) {
    Crossing x;
    x.x = XPoint(v);
    x.edge = k;
    x.side = corner;
    x.ring = ring;
    x.entering = entering;
    w.crossings.push_back(x);
  };
  if (const int corner = cornerAt(w, std::size_t(k), all); corner >= 0) {
    changed &= ~onP;
    if ((lq & onP) == onP) add(p, corner, true);
  }
  if (const int corner = cornerAt(w, kq, all); corner >= 0) {
    changed &= ~onQ;
    if ((lp & onQ) == onQ) add(q, corner, false);
  }
  return changed;
}

// Appends to w.crossings the crossings of ring s (number `ring`, classified by
// classifyVertices()) with C's boundary, edge by edge and along each edge. A vertex of s on C's
// boundary is a crossing of each edge at it that lies in C near it: near a vertex on a side, C is
// that side's half-plane; near a corner j, the wedge of sides j - 1 and j, and the crossing
// counts as the start of side j. False when an edge runs along a side's line, or when its line
// passes through a corner of C that is not one of its ends.
bool appendCrossings(const CcwRing& s, int ring, const CcwRing& c, unsigned all, WeilerScratch& w) {
  const int n = s.size(), m = c.size();
  for (int k = 0; k < n; ++k) {
    const std::size_t kq = k + 1 == n ? 0 : std::size_t(k) + 1;
    const unsigned lp = w.left[std::size_t(k)], lq = w.left[kq];
    if ((lp & lq) == all) continue;  // both ends in C: the edge lies in C
    const unsigned onP = w.onLine[std::size_t(k)], onQ = w.onLine[kq];
    if ((onP & onQ) != 0) return false;  // along a side's line
    // Both ends strictly on the same sides of every line (most edges outside C): no crossing.
    if (((lp ^ lq) | onP | onQ) == 0) continue;
    const IPoint p = s[k], q = s[int(kq)];
    const std::size_t before = w.crossings.size();
    unsigned changed = lp ^ lq;
    if (__builtin_expect((onP | onQ) != 0, 0)) changed = cornerCrossings(k, kq, p, q, ring, all, w);
    for (; changed != 0; changed &= changed - 1) {
      const int j = __builtin_ctz(changed);
      const IPoint a = c[j], b = c[(j + 1) % m];
      const int oa = orientInGrid(p, q, a), ob = orientInGrid(p, q, b);
      if (oa == 0 || ob == 0) return false;  // through a corner of C
      if (oa == ob) continue;                // crosses the side's line outside the side
      Crossing x;
      if (!lineIntersection(p, q, a, b, x.x)) return false;
      x.edge = k;
      x.side = j;
      x.ring = ring;
      x.entering = ((lq >> j) & 1U) != 0;
      w.crossings.push_back(x);
    }
    if (w.crossings.size() - before > 1) {
      std::sort(
          w.crossings.begin() + std::ptrdiff_t(before), w.crossings.end(),
          [&](const Crossing& u, const Crossing& v) { return orderAlong(p, q, u.x, v.x) < 0; });
    }
  }
  return true;
}

// The exact point of a walked point.
XPoint exactOf(const WeilerScratch& w, const WalkPoint& a) {
  return a.crossing < 0 ? XPoint(a.p) : w.crossings[std::size_t(a.crossing)].x;
}
bool lessWalked(const WeilerScratch& w, const WalkPoint& a, const WalkPoint& b) {
  if (a.crossing < 0 && b.crossing < 0) return a.p < b.p;
  return lessInBox(exactOf(w, a), exactOf(w, b));
}
bool equalWalked(const WeilerScratch& w, const WalkPoint& a, const WalkPoint& b) {
  if (a.crossing < 0 && b.crossing < 0) return a.p == b.p;
  return a.crossing == b.crossing || equalInBox(exactOf(w, a), exactOf(w, b));
}

// Appends `count` vertices of s, from vertex `from` on (counter-clockwise, round the ring).
void appendRun(const CcwRing& s, int from, int count, std::vector<WalkPoint>& out) {
  const std::size_t at = out.size();
  out.resize(at + std::size_t(count));
  WalkPoint* to = out.data() + at;
  const IPoint* points = s.ring->data();
  const int n = s.size();
  int j = s.reversed ? n - 1 - from : from;  // the stored index
  if (s.reversed) {
    for (int i = 0; i < count; ++i) {
      to[i].p = points[j];
      j = j == 0 ? n - 1 : j - 1;
    }
  } else {
    for (int i = 0; i < count; ++i) {
      to[i].p = points[j];
      j = j == n - 1 ? 0 : j + 1;
    }
  }
}

// Weiler-Atherton's walk over the crossings in w.crossings (each ring's in a row, from
// w.crossStart[r]; the rings taken with the filled side on the left, `ringAt(r)` giving ring r):
// along a ring from each entering crossing to the next crossing on it, which leaves C, then
// along C to the next crossing on C's boundary, which enters; round until back. The result
// rings go to w.points / w.ringStart; `piece(t, r)` is told that result ring t runs along ring r.
// False when the crossings do not alternate as they must.
template <class RingAt, class Piece>
bool walkCrossings(const CcwRing& c, RingAt ringAt, Piece piece, WeilerScratch& w) {
  const std::vector<Crossing>& crossings = w.crossings;
  const std::size_t kCount = crossings.size();
  const int m = c.size();
  // Crossings along C's boundary: by side, then along it.
  std::vector<int>& alongC = w.alongC;
  alongC.resize(kCount);
  for (std::size_t i = 0; i < kCount; ++i) alongC[i] = int(i);
  // Two crossings at one point are a vertex of a ring that touches C's side from inside: it
  // leaves C there, then enters again, so the leaving one comes first.
  std::sort(alongC.begin(), alongC.end(), [&](int u, int v) {
    const Crossing &a = crossings[std::size_t(u)], &b = crossings[std::size_t(v)];
    if (a.side != b.side) return a.side < b.side;
    const int order = orderAlong(c[a.side], c[(a.side + 1) % m], a.x, b.x);
    if (order == 0) return !a.entering && b.entering;  // one point: leaving first
    return order < 0;
  });
  std::vector<int>& rankOnC = w.rankOnC;
  rankOnC.resize(kCount);
  for (std::size_t i = 0; i < kCount; ++i) rankOnC[std::size_t(alongC[i])] = int(i);

  w.used.assign(kCount, 0);
  w.points.clear();
  w.ringStart.assign(1, 0);
  for (std::size_t start = 0; start < kCount; ++start) {
    if (!crossings[start].entering || w.used[start]) continue;
    const int t = int(w.ringStart.size()) - 1;
    std::size_t at = start;
    do {
      // Entering at `at`: along its ring to the next crossing on it, which leaves C.
      w.used[at] = 1;
      const Crossing& in = crossings[at];
      const CcwRing s = ringAt(in.ring);
      const int n = s.size();
      const std::size_t ringEnd = std::size_t(w.crossStart[std::size_t(in.ring) + 1]);
      const std::size_t leaveAt =
          at + 1 < ringEnd ? at + 1 : std::size_t(w.crossStart[std::size_t(in.ring)]);
      const Crossing& leave = crossings[leaveAt];
      if (leave.entering) return false;
      piece(t, in.ring);
      // Entering where it just left (a touch from inside): the point once.
      const WalkPoint inPoint{{}, int(at)};
      if (w.points.size() == w.ringStart.back() || !equalWalked(w, w.points.back(), inPoint)) {
        w.points.push_back(inPoint);
      }
      int steps = (leave.edge - in.edge + n) % n;
      if (steps == 0 && leaveAt <= at) steps = n;  // round the whole ring on one edge
      appendRun(s, (in.edge + 1) % n, steps, w.points);
      w.points.push_back({{}, int(leaveAt)});
      // Along C from the leaving crossing to the next crossing on C, which enters.
      const std::size_t rank = std::size_t(rankOnC[leaveAt]);
      const std::size_t nextRank = (rank + 1) % kCount;
      const std::size_t enterAt = std::size_t(alongC[nextRank]);
      const Crossing& enter = crossings[enterAt];
      if (!enter.entering) return false;
      int corners = (enter.side - leave.side + m) % m;
      if (corners == 0 && nextRank <= rank) corners = m;
      for (int k = 1; k <= corners; ++k) w.points.push_back({c[(leave.side + k) % m]});
      at = enterAt;
    } while (at != start);
    if (equalWalked(w, w.points.back(), w.points[w.ringStart.back()])) w.points.pop_back();
    w.ringStart.push_back(w.points.size());
  }
  return true;
}

// The index in w.points of the lexicographically smallest point of result ring t: among the grid
// vertices (most of a ring) by their coordinates first, then against the crossings.
std::size_t lowestOf(const WeilerScratch& w, std::size_t t) {
  const std::size_t begin = w.ringStart[t], end = w.ringStart[t + 1];
  std::size_t first = end;
  for (std::size_t i = begin; i < end; ++i) {
    const WalkPoint& a = w.points[i];
    if (a.crossing < 0 && (first == end || a.p < w.points[first].p)) first = i;
  }
  for (std::size_t i = begin; i < end; ++i) {
    if (w.points[i].crossing >= 0 &&
        (first == end || lessWalked(w, w.points[i], w.points[first]))) {
      first = i;
    }
  }
  return first;
}

// Result ring t's output path: counter-clockwise from its smallest vertex, reversed.
Path walkedPath(const WeilerScratch& w, std::size_t t, std::size_t lowest,
                const OutputFrame& frame) {
  const std::size_t begin = w.ringStart[t], n = w.ringStart[t + 1] - begin;
  // Output index k takes the point k + 1 steps back from the lowest (outputRing() asks k = 0,
  // 1, ... in turn).
  std::size_t i = lowest == begin ? begin + n - 1 : lowest - 1;
  return outputRing(n, [&](std::size_t) {
    const WalkPoint& a = w.points[i];
    i = i == begin ? begin + n - 1 : i - 1;
    return a.crossing < 0 ? frame.point(a.p) : frame.point(w.crossings[std::size_t(a.crossing)].x);
  });
}

// Output as stages 1 to 4 emit it: each ring counter-clockwise from its lexicographically smallest
// vertex, reversed (roiclip's orientation); polygons in the order of those smallest vertices.
PolygonSet emit(WeilerScratch& w, const Grid& grid) {
  const std::size_t ringCount = w.ringStart.size() - 1;
  w.lowest.clear();
  w.order.clear();
  for (std::size_t r = 0; r < ringCount; ++r) {
    w.lowest.push_back(lowestOf(w, r));
    w.order.push_back(r);
  }
  std::sort(w.order.begin(), w.order.end(), [&](std::size_t a, std::size_t b) {
    return lessWalked(w, w.points[w.lowest[a]], w.points[w.lowest[b]]);
  });
  const OutputFrame frame(grid);
  PolygonSet result;
  result.polygons.reserve(ringCount);
  for (const std::size_t r : w.order) {
    Path path = walkedPath(w, r, w.lowest[r], frame);
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
  return withSideCount(sides, [&](auto k) {
    for (const std::vector<IPoint>& ring : rings) {
      for (const IPoint& p : ring) {
        const auto [left, zeros] = sides.classify<k()>(p);
        if ((left | zeros) != sides.all()) return false;
      }
    }
    return true;
  });
}

bool intersectSimpleConvex(const std::vector<IPoint>& ring, FillRule rule,
                           const std::vector<IPoint>& convex, int convexOrientation,
                           const Grid& grid, ChainScratch& chains, WeilerScratch& w,
                           PolygonSet& out, const KnownSides& known) {
  out = {};
  const int n = int(ring.size()), m = int(convex.size());
  // A ring that crosses itself with a loop (rotation index not +-1) leaves at once, before the
  // vertex test; one outside C does after it, and the rotation index costs it less.
  if (n < 3 || m > kMaxSides || !turnsOnce(ring)) return false;
  // The orientation, if S is simple (asked below, after the cheaper test of its vertices).
  const bool ccw = lowestVertex(ring).ccw;
  const CcwRing s{&ring, !ccw}, c{&convex, convexOrientation < 0};
  const SideLines sides(convex, convexOrientation);
  const unsigned all = sides.all();
  unsigned anyOn = 0;
  // No vertex strictly left of some side: the ring lies in that side's closed outer half-plane,
  // and so does every point it winds around, simple or not. Nothing of it is in C.
  if (classifyVertices(s, sides, w, anyOn, known) != all) return true;
  int probe = 0;  // a corner of C that is no vertex of S
  if (anyOn != 0) {
    const BoundaryTouch touch = boundaryVertices(w, all, std::size_t(n));
    if (touch.onBoundary && touch.everyInClosed) {
      // A simple ring in C that touches its boundary (a tag's square at a corner of the ROI):
      // it fills what it fills.
      if (!ringIsSimple(ring, chains, /*turnsChecked=*/true)) return false;
      out = simpleRingRegion(ring, rule, grid);
      return true;
    }
    // A vertex on C's boundary, of a ring across C: each edge at it lies inside or outside C
    // near it (appendCrossings()). One edge in, one out: a crossing at the vertex; both in: a
    // touch from inside, leaving and entering there; both out: a touch from outside.
    probe = touch.freeCorner(all);
  }
  if (!ringIsSimple(ring, chains, /*turnsChecked=*/true)) return false;
  if (!isFilled(rule, ccw ? 1 : -1)) return true;  // S fills nothing under its rule

  w.crossings.clear();
  if (!appendCrossings(s, 0, c, all, w)) return false;
  if (w.crossings.empty()) {
    if (w.left[0] == all) {
      out = simpleRingRegion(ring, FillRule::NonZero, grid);  // S lies in C
    } else if (probe < 0) {
      return false;  // S touches every corner of C from outside
    } else if (insideRing(s, c[probe])) {
      out = simpleRingRegion(convex, FillRule::NonZero, grid);  // C lies in S
    }
    return true;
  }
  if (w.crossings.size() % 2 != 0) return false;
  w.crossStart.assign({0, int(w.crossings.size())});
  if (!walkCrossings(
          c, [&](int) { return s; }, [](int, int) {}, w))
    return false;
  out = emit(w, grid);
  return true;
}

bool intersectSimpleRingsConvex(const Rings& rings, FillRule rule,
                                const std::vector<IPoint>& convex, int convexOrientation,
                                const Grid& grid, ChainScratch& chains, WeilerScratch& w,
                                PolygonSet& out, const KnownSides* known,
                                const std::vector<PinchedRings::Pinch>* touchingInC) {
  out = {};
  if (convex.size() > std::size_t(kMaxSides)) return false;
  nestSimpleRings(rings, rule, chains);
  const std::vector<RingNesting>& rn = chains.nesting;
  const SideLines sides(convex, convexOrientation);
  const unsigned all = sides.all();
  const CcwRing c{&convex, convexOrientation < 0};
  const std::size_t ringCount = rings.size();
  // Each ring of the result's boundary with the filled side on its left (outer rings
  // counter-clockwise, holes clockwise).
  const auto ringAt = [&](int r) {
    const RingNesting& ring = rn[std::size_t(r)];
    return CcwRing{&rings[std::size_t(r)], ring.lowest.ccw != ring.filledInside};
  };
  // Where each lies: across C's boundary (its crossings from w.crossStart[r]), inside C, or
  // outside it (left out).
  enum : char { kOutside, kInside, kAcross };
  std::vector<char>& place = w.place;
  place.assign(ringCount, kOutside);
  w.crossings.clear();
  w.crossStart.assign(ringCount + 1, 0);
  for (std::size_t r = 0; r < ringCount; ++r) {
    w.crossStart[r] = int(w.crossings.size());
    if (!rn[r].inResult) continue;
    const CcwRing s = ringAt(int(r));
    unsigned anyOn = 0;
    const KnownSides ringKnown = known != nullptr ? known[r] : KnownSides{};
    if (classifyVertices(s, sides, w, anyOn, ringKnown) != all) continue;  // outside a side line
    int probe = 0;  // a corner of C that is no vertex of the ring
    if (anyOn != 0) {
      const BoundaryTouch touch = boundaryVertices(w, all, std::size_t(s.size()));
      if (touch.onBoundary && touch.everyInClosed) {
        // In C, touching its boundary (a tag's square at a corner of the ROI): an outer ring
        // fills what it fills, and the region just outside it is empty, so no walked ring runs
        // through the touching points. A hole there would touch a walked ring: the general path.
        if (!rn[r].filledInside) return false;
        place[r] = kInside;
        continue;
      }
      // Across C: a vertex on its boundary is a crossing or a touch, as for one ring.
      probe = touch.freeCorner(all);
    }
    if (!appendCrossings(s, int(r), c, all, w)) return false;
    const std::size_t count = w.crossings.size() - std::size_t(w.crossStart[r]);
    if (count % 2 != 0) return false;
    if (count > 0) {
      place[r] = kAcross;
    } else if (w.left[0] == all) {
      place[r] = kInside;
    } else if (probe < 0 || insideRing(s, c[probe])) {
      return false;  // around C (or touching every corner): the general path
    }
  }
  w.crossStart[ringCount] = int(w.crossings.size());
  if (touchingInC != nullptr) {
    std::vector<char> across(ringCount);
    for (std::size_t r = 0; r < ringCount; ++r) across[r] = place[r] == kAcross ? 1 : 0;
    if (!pinchesKeepRings(*touchingInC, rn, &across)) return false;
  }

  // The walked rings are outer rings (each runs along C somewhere). For each ring across C that
  // bounds an outer ring's face (the outer ring itself, or one of its holes), the walked ring it
  // runs along: one, else -2.
  std::vector<int>& walkedOf = w.walkedOf;
  walkedOf.assign(ringCount, -1);
  const auto faceOf = [&](int r) {
    return rn[std::size_t(r)].filledInside ? r : rn[std::size_t(r)].resultAround;
  };
  const auto piece = [&](int t, int r) {
    const int face = faceOf(r);
    if (face < 0) return;  // no outer ring around a hole: its holes find none (below)
    int& f = walkedOf[std::size_t(face)];
    f = f == -1 || f == t ? t : -2;
  };
  if (!w.crossings.empty() && !walkCrossings(c, ringAt, piece, w)) return false;

  // Polygons: the walked rings and the outer rings inside C, by their smallest vertices.
  struct Entry {
    XPoint key;
    int walked;  // the walked ring, or -1
    int ring;    // the ring inside C, or -1
  };
  std::vector<Entry> polygons;
  const std::size_t walkedCount = w.crossings.empty() ? 0 : w.ringStart.size() - 1;
  w.lowest.clear();
  for (std::size_t t = 0; t < walkedCount; ++t) {
    w.lowest.push_back(lowestOf(w, t));
    polygons.push_back({exactOf(w, w.points[w.lowest.back()]), int(t), -1});
  }
  for (std::size_t r = 0; r < ringCount; ++r) {
    if (place[r] == kInside && rn[r].filledInside) {
      polygons.push_back({XPoint(rings[r][rn[r].lowest.index]), -1, int(r)});
    }
  }
  std::sort(polygons.begin(), polygons.end(),
            [](const Entry& a, const Entry& b) { return lessInBox(a.key, b.key); });
  std::vector<int>& polygonOf = w.polygonOf;  // by walked ring, then by ring
  polygonOf.assign(walkedCount + ringCount, -1);
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    const Entry& e = polygons[i];
    polygonOf[e.walked >= 0 ? std::size_t(e.walked) : walkedCount + std::size_t(e.ring)] = int(i);
  }
  // Holes inside C: in their outer ring's polygon, or in the one walked ring along that outer
  // ring's face.
  std::vector<std::pair<int, int>>& holes = w.holes;  // (polygon, ring)
  holes.clear();
  for (std::size_t r = 0; r < ringCount; ++r) {
    if (place[r] != kInside || rn[r].filledInside) continue;
    const int outer = rn[r].resultAround;
    if (outer < 0) return false;
    int polygon = -1;
    if (place[std::size_t(outer)] == kInside) {
      polygon = polygonOf[walkedCount + std::size_t(outer)];
    } else if (place[std::size_t(outer)] == kAcross && walkedOf[std::size_t(outer)] >= 0) {
      polygon = polygonOf[std::size_t(walkedOf[std::size_t(outer)])];
    }
    if (polygon < 0) return false;  // several walked rings may hold it: the general path
    polygonOf[walkedCount + r] = polygon;
    holes.emplace_back(polygon, int(r));
  }
  std::sort(holes.begin(), holes.end(), [&](const auto& a, const auto& b) {
    if (a.first != b.first) return a.first < b.first;
    return rings[std::size_t(a.second)][rn[std::size_t(a.second)].lowest.index] <
           rings[std::size_t(b.second)][rn[std::size_t(b.second)].lowest.index];
  });

  const OutputFrame frame(grid);
  PolygonSet result;
  result.polygons.resize(polygons.size());
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    const Entry& e = polygons[i];
    Polygon& polygon = result.polygons[i];
    if (e.walked >= 0) {
      polygon.outer = walkedPath(w, std::size_t(e.walked), w.lowest[std::size_t(e.walked)], frame);
    } else {
      const RingNesting& ring = rn[std::size_t(e.ring)];
      polygon.outer = simpleRingPath(rings[std::size_t(e.ring)], ring.lowest, false, frame);
    }
    if (polygon.outer.size() < 3) return false;  // rounding collapsed it: the general path
  }
  std::vector<int>& holeIndex = w.holeIndex;  // by ring
  holeIndex.assign(ringCount, -1);
  for (const auto& [p, r] : holes) {
    Polygon& polygon = result.polygons[std::size_t(p)];
    holeIndex[std::size_t(r)] = int(polygon.holes.size());
    polygon.holes.push_back(
        simpleRingPath(rings[std::size_t(r)], rn[std::size_t(r)].lowest, true, frame));
    if (polygon.holes.back().size() < 3) return false;
  }
  // Outer rings inside a hole inside C lie in that hole; inside a hole across C, at the top.
  for (const Entry& e : polygons) {
    if (e.ring < 0) continue;
    const int hole = rn[std::size_t(e.ring)].resultAround;
    if (hole < 0 || place[std::size_t(hole)] != kInside) continue;
    Polygon& polygon = result.polygons[std::size_t(polygonOf[walkedCount + std::size_t(e.ring)])];
    polygon.parent = polygonOf[walkedCount + std::size_t(hole)];
    polygon.parentHole = holeIndex[std::size_t(hole)];
  }
  out = std::move(result);
  return true;
}

}  // namespace roiclip::detail
