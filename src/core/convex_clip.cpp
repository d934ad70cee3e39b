// SPDX-License-Identifier: MIT
// The convex fast path: an exact Sutherland-Hodgman pre-clip of the subject against a convex
// clip ring (the quad through four tags is the common ROI).
//
// Clipping a closed path against a half-plane replaces each run outside by the stretch of the
// boundary line between where the run leaves and re-enters. Inside the half-plane no point is
// crossed by that replacement, so every winding number there is unchanged; outside it the new
// path winds 0 times around every point. Doing this for each half-plane of a convex ring C
// leaves paths inside C whose winding numbers equal the subject's in C and 0 elsewhere, so
// resolving them with the subject's fill rule gives subject AND C. Every vertex made here is the
// crossing of two integer segments and every new edge lies on an integer segment (a subject
// edge or a side of C), so the sweep handles the result exactly. Cost: O(n * c) for n subject
// edges and c sides of C; the sweep then only sees what lies inside C.
//
// Only what leaves C is clipped. One pass decides for every vertex whether it lies in C (the
// closed ring, exact int64 orientation: orientInGrid()); an edge with both ends in C lies in C
// (C is convex) and passes every half-plane step unchanged, so it is emitted as it is, an
// InputEdge. The ring splits at its vertices in C into open chains v0 .. vm whose inner vertices
// lie outside C. Each Sutherland-Hodgman step is local: what it emits for an edge p -> q depends
// only on the sides of p and q and on p's supporting segment, and a vertex inside the half-plane
// is emitted as it is. So v0 and vm, inside every half-plane, survive every step unchanged and
// still delimit what the step made of the chain between them (by induction over the steps):
// clipping the closed ring is clipping each chain on its own (its last vertex vm not emitted,
// it starts the next chain) and putting the pieces together in ring order. Only a ring with no
// vertex in C is clipped whole (clipHalfPlane()), as is the reference preclipConvexReference().
#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <optional>

#include <roiclip/error.hpp>

#include "convex_sides.hpp"
#include "pipeline.hpp"
#include "workspace.hpp"

namespace roiclip::detail {
namespace {

using Vertex = ClipVertex;

XPoint crossing(const Vertex& from, IPoint hA, IPoint hB) {
  XPoint x;
  if (!lineIntersection(from.lineA, from.lineB, hA, hB, x)) {
    throw InternalError("preclipConvex: parallel lines have no crossing");
  }
  return x;
}

// One Sutherland-Hodgman step over the edges in[i] -> in[i + 1] and in[n - 1] -> a vertex on
// side `endSide` of hA -> hB: keep the part on the left (points on the line count as inside),
// appended to `out`.
void clipEdges(const std::vector<Vertex>& in, int endSide, IPoint hA, IPoint hB,
               std::vector<Vertex>& out) {
  const std::size_t n = in.size();
  int sp = orientInBox(hA, hB, in[0].p);
  for (std::size_t i = 0; i < n; ++i) {
    const Vertex& p = in[i];
    const int sq = i + 1 < n ? orientInBox(hA, hB, in[i + 1].p) : endSide;
    if (sp >= 0) {
      out.push_back(p);
      if (sq < 0) {
        if (sp == 0) {
          out.back().lineA = hA;  // leaves along the boundary right away
          out.back().lineB = hB;
        } else {
          out.push_back({crossing(p, hA, hB), hA, hB});
        }
      }
    } else if (sq > 0) {
      out.push_back({crossing(p, hA, hB), p.lineA, p.lineB});
    }
    sp = sq;
  }
}

// One step on a closed path (its last edge back to in[0]). Writes into `out` (cleared first).
void clipHalfPlane(const std::vector<Vertex>& in, IPoint hA, IPoint hB, std::vector<Vertex>& out) {
  out.clear();
  if (in.empty()) return;
  out.reserve(in.size() + 16);  // a few crossings more than the input: no growth by doubling
  clipEdges(in, orientInBox(hA, hB, in[0].p), hA, hB, out);
}

// One step on an open chain in[0] .. in[n-1], `end` (both in C, so inside the half-plane): what
// clipHalfPlane() emits for these edges of a closed path, `end` not emitted (it starts the next
// chain). in[0] always comes out first.
void clipChainHalfPlane(const std::vector<Vertex>& in, IPoint end, IPoint hA, IPoint hB,
                        std::vector<Vertex>& out) {
  out.clear();
  clipEdges(in, orientInGrid(hA, hB, end), hA, hB, out);
}

// The edge from v to w on v's supporting segment, unless it has length 0.
void emitExact(const Vertex& v, const XPoint& w, std::vector<ExactEdge>& out) {
  const int c = compare(v.p, w);
  if (c == 0) return;
  ExactEdge e;
  e.lineA = v.lineA < v.lineB ? v.lineA : v.lineB;
  e.lineB = v.lineA < v.lineB ? v.lineB : v.lineA;
  e.left = c < 0 ? v.p : w;
  e.right = c < 0 ? w : v.p;
  e.direction = c < 0 ? +1 : -1;
  e.operand = 0;
  out.push_back(e);
}

// The edges of a clipped closed path.
void emitClosed(const std::vector<Vertex>& path, std::vector<ExactEdge>& out) {
  for (std::size_t i = 0; i < path.size(); ++i)
    emitExact(path[i], path[(i + 1) % path.size()].p, out);
}

// The convex ring with its inside on the left.
std::vector<IPoint> leftTurning(const std::vector<IPoint>& convexRing, int orientation) {
  if (orientation == 0) throw InternalError("preclipConvex: clip ring is not convex");
  std::vector<IPoint> clipRing = convexRing;
  if (orientation < 0) std::reverse(clipRing.begin(), clipRing.end());
  return clipRing;
}

// A ring clipped whole: every half-plane step on the closed path (the reference, and rings with
// no vertex in C).
void clipRingWhole(const std::vector<IPoint>& ring, const std::vector<IPoint>& clipRing,
                   std::vector<Vertex>& path, std::vector<Vertex>& next,
                   std::vector<ExactEdge>& out) {
  path.clear();
  path.reserve(ring.size());
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const IPoint a = ring[i], b = ring[(i + 1) % ring.size()];
    path.push_back({XPoint(a), a, b});
  }
  const std::size_t sides = clipRing.size();
  for (std::size_t k = 0; k < sides && !path.empty(); ++k) {
    clipHalfPlane(path, clipRing[k], clipRing[(k + 1) % sides], next);
    path.swap(next);
  }
  emitClosed(path, out);
}

// Whether the rings go through RingClipper: the outcodes are one bit per side of C.
constexpr std::size_t kMaxCodedSides = 64;

// Pre-clips one ring at a time: edges in C as InputEdges, chains leaving C clipped to
// ExactEdges. Every vertex gets an outcode, the sides of C it lies strictly outside of (0: in C).
class RingClipper {
 public:
  // `convexRing` (at most kMaxCodedSides sides) turns by `orientation`; the sides are kept
  // with the inside on their left.
  RingClipper(const std::vector<IPoint>& convexRing, int orientation, Workspace& ws,
              std::vector<InputEdge>& edges, std::vector<ExactEdge>& exact)
      : convexRing_(convexRing),
        orientation_(orientation),
        sideCount_(convexRing.size()),
        path_(ws.path),
        next_(ws.next),
        edges_(edges),
        exact_(exact) {
    for (std::size_t k = 0; k < sideCount_; ++k) {
      const std::size_t j = k + 1 < sideCount_ ? k + 1 : 0;
      const IPoint a = orientation > 0 ? convexRing[k] : convexRing[sideCount_ - 1 - k];
      const IPoint b = orientation > 0 ? convexRing[j] : convexRing[sideCount_ - 1 - j];
      sides_[k] = {a.x, a.y, b.x, b.y, b.x - a.x, b.y - a.y};
    }
    allSides_ =
        sideCount_ == kMaxCodedSides ? ~std::uint64_t{0} : (std::uint64_t{1} << sideCount_) - 1;
    if (sideCount_ <= std::size_t(kMaxSides)) lines_.emplace(convexRing, orientation);
  }

  void clip(const std::vector<IPoint>& ring, const KnownSides& known) {
    const std::size_t n = ring.size();
    if (n > kInlineCodes && n > heapCapacity_) {
      heapCodes_.reset(new std::uint64_t[n]);  // written before read: not zeroed
      heapCapacity_ = n;
    }
    codes_ = n > kInlineCodes ? heapCodes_.get() : inlineCodes_.data();
    std::uint64_t strictlyIn = 0;  // the sides some vertex lies strictly inside of
    if (known.inside) {            // every vertex strictly inside C
      std::fill_n(codes_, n, 0);
      strictlyIn = allSides_;
    } else if (lines_) {
      // Up to kMaxSides sides: the grouping's masks (SideLines's order) when it has them, else
      // SideLines's test, its loop over the sides unrolled for a quad (W2-10k even-odd: -2.9% of
      // the call).
      const unsigned all = lines_->all();
      unsigned in = 0;
      const auto take = [&](std::size_t i, unsigned left, unsigned zeros) {
        codes_[i] = all & ~(left | zeros);
        in |= left;
      };
      if (known.left != nullptr) {
        for (std::size_t i = 0; i < n; ++i) take(i, known.left[i], known.onLine[i]);
      } else {
        withSideCount(*lines_, [&](auto k) {
          classifyPath(
              ring.data(), n,
              [&](IPoint p, std::int64_t& reach) { return lines_->classify<k()>(p, reach); },
              [&](std::size_t i, SideLines::Masks m) { take(i, m.left, m.zeros); });
        });
      }
      strictlyIn = in;
    } else {
      for (std::size_t i = 0; i < n; ++i) codes_[i] = outcode(ring[i], strictlyIn);
    }
    // Entirely outside one half-plane (on its line at most): winds 0 times around every point of
    // C, dropped.
    if (strictlyIn != allSides_) return;
    std::size_t first = 0;  // the first vertex in C
    while (first < n && codes_[first] != 0) ++first;
    if (first == n) {
      clipRingWhole(ring, leftTurning(convexRing_, orientation_), path_, next_, exact_);
      return;
    }
    std::size_t chainStart = first;
    for (std::size_t i = first + 1; i < n; ++i) {
      if (codes_[i] != 0) continue;
      closeChain(ring, chainStart, i);
      chainStart = i;
    }
    closeChain(ring, chainStart, first);  // round the end of the ring
  }

 private:
  // No member initialisers: the arrays below are written before they are read, not zeroed
  // on every call.
  struct Side {
    std::int64_t ax, ay, bx, by, dx, dy;
    [[nodiscard]] IPoint a() const { return {ax, ay}; }
    [[nodiscard]] IPoint b() const { return {bx, by}; }
  };
  static constexpr std::size_t kInlineCodes = 256;  // rings up to this size: no allocation

  // The sides q lies strictly outside of; adds those it lies strictly inside of to `strictlyIn`.
  // orientInGrid() with the sides' directions computed once.
  std::uint64_t outcode(IPoint q, std::uint64_t& strictlyIn) const {
    std::uint64_t out = 0, in = 0;
    for (std::size_t k = 0; k < sideCount_; ++k) {
      const Side& s = sides_[k];
      const std::int64_t l = s.dx * (q.y - s.ay), r = s.dy * (q.x - s.ax);
      out |= std::uint64_t(l < r) << k;
      in |= std::uint64_t(l > r) << k;
    }
    strictlyIn |= in;
    return out;
  }

  // Appends ring[i] as a chain vertex (its supporting segment set by the next one).
  void keep(const std::vector<IPoint>& ring, std::size_t i) {
    path_.push_back({XPoint(ring[i]), ring[i], ring[i]});
  }

  // The chain ring[start] .. ring[end] (both in C, the vertices between outside it): one edge in
  // C, or a stretch outside C clipped on its own. A run of vertices strictly outside one common
  // side is cut to its first and last: the loop that removes (the run closed by the chord
  // between them) lies in that open half-plane, outside C, so no winding number in C changes.
  void closeChain(const std::vector<IPoint>& ring, std::size_t start, std::size_t end) {
    const std::size_t n = ring.size();
    const auto after = [n](std::size_t i) { return i + 1 < n ? i + 1 : 0; };
    if (after(start) == end) {
      edges_.push_back(closedEdge(ring[start], ring[end], 0));
      return;
    }
    path_.clear();
    keep(ring, start);
    std::size_t runFirst = after(start), runLast = runFirst;
    std::uint64_t common = codes_[runFirst];
    for (std::size_t i = after(runFirst); i != end; i = after(i)) {
      if ((common & codes_[i]) != 0) {
        common &= codes_[i];
        runLast = i;
        continue;
      }
      keep(ring, runFirst);
      if (runLast != runFirst) keep(ring, runLast);
      runFirst = runLast = i;
      common = codes_[i];
    }
    keep(ring, runFirst);
    if (runLast != runFirst) keep(ring, runLast);
    const IPoint last = ring[end];
    for (std::size_t v = 0; v < path_.size(); ++v) {
      path_[v].lineB = v + 1 < path_.size() ? path_[v + 1].lineA : last;
    }
    for (std::size_t k = 0; k < sideCount_; ++k) {
      clipChainHalfPlane(path_, last, sides_[k].a(), sides_[k].b(), next_);
      path_.swap(next_);
    }
    const XPoint lastPoint(last);
    for (std::size_t v = 0; v < path_.size(); ++v) {
      emitExact(path_[v], v + 1 < path_.size() ? path_[v + 1].p : lastPoint, exact_);
    }
  }

  const std::vector<IPoint>& convexRing_;
  int orientation_ = 0;
  std::size_t sideCount_ = 0;
  std::array<Side, kMaxCodedSides> sides_;
  std::uint64_t allSides_ = 0;
  std::optional<SideLines> lines_;  // the same sides, for up to kMaxSides of them
  std::vector<Vertex>& path_;
  std::vector<Vertex>& next_;
  std::vector<InputEdge>& edges_;
  std::vector<ExactEdge>& exact_;
  std::uint64_t* codes_ = nullptr;  // the outcodes of the ring being clipped
  std::array<std::uint64_t, kInlineCodes> inlineCodes_;
  std::unique_ptr<std::uint64_t[]> heapCodes_;
  std::size_t heapCapacity_ = 0;
};

// Whether a ring is dropped: some half-plane has no vertex strictly inside it.
bool outsideOneSide(const std::vector<IPoint>& ring, const std::vector<IPoint>& clipRing) {
  for (std::size_t k = 0; k < clipRing.size(); ++k) {
    const IPoint hA = clipRing[k], hB = clipRing[(k + 1) % clipRing.size()];
    if (std::none_of(ring.begin(), ring.end(),
                     [&](IPoint q) { return orientInGrid(hA, hB, q) > 0; })) {
      return true;
    }
  }
  return false;
}

}  // namespace

int convexOrientation(const std::vector<IPoint>& ring) {
  const std::size_t n = ring.size();
  if (n < 3) return 0;
  const IPoint* const p = ring.data();
  const auto sign = [](std::int64_t v) { return int(v > 0) - int(v < 0); };
  // Edge i runs from vertex i to vertex i + 1 (edge n - 1 back to vertex 0). The signs of the
  // edges' x and y before edge 0: those of the last edge with a non-zero one.
  int lastDx = 0, lastDy = 0;
  for (std::size_t k = n; k > 0 && (lastDx == 0 || lastDy == 0); --k) {
    const IPoint a = p[k - 1], b = p[k == n ? 0 : k];
    if (lastDx == 0) lastDx = sign(b.x - a.x);
    if (lastDy == 0) lastDy = sign(b.y - a.y);
  }
  int turn = 0;
  int xFlips = 0, yFlips = 0;
  IPoint d{p[0].x - p[n - 1].x, p[0].y - p[n - 1].y};
  for (std::size_t i = 0; i < n; ++i) {
    const IPoint b = p[i + 1 == n ? 0 : i + 1];
    const IPoint e{b.x - p[i].x, b.y - p[i].y};
    // The turn at vertex i (orientInGrid(): exact in int64 for grid points).
    const std::int64_t l = d.x * e.y, r = d.y * e.x;
    if (l == r) return 0;  // straight runs were merged: this is a reversal
    const int o = l > r ? 1 : -1;
    if (turn == 0) turn = o;
    if (o != turn) return 0;
    // Winding once: the edge direction's x and y signs each change exactly twice round the ring.
    const int dx = sign(e.x), dy = sign(e.y);
    if (dx != 0) {
      xFlips += int(dx != lastDx);
      lastDx = dx;
    }
    if (dy != 0) {
      yFlips += int(dy != lastDy);
      lastDy = dy;
    }
    d = e;
  }
  return xFlips <= 2 && yFlips <= 2 ? turn : 0;
}

void preclipConvex(const Rings& rings, const std::vector<IPoint>& convexRing,
                   std::vector<ExactEdge>& out) {
  const WorkspaceLease workspace;
  std::vector<InputEdge> edges;
  preclipConvex(rings, convexRing, convexOrientation(convexRing), *workspace, edges, out);
  for (const InputEdge& e : edges) {
    ExactEdge x;
    x.lineA = e.a;
    x.lineB = e.b;
    x.left = XPoint(e.a);
    x.right = XPoint(e.b);
    x.direction = e.direction;
    x.operand = e.operand;
    out.push_back(x);
  }
}

void preclipConvex(const Rings& rings, const std::vector<IPoint>& convexRing, int orientation,
                   Workspace& workspace, std::vector<InputEdge>& edges, std::vector<ExactEdge>& out,
                   const KnownSides* known) {
  workspace.generalPathUsed = true;
  if (orientation == 0) throw InternalError("preclipConvex: clip ring is not convex");
  // Reserved up front for every vertex: growth by doubling doubled the bytes allocated at 100k
  // vertices (fresh pages cost more than the clipping), and on a small call it cost W2-1k 1.5%
  // of its instructions. The edges are freed once the sweep has its pieces, so the reserve is
  // not held at the call's peak.
  std::size_t vertexCount = 0;
  for (const std::vector<IPoint>& ring : rings) vertexCount += ring.size();
  edges.clear();
  edges.reserve(vertexCount);
  out.clear();
  if (convexRing.size() <= kMaxCodedSides) {
    RingClipper clipper(convexRing, orientation, workspace, edges, out);
    for (std::size_t r = 0; r < rings.size(); ++r) {
      clipper.clip(rings[r], known != nullptr ? known[r] : KnownSides{});
    }
  } else {  // a convex ring of many sides: every ring clipped whole
    const std::vector<IPoint> clipRing = leftTurning(convexRing, orientation);
    for (const std::vector<IPoint>& ring : rings) {
      if (!outsideOneSide(ring, clipRing)) {
        clipRingWhole(ring, clipRing, workspace.path, workspace.next, out);
      }
    }
  }
  // Not held through the sweep that follows (a chain can be as long as the ring).
  releaseEachAbove(kKeptStageBytes, workspace.path, workspace.next);
}

void preclipConvexReference(const Rings& rings, const std::vector<IPoint>& convexRing,
                            std::vector<ExactEdge>& out) {
  const std::vector<IPoint> clipRing = leftTurning(convexRing, convexOrientation(convexRing));
  out.clear();
  std::vector<Vertex> path, next;
  for (const std::vector<IPoint>& ring : rings) clipRingWhole(ring, clipRing, path, next, out);
}

}  // namespace roiclip::detail
