// SPDX-License-Identifier: MIT
// roiclip private header: the stages of the clipping pipeline and the data passed between them.
// boolean_op.cpp strings them together; each stage lives in its own file.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include <roiclip/geometry.hpp>
#include <roiclip/roiclip.hpp>

#include "chunked_array.hpp"
#include "predicates.hpp"

namespace roiclip::detail {

struct Workspace;       // workspace.hpp: every array kept between calls
struct TraceScratch;    // workspace.hpp: the working arrays of traceContours()
struct NestingScratch;  // workspace.hpp: the working arrays of buildNesting()
struct ChainScratch;    // workspace.hpp: the working arrays of ringIsSimple()
struct WeilerScratch;   // workspace.hpp: the working arrays of intersectSimpleConvex()
struct OverlapScratch;  // workspace.hpp: the working arrays of cancelOverlaps()
struct RingNesting;     // workspace.hpp: one ring's place in the nesting of simple rings
class OutputFrame;      // output.hpp: exact points to doubles

/// Operand index: 0 = subject, 1 = clip.
constexpr int kOperands = 2;
using Windings = std::array<std::int64_t, kOperands>;

/// One directed input edge on the grid, stored with a < b (lexicographically).
struct InputEdge {
  IPoint a, b;
  int direction = 0;  ///< +1 when the input runs a -> b, -1 when it runs b -> a
  int operand = 0;
  bool open = false;  ///< a segment of an open polyline: it bounds nothing, it is only cut
};

/// The edge s -> t of a closed path of `operand`, its ends in lexicographic order.
inline InputEdge closedEdge(IPoint s, IPoint t, int operand) {
  return s < t ? InputEdge{s, t, +1, operand} : InputEdge{t, s, -1, operand};
}

/// An input edge whose ends are exact points (crossings) on the integer segment lineA-lineB;
/// made by the convex pre-clip. left < right lexicographically.
struct ExactEdge {
  IPoint lineA, lineB;  ///< lineA < lineB
  XPoint left, right;
  int direction = 0;  ///< +1 when the path runs left -> right
  int operand = 0;
};

/// Stage 0 (input.cpp): validate, snap to the grid, drop repeated points, emit the edges of
/// every closed path. Throws InvalidInputError naming the path and vertex.
void appendInputEdges(const Paths& paths, int operand, const Grid& grid,
                      std::vector<InputEdge>& out);

/// Closed rings of grid points, as snapRings() makes them.
using Rings = std::vector<std::vector<IPoint>>;
/// The bytes a set of rings holds, with the rings' own arrays.
inline std::size_t bytesOf(const Rings& rings) {
  std::size_t sum = rings.capacity() * sizeof(std::vector<IPoint>);
  for (const std::vector<IPoint>& ring : rings) sum += ring.capacity() * sizeof(IPoint);
  return sum;
}
/// Where each ring's first vertex lies when the rings' vertices are numbered one after the
/// other (flat), and their total, last.
inline void ringStarts(const Rings& rings, std::vector<std::size_t>& start) {
  start.assign(rings.size() + 1, 0);
  for (std::size_t r = 0; r < rings.size(); ++r) start[r + 1] = start[r] + rings[r].size();
}

/// Rings a stage writes again for each group of a call (the pinch and overlap stages' output):
/// a ring dropped keeps its array in `spare`, and add() takes one from there, so the groups of a
/// call after the first allocate none (with the stages' other arrays kept too, W5 scene_05's warm
/// call went from 1,012 allocations to 382).
class KeptRings {
 public:
  Rings rings;
  /// An empty ring at the end of `rings`.
  std::vector<IPoint>& add() {
    if (spare_.empty()) return rings.emplace_back();
    rings.push_back(std::move(spare_.back()));
    spare_.pop_back();
    rings.back().clear();
    return rings.back();
  }
  /// Drops every ring, keeping their arrays.
  void clear() {
    for (; !rings.empty(); rings.pop_back()) spare_.push_back(std::move(rings.back()));
  }
  /// The bytes held by the rings and the spare arrays.
  [[nodiscard]] std::size_t bytes() const { return bytesOf(rings) + bytesOf(spare_); }
  void swap(KeptRings& o) noexcept {
    rings.swap(o.rings);
    spare_.swap(o.spare_);
  }

 private:
  Rings spare_;
};

/// The edges of already snapped rings (input.cpp; appendInputEdges() is snapRings() + this).
void appendRingEdges(const Rings& rings, int operand, std::vector<InputEdge>& out);

/// Stage 0 for open polylines (input.cpp): validate and snap each polyline, drop repeated points
/// and vertices where it goes straight on, and emit its segments as open edges in path order.
/// `firstEdge` receives, per polyline, the index in `out` of its first segment (plus one
/// final entry), so the segments of polyline i are out[firstEdge[i] .. firstEdge[i+1]).
void appendLineEdges(const Paths& lines, const Grid& grid, std::vector<InputEdge>& out,
                     std::vector<std::size_t>& firstEdge);

/// countDegeneratePaths() (input.cpp): paths whose snapped points all lie on one line.
std::size_t countDegenerate(const Paths& paths, const Grid& grid);

/// Which side of a piece is filled in the result.
enum class Side : std::uint8_t { None = 0, Above = 1, Below = 2 };

/// What the boolean combination of the operands is: the operation and each operand's fill rule.
struct BooleanSpec {
  bool binary = false;  ///< false: subject only (simplify)
  /// false: only open pieces are wanted (clipLines), the region's own boundary is not stored
  bool keepBoundary = true;
  ClipOp op = ClipOp::Intersection;
  FillRule subjectRule = FillRule::EvenOdd;
  FillRule clipRule = FillRule::EvenOdd;
  /// Limits::maxCrossings: the sweep throws ResourceLimitError when it finds more crossings.
  std::uint64_t maxCrossings = Limits::kUnlimited;
  /// Whether the arrangement records the winding numbers of its pieces (Arrangement::windings):
  /// the stage tests check them; no stage reads them.
  bool recordWindings = false;
  /// Whether the sweep may find dense crossings slab by slab (split_edges.cpp, slab mode); the
  /// stage tests compare the arrangements with and without.
  bool slabs = true;
  /// Whether a point with these winding numbers is in the result. (Inline: the sweep asks this
  /// twice for every piece.) The operation is a truth table over (subject filled, clip filled),
  /// looked up without a branch on the windings: on W3 a branch on whether the subject is
  /// filled went the wrong way 933k times.
  [[nodiscard]] bool inside(const Windings& w) const {
    const unsigned s = isFilled(subjectRule, w[0]) ? 1U : 0U;
    const unsigned c = binary && isFilled(clipRule, w[1]) ? 2U : 0U;
    return ((truthTable() >> (s | c)) & 1U) != 0;
  }
  /// Bit (s + 2 c) says whether the result holds a point that the subject fills (s) and the clip
  /// fills (c); without a clip (`binary` false) only the subject counts.
  [[nodiscard]] unsigned truthTable() const {
    if (!binary) return 0b1010U;  // s
    switch (op) {
      case ClipOp::Intersection:
        return 0b1000U;  // s and c
      case ClipOp::Union:
        return 0b1110U;  // s or c
      case ClipOp::Difference:
        return 0b0010U;  // s and not c
      case ClipOp::Xor:
        return 0b0110U;  // s xor c
    }
    return 0;
  }
};

/// The side of a piece the result lies on, from whether the result holds the points just below
/// and just above it. Pieces between regions of equal status (the paper's "edges inside holes")
/// get Side::None and are not kept.
inline Side sideBetween(bool below, bool above) {
  if (below == above) return Side::None;
  return above ? Side::Above : Side::Below;
}

/// Stage 2 (classify.cpp): from the winding numbers just below a piece and its contribution,
/// the fill rules and the operation decide whether the piece bounds the result and on which
/// side the result lies. (The sweep asks the same through a PieceClassifier, one inside() per
/// side shared by the pieces on either side of it.)
inline Side classifyPiece(const Windings& below, const Windings& contribution,
                          const BooleanSpec& spec) {
  return sideBetween(spec.inside(below),
                     spec.inside({below[0] + contribution[0], below[1] + contribution[1]}));
}

/// BooleanSpec::inside() for the many pieces of one sweep (which classifies each piece from the
/// sides below and above it, as classifyPiece()): the operation's truth table and the fill rules
/// are read once, and each rule becomes a test without a branch or a switch per winding
/// number, ((sign * w) & mask) != 0: even-odd (1, 1), non-zero (1, -1), negative (1, the sign
/// bit), positive (-1, the sign bit). (The switches per rule and per operation were 9% of
/// W3-1k non-zero's instructions.) Winding numbers are sums of +-1 over input edges: |w| < 2^63.
class PieceClassifier {
 public:
  explicit PieceClassifier(const BooleanSpec& spec)
      : subject_(testOf(spec.subjectRule)),
        clip_(spec.binary ? testOf(spec.clipRule) : RuleTest{1, 0}),
        table_(spec.truthTable()) {}
  /// BooleanSpec::inside().
  [[nodiscard]] bool inside(const Windings& w) const {
    return ((table_ >> (subject_.filled(w[0]) | clip_.filled(w[1]) << 1)) & 1U) != 0;
  }

 private:
  struct RuleTest {
    std::int64_t sign, mask;
    [[nodiscard]] unsigned filled(std::int64_t w) const {
      return ((sign * w) & mask) != 0 ? 1U : 0U;
    }
  };
  static RuleTest testOf(FillRule rule) {
    constexpr std::int64_t kSignBit = std::numeric_limits<std::int64_t>::min();
    switch (rule) {
      case FillRule::EvenOdd:
        return {1, 1};
      case FillRule::NonZero:
        return {1, -1};
      case FillRule::Positive:
        return {-1, kSignBit};
      case FillRule::Negative:
        return {1, kSignBit};
    }
    return {1, 0};
  }
  RuleTest subject_, clip_;  // without a clip, a test no winding number passes
  unsigned table_;
};

/// Where a piece of an open polyline lies relative to the region.
enum class LinePlace : std::uint8_t {
  Outside,   ///< not filled on either side
  Boundary,  ///< on the region's boundary: filled on exactly one side
  Inside,    ///< filled on both sides
};

/// Stage 2 for open pieces (classify.cpp): from the winding numbers on the two sides of the
/// closed pieces coincident with an open piece (equal when there are none).
LinePlace classifyOpenPiece(const Windings& below, const Windings& above, const BooleanSpec& spec);

/// A piece of one open input segment between two consecutive event points on it.
struct OpenPiece {
  int edge = -1;  ///< index of its segment in the sweep's input edges
  XPoint left, right;
  LinePlace place = LinePlace::Outside;
};

/// Winding numbers as an arrangement stores them. A winding number is a sum of +-1 over input
/// edges, and the sweep numbers its pieces with int, so it fits 32 bits.
using CompactWindings = std::array<std::int32_t, kOperands>;
inline CompactWindings compact(const Windings& w) {
  return {std::int32_t(w[0]), std::int32_t(w[1])};
}
inline Windings widen(const CompactWindings& w) { return {w[0], w[1]}; }

/// A grid segment in 32 bits: the line a piece lies on, while the sweep has it (SweepPiece) and
/// in the arrangement (EdgePiece).
struct GridSegment {
  /// The grid segment it lies on (lineA < lineB), in 32 bits: every grid point lies within
  /// Grid::kMaxUnits = 2^30 units of the origin.
  std::int32_t ax = 0, ay = 0, bx = 0, by = 0;
  [[nodiscard]] IPoint lineA() const { return {ax, ay}; }
  [[nodiscard]] IPoint lineB() const { return {bx, by}; }
  [[nodiscard]] IPoint direction() const { return {std::int64_t(bx) - ax, std::int64_t(by) - ay}; }
  void setLine(IPoint a, IPoint b) {
    static_assert(Grid::kMaxUnits <= (std::int64_t{1} << 30), "line coordinates fit 32 bits");
    ax = std::int32_t(a.x), ay = std::int32_t(a.y), bx = std::int32_t(b.x), by = std::int32_t(b.y);
  }
};

/// The crossing of the lines of l1 and l2 as its parameter num / den along l1 (den > 0), where
/// both fit 64 bits (all but lines near the grid range's corners); false elsewhere.
inline bool crossingParameter(const GridSegment& l1, const GridSegment& l2, std::int64_t& num,
                              std::int64_t& den) {
  const std::int64_t d1x = std::int64_t(l1.bx) - l1.ax, d1y = std::int64_t(l1.by) - l1.ay;
  const std::int64_t d2x = std::int64_t(l2.bx) - l2.ax, d2y = std::int64_t(l2.by) - l2.ay;
  const std::int64_t cx = std::int64_t(l2.ax) - l1.ax, cy = std::int64_t(l2.ay) - l1.ay;
  // Each product of two differences lies within 2^62; their difference may not fit, and
  // neither may its negation (-2^63).
  if (__builtin_sub_overflow(d1x * d2y, d1y * d2x, &den) ||
      __builtin_sub_overflow(cx * d2y, cy * d2x, &num) || den == INT64_MIN || num == INT64_MIN) {
    return false;
  }
  if (den < 0) {
    den = -den;
    num = -num;
  }
  return den != 0;
}
/// The crossing of the lines of l1 and l2, which must not be parallel, as (X/W, Y/W) with
/// W = |d1 x d2| for their directions d1 and d2, not reduced (lineIntersection() without the grid
/// test and the cached doubles). Grid coordinates lie within 2^30 of the origin, so each
/// difference fits 32 bits and each product of two 64; W and the crossing's parameter along l1
/// mostly fit 64 bits too, and then each coordinate takes two 64-by-64-bit products.
inline ExactCoords crossingOfLines(const GridSegment& l1, const GridSegment& l2) {
  const std::int64_t d1x = std::int64_t(l1.bx) - l1.ax, d1y = std::int64_t(l1.by) - l1.ay;
  std::int64_t w = 0, t = 0;
  if (crossingParameter(l1, l2, t, w)) {
    return {i128(l1.ax) * w + i128(d1x) * t, i128(l1.ay) * w + i128(d1y) * t, w};
  }
  const std::int64_t d2x = std::int64_t(l2.bx) - l2.ax, d2y = std::int64_t(l2.by) - l2.ay;
  const std::int64_t cx = std::int64_t(l2.ax) - l1.ax, cy = std::int64_t(l2.ay) - l1.ay;
  i128 den = i128(d1x * d2y) - i128(d1y * d2x);
  i128 num = i128(cx * d2y) - i128(cy * d2x);
  if (den < 0) {
    den = -den;
    num = -num;
  }
  return {i128(l1.ax) * den + i128(d1x) * num, i128(l1.ay) * den + i128(d1y) * num, den};
}

/// The winding numbers on the two sides of a piece.
struct PieceWindings {
  /// Change of each operand's winding number from the side below the piece to the side above
  /// (the sum of the directions of the coincident input edges).
  CompactWindings contribution{};
  CompactWindings windBelow{};  ///< winding numbers just below the piece
  [[nodiscard]] Windings windAbove() const {
    return {std::int64_t(windBelow[0]) + contribution[0],
            std::int64_t(windBelow[1]) + contribution[1]};
  }
};

/// A grid segment with the winding numbers on its two sides: a piece while the sweep has it.
struct LabelledSegment : GridSegment, PieceWindings {};

/// A piece of the planar arrangement: a maximal part of one or more coincident input edges
/// that no other edge crosses or touches except at its two ends. 28 bytes (W3-1k-evenodd keeps
/// 465k of them: they were 80 with 64-bit windings, 64 with 64-bit line coordinates, 44 with
/// their winding numbers, which no stage after the sweep reads).
struct EdgePiece : GridSegment {
  int left = -1;   ///< vertex id of the lexicographically smaller end
  int right = -1;  ///< vertex id of the other end
  int below = -1;  ///< the nearest result piece below this one at its left end, or -1
};
static_assert(sizeof(EdgePiece) == 28, "the arrangement keeps one per result piece");
/// In chunks of 2^13 (224 KiB): at most one chunk unused (2^15 left 0.34 MB unused on W3-1k
/// non-zero, where it peaks).
using EdgePieces = ChunkedArray<EdgePiece, 13>;

/// A vertex of the arrangement in 8 bytes, an exact point in 32 (PackedPoint) kept only where
/// needed. Nearly every vertex is a grid point or the crossing of the grid lines of two input
/// edges; the crossing is computed again from the lines when it is read (W3-1k non-zero keeps
/// 104k vertices through tracing, where it peaks: 3.3 MB as exact points). Grid coordinates lie
/// within Grid::kMaxUnits = 2^30 of the origin, so `a` beyond that range tells the other kinds:
///   a in [-2^30, 2^30]: the grid point (a, b);
///   a < -2^30: the crossing of Arrangement::lines[-2^30 - 1 - a] and lines[b];
///   a > 2^30: Arrangement::offGrid[a - 2^30 - 1] (an off-grid end of an exact edge).
struct ArrangementVertex {
  static constexpr std::int64_t kGridBound = std::int64_t{1} << 30;
  /// The largest index a crossing's first line or an off-grid point can have.
  static constexpr std::int64_t kMaxIndex = std::int64_t(INT32_MAX) - kGridBound - 1;
  std::int32_t a = 0, b = 0;
  static ArrangementVertex grid(IPoint p) { return {std::int32_t(p.x), std::int32_t(p.y)}; }
  static ArrangementVertex crossing(std::int64_t line1, std::int64_t line2) {
    return {std::int32_t(-kGridBound - 1 - line1), std::int32_t(line2)};
  }
  static ArrangementVertex offGrid(std::int64_t index) {
    return {std::int32_t(kGridBound + 1 + index), 0};
  }
  [[nodiscard]] bool onGrid() const { return a >= -kGridBound && a <= kGridBound; }
  [[nodiscard]] bool isCrossing() const { return a < -kGridBound; }
  [[nodiscard]] std::size_t line1() const { return std::size_t(-kGridBound - 1 - a); }
  [[nodiscard]] std::size_t line2() const { return std::size_t(b); }
  [[nodiscard]] std::size_t offGridIndex() const { return std::size_t(a - kGridBound - 1); }
};
static_assert(Grid::kMaxUnits <= ArrangementVertex::kGridBound, "grid points fit the range");
static_assert(sizeof(ArrangementVertex) == 8);

/// The result pieces of the planar arrangement of all input edges, in the order the sweep met
/// them (so a piece's `below` always has a smaller index), with the vertices they use in
/// lexicographic order. Pieces that do not bound the result are never stored, so memory is
/// linear in input plus output.
struct Arrangement {
  /// In chunks of 2^15 (256 KiB): grown without copies or a doubled capacity
  /// (chunked_array.hpp). The sweep appends them one at a time; how many there are is known
  /// only at its end.
  ChunkedArray<ArrangementVertex, 15> vertices;
  /// The grid lines crossing vertices refer to (each input edge's once, when it first makes
  /// one), and the vertices that are neither grid points nor such crossings.
  std::vector<GridSegment> lines;
  std::vector<PackedPoint> offGrid;
  EdgePieces pieces;
  std::vector<Side> sides;  ///< filled side of each piece (never Side::None)
  /// The winding numbers on each piece's sides, only with BooleanSpec::recordWindings.
  std::vector<PieceWindings> windings;
  /// Every piece of every open input edge, in sweep order (so the pieces of one edge come
  /// left to right).
  std::vector<OpenPiece> openPieces;
  /// Crossings the sweep found (what Limits::maxCrossings counts).
  std::uint64_t crossings = 0;
  /// Slabs whose crossings the sweep found by a slab pass (slab mode).
  std::uint64_t slabPasses = 0;

  /// Vertex v as exact coordinates (X/W, Y/W), W > 0, not reduced.
  [[nodiscard]] ExactCoords exact(int v) const {
    const ArrangementVertex& vertex = vertices[std::size_t(v)];
    if (vertex.onGrid()) return {vertex.a, vertex.b, 1};
    if (vertex.isCrossing()) return crossingOfLines(lines[vertex.line1()], lines[vertex.line2()]);
    const PackedPoint& p = offGrid[vertex.offGridIndex()];
    return {p.x(), p.y(), i128(p.w)};
  }
  /// Vertex v with its cached doubles.
  [[nodiscard]] XPoint point(int v) const {
    const ExactCoords p = exact(v);
    return XPoint(p.x, p.y, p.w);
  }
};

/// Stage 1 (split_edges.cpp): sweep line over all edges. Finds every crossing, touching vertex
/// and collinear overlap, splits edges there, merges coincident pieces, labels every piece
/// with the winding numbers on both sides and keeps the ones stage 2 classifies as result
/// boundary. O((n + k) log n) time for n edges and k crossings.
Arrangement splitEdges(const std::vector<InputEdge>& edges,
                       const std::vector<ExactEdge>& exactEdges, const BooleanSpec& spec,
                       Workspace& workspace);
/// The same on the calling thread's workspace.
Arrangement splitEdges(const std::vector<InputEdge>& edges,
                       const std::vector<ExactEdge>& exactEdges, const BooleanSpec& spec);
/// splitEdges() of the workspace's own edges (Workspace::edges and ::clipped), which it frees
/// once the sweep holds their pieces when they take more than kKeptStageBytes.
Arrangement splitWorkspaceEdges(const BooleanSpec& spec, Workspace& workspace);

/// A ring's vertex ids: a run of Contours::vertices, the one array of every ring's vertices.
struct VertexRun {
  const int* first = nullptr;
  std::size_t count = 0;
  [[nodiscard]] std::size_t size() const { return count; }
  [[nodiscard]] const int* begin() const { return first; }
  [[nodiscard]] const int* end() const { return first + count; }
  [[nodiscard]] std::reverse_iterator<const int*> rbegin() const {
    return std::reverse_iterator<const int*>(end());
  }
  [[nodiscard]] std::reverse_iterator<const int*> rend() const {
    return std::reverse_iterator<const int*>(begin());
  }
  int operator[](std::size_t i) const { return first[i]; }
};

/// A closed ring traced from result pieces, filled on its left.
struct TracedRing {
  /// vertex ids, each once; straight-on vertices removed except touch points (where other
  /// result pieces meet the ring)
  VertexRun vertices;
  int referencePiece = -1;  ///< its lowest piece at its leftmost vertex
  /// The nearest result piece below the reference piece's left end (EdgePiece::below), or -1:
  /// all that nesting reads of the pieces, so they can be freed before it.
  int belowPiece = -1;
  bool hole = false;  ///< true when the region inside is not filled
};

/// Stage 3 (trace_contours.cpp): link result pieces into simple closed rings with the paper's
/// stack method (push vertices; when a vertex repeats, pop a contour), filled side on the left,
/// so outer rings run counter-clockwise in the raw frame and holes clockwise.
struct Contours {
  std::vector<TracedRing> rings;
  std::vector<int> ringOfPiece;  ///< ring index of each result piece, -1 for the others
  /// Every ring's vertex ids, ring after ring (one allocation, not one per ring). The rings
  /// point into it: a Contours moves (the array keeps its storage) but is not copied.
  std::vector<int> vertices;
  /// Vertices that more than one ring passes (where rings touch: every crossing that two rings
  /// of an even-odd result share).
  std::size_t sharedVertices = 0;

  Contours() = default;
  Contours(Contours&&) = default;
  Contours& operator=(Contours&&) = default;
  Contours(const Contours&) = delete;
  Contours& operator=(const Contours&) = delete;
  ~Contours() = default;
};
Contours traceContours(const Arrangement& arrangement);
/// The same, with its working arrays from `scratch` (a Workspace's; no allocation for them once
/// they are large enough).
Contours traceContours(const Arrangement& arrangement, TraceScratch& scratch);

/// Snap one operand's paths to the grid as closed rings of grid points (repeats and straight
/// runs removed); rings with fewer than 2 points are dropped.
std::vector<std::vector<IPoint>> snapRings(const Paths& paths, int operand, const Grid& grid);
/// The same into `rings`, reusing the arrays of the rings it holds.
void snapRingsInto(const Paths& paths, int operand, const Grid& grid, Rings& rings);

/// A ring's lexicographically smallest vertex and the turn there: for a simple ring, +1 when it
/// runs counter-clockwise (winds +1 around its inside), -1 clockwise.
struct LowestVertex {
  std::size_t index = 0;
  bool ccw = false;
};
inline LowestVertex lowestVertex(const std::vector<IPoint>& ring) {
  const std::size_t n = ring.size();
  const std::size_t i = std::size_t(std::min_element(ring.begin(), ring.end()) - ring.begin());
  return {i, orientInGrid(ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n]) > 0};
}

/// The simple-ring test (simple_ring.cpp): whether a ring from snapRings() is simple (distinct
/// vertices, consecutive edges meet only at their shared vertex and are not collinear, no other
/// edges meet). A sweep over the ring's lexicographically monotone chains: O(n log c) for n
/// vertices in c chains; it stops at the first contact.
/// `turnsChecked`: the caller has asked turnsOnce() already.
bool ringIsSimple(const std::vector<IPoint>& ring, ChainScratch& scratch,
                  bool turnsChecked = false);
/// Whether the ring's edge direction turns exactly once round (rotation index +-1) without a
/// spike or a straight-on vertex: true for every simple ring (Hopf), false for most that cross
/// themselves (a figure eight turns 0 times, a ring with a loop twice). O(n), a cross product per
/// vertex: asked first by ringIsSimple().
bool turnsOnce(const std::vector<IPoint>& ring);
/// The region a simple ring fills under `rule` (it winds +1 or -1 around its inside), exactly as
/// stages 1 to 4 emit it: none, or one polygon, its vertices the ring's, in roiclip's output
/// orientation, the path ending at the lexicographically smallest vertex.
PolygonSet simpleRingRegion(const std::vector<IPoint>& ring, FillRule rule, const Grid& grid);

/// What is known of one ring's vertices against the side lines of a strictly convex ring C
/// (SideLines::classify(), bits as SideLines::Masks), so that Weiler-Atherton need not classify
/// them again: nothing (the default), every vertex strictly inside C, or the masks of each vertex
/// in the ring's stored order.
struct KnownSides {
  const unsigned* left = nullptr;    ///< per vertex: the sides it lies strictly left of, or null
  const unsigned* onLine = nullptr;  ///< per vertex: the side lines it lies on (with `left`)
  bool inside = false;               ///< every vertex lies strictly inside C
};

/// The intersection of a ring, filled under `rule`, with a strictly
/// convex ring of orientation `convexOrientation` (convexOrientation()), by Weiler-Atherton on
/// the two boundaries (simple_convex.cpp), into `out` exactly as stages 1 to 4 emit it. Returns
/// true with an empty result for any ring (simple or not) with no vertex strictly inside some
/// side line of the convex ring. Otherwise returns false, and leaves the case to the general
/// path, unless the ring is simple (ringIsSimple(), asked after the cheaper test of its
/// vertices against the convex ring) and every meeting of the boundaries is a transversal
/// crossing, a vertex of the simple ring on the convex one's boundary (a crossing or a touch
/// there), or at a corner of it; no edge of the simple ring along a side's line or with its line
/// through a corner it does not end at. O(n m + k log k).
/// `known`: what is known of the ring's vertices against C's sides (groupRingsForConvex()).
bool intersectSimpleConvex(const std::vector<IPoint>& ring, FillRule rule,
                           const std::vector<IPoint>& convex, int convexOrientation,
                           const Grid& grid, ChainScratch& chains, WeilerScratch& scratch,
                           PolygonSet& out, const KnownSides& known = {});

/// The same for a set of rings: each simple and no two meeting. Leaves in `scratch` what
/// simpleRingsRegion() needs (the chain below each ring's smallest vertex). `merged`: the rings
/// are as snapRings() leaves them, with no vertex where a ring goes straight on or back (the
/// collinear edges the sweep leaves to turnsOnce()), so turnsOnce() is not asked: the sweep finds
/// every other contact. (A single ring keeps asking it first: it rejects a self-crossing ring,
/// such as W2's epitrochoid, at once: without it W2's rows cost 13% to 18% more instructions,
/// the sweep running up to the first crossing.)
bool ringsAreSimple(const Rings& rings, ChainScratch& scratch, bool merged = false);
/// The region a set of rings that ringsAreSimple() accepted fills under `rule`, with holes and
/// nesting, exactly as stages 1 to 4 emit it (one pass over the rings, nesting from the sweep).
PolygonSet simpleRingsRegion(const Rings& rings, FillRule rule, ChainScratch& scratch,
                             const Grid& grid);
/// The same on the nesting nestSimpleRings() left in `scratch` for `rings`.
PolygonSet nestedRingsRegion(const Rings& rings, ChainScratch& scratch, const Grid& grid);

/// The nesting of a set of rings that ringsAreSimple() accepted (just before, on `scratch`),
/// under `rule`: scratch.nesting gets each ring's smallest vertex, the innermost ring around it,
/// its winding number, whether it bounds the region and the innermost such ring around it.
void nestSimpleRings(const Rings& rings, FillRule rule, ChainScratch& scratch);
/// A simple ring's output path, as stages 1 to 4 trace it with the filled side on the left and
/// emit it reversed: an outer ring traced from its smallest vertex, a hole from the other end of
/// its lower edge there (where the trace of its lowest piece starts).
Path simpleRingPath(const std::vector<IPoint>& ring, LowestVertex lowest, bool hole,
                    const OutputFrame& frame);

/// Rings touching themselves or each other only at vertices, as separatePinches() prepares them
/// (pinches.cpp), and the stage's working arrays (the workspace keeps one between groups and
/// calls).
struct PinchedRings {
  struct Pinch {
    IPoint at;
    int ring, other;        ///< the two rings of `rings` through it
    int index, otherIndex;  ///< its index in each
  };
  /// A visit of a point: a ring and the index of the point in it.
  struct Visit {
    int ring, index;
  };
  /// The rings split where one visits a vertex twice: each visits each vertex once; every
  /// point that two visit is a pinch. The rings given (which must outlive this use), or
  /// `split` when one was split.
  const Rings* rings = nullptr;
  KeptRings split;
  /// The same rings (same indices) with one of the two corners at each pinch cut off by a grid
  /// step along its edges: simple and pairwise apart (ringsAreSimple()) only if `rings` meet
  /// nowhere but at the pinches, touching there without crossing. Their nesting is that of
  /// `rings`.
  KeptRings separated;
  std::vector<Pinch> pinches;
  /// The rings stages 1 to 4 trace where pinches join the rings of one face in a cycle
  /// (pinchedRingsRegion()).
  KeptRings traced;
  /// The pinches strictly inside the convex ring (boolean_op.cpp's intersectPinched()).
  std::vector<Pinch> touching;
  // The working arrays: a hash table of the points, the points visited twice (pairs of
  // visits), where the split moved each vertex, a ring's vertices visited twice (the other
  // visit's index, or -1), the stack of the split, each ring's first vertex (flat), and the
  // vertices whose corner is cut.
  std::vector<std::uint64_t> table;
  std::vector<Visit> twice, moved;
  std::vector<int> partner, stack, position;
  std::vector<std::size_t> start;
  std::vector<char> selfPinched, cut;
  /// What the grouping knew of the vertices, moved with them into the split rings
  /// (boolean_op.cpp): per split ring, and each vertex's masks flat by `start`.
  std::vector<KnownSides> known;
  std::vector<unsigned> knownLeft, knownOnLine;
  template <class F>
  void forEach(F f) {
    f(known);
    f(knownLeft);
    f(knownOnLine);
    f(split);
    f(separated);
    f(pinches);
    f(traced);
    f(touching);
    f(table);
    f(twice);
    f(moved);
    f(partner);
    f(stack);
    f(position);
    f(start);
    f(selfPinched);
    f(cut);
  }
};
/// intersectSimpleConvex() for a set of rings that ringsAreSimple() accepted (just before, on
/// `chains`): Weiler-Atherton over every ring that bounds the region, holes walked clockwise;
/// rings inside C stay whole, and a hole inside C goes to the walked ring along its outer ring's
/// face. False (the general path) under intersectSimpleConvex()'s conditions, and when a ring
/// that bounds the region runs around C, or walked rings along one outer ring's face are several
/// and a hole inside C would need a point test to choose among them.
/// `known`, when not null: what is known of each ring's vertices (as for one ring above).
/// `touchingInC`, when not null: the pinches of separatePinches() strictly inside C; false
/// unless pinchesKeepRings() holds with the rings across C's boundary of each face counted as
/// one (the walked rings may join them).
bool intersectSimpleRingsConvex(const Rings& rings, FillRule rule,
                                const std::vector<IPoint>& convex, int convexOrientation,
                                const Grid& grid, ChainScratch& chains, WeilerScratch& scratch,
                                PolygonSet& out, const KnownSides* known = nullptr,
                                const std::vector<PinchedRings::Pinch>* touchingInC = nullptr);

/// What separatePinches() made of a set of rings.
enum class Pinches {
  separated,    ///< `out` holds them, ready for the simple-ring test
  none,         ///< no point is visited twice (or the stage could not look: too few low zero bits)
  overlapping,  ///< two edges leave a point the same way, or a point is visited three times:
                ///< cancelOverlaps() may take them
  refused,      ///< points are visited twice, but the stage cannot separate them
};
/// Prepares rings for the sweep-free paths where they touch only at vertices (pixel contours
/// meeting at a pixel corner). Refused when two edges at a pinch overlap, two rings cross at
/// one, or a loop split off a ring has fewer than three vertices; `none` also when the vertices
/// lack the common low zero bits the cut needs (a fitted grid's pixel coordinates have about 20;
/// 12 needed). A point visited twice fails the simple-ring test, so only `none` leaves that test
/// anything to take.
Pinches separatePinches(const Rings& rings, PinchedRings& out);
/// Prepares rings whose edges run along each other (overlaps.cpp): edges on one line split at
/// the ends of the others inside them, equal edges in opposite directions cancelled, the rest
/// linked into rings with the same winding numbers off the cancelled edges, each visiting each
/// point once, straight-on vertices dropped. `touching`: whether the rings still share a point
/// (the pinch stage's case). False when nothing cancels, or when two edges run the same way
/// along each other, a point has several cancelled ends to pair, or a ring goes straight on
/// through another's point or back along itself.
bool cancelOverlaps(const Rings& rings, KeptRings& out, bool& touching, OverlapScratch& scratch);
/// Whether stages 1 to 4 return the pinched rings as they are, with `nesting` as
/// nestSimpleRings() leaves it for them. Stages 1 to 4 pair the edges at a pinch around each
/// filled sector, then split a ring that visits a vertex twice. Rings of two faces of the region
/// (two outer rings side by side, an island in a hole) stay as they are. The rings of one face
/// (an outer ring and its holes) that pinches join are traced as one ring and split again, which
/// gives them back when those pinches join them in a forest, and other rings when they join them
/// in a cycle (a hole touching its outer ring at two vertices leaves two polygons, not one with
/// that hole).
/// `joinedInFace`, when not null: rings that count as one with the others so marked in their
/// face.
bool pinchesKeepRings(const std::vector<PinchedRings::Pinch>& pinches,
                      const std::vector<RingNesting>& nesting,
                      const std::vector<char>* joinedInFace = nullptr);
/// The region of pinched rings whose separated rings ringsAreSimple() accepted (just before, on
/// `scratch`), as simpleRingsRegion(). When pinches join the rings of a face in a cycle, the
/// rings stages 1 to 4 trace there (PinchedRings::traced) take the stage again: false when it
/// refuses them or pinchesKeepRings() fails for them. Reuses `pinched`'s arrays.
bool pinchedRingsRegion(PinchedRings& pinched, FillRule rule, ChainScratch& scratch,
                        const Grid& grid, PolygonSet& out);

/// Whether every vertex of the rings lies inside the convex ring (orientation
/// `convexOrientation`) or on its boundary: then so does everything they fill, and their
/// intersection with it is their region. Stops at the first vertex outside.
bool ringsInsideConvex(const Rings& rings, const std::vector<IPoint>& convex,
                       int convexOrientation);

/// The rings of a subject that meet a strictly convex ring C, in groups that its intersection
/// with C can take one at a time (convex_groups.cpp).
struct RingGroups {
  std::vector<int> rings;               ///< indices of the rings that meet C, group after group
  std::vector<std::size_t> groupStart;  ///< where each group begins in `rings`, and the end
  std::size_t apart = 0;                ///< rings that do not meet C
  /// Per ring of the input: 1 when every vertex lies in C or on its boundary (as
  /// ringsInsideConvex() tells for a set of rings).
  std::vector<char> inClosed;
  /// Per vertex of the input, ring after ring (from vertexStart[r]): the side masks of the
  /// vertices of each ring whose vertices the grouping classified one by one (sidesOf()); left
  /// uninitialised for the others.
  std::unique_ptr<unsigned[]> left, onLine;
  std::vector<std::size_t> vertexStart;
  /// Per ring: kNothing, kInside (its bounding box lies strictly inside C) or kMasks.
  enum : char { kNothing, kInside, kMasks };
  std::vector<char> known;
  [[nodiscard]] std::size_t count() const { return groupStart.size() - 1; }
  /// What the grouping learnt of ring r's vertices.
  [[nodiscard]] KnownSides sidesOf(std::size_t r) const {
    if (known[r] == kInside) return {nullptr, nullptr, true};
    if (known[r] == kMasks) return {left.get() + vertexStart[r], onLine.get() + vertexStart[r]};
    return {};
  }
  /// Whether every ring of group g lies in C or on its boundary.
  [[nodiscard]] bool groupInClosed(std::size_t g) const {
    for (std::size_t k = groupStart[g]; k < groupStart[g + 1]; ++k) {
      if (inClosed[std::size_t(rings[k])] == 0) return false;
    }
    return true;
  }
};
/// Splits `rings` into groups for the intersection with the strictly convex ring `convex`: a ring
/// that does not meet C (or has fewer than 3 vertices) is left out, and the bounding boxes of the
/// rest are cut into groups with a gap between any two, so that within C the subject's region is
/// the disjoint union of the groups' regions and no two of them touch. False when the rings left
/// out wind around C in total (then every point of C gets that winding number from them) or C has
/// more than kMaxSides sides. O(n m) for n vertices and m sides of C, plus O(r log r) a level of
/// cuts for r rings.
bool groupRingsForConvex(const Rings& rings, const std::vector<IPoint>& convex,
                         int convexOrientation, RingGroups& out);

/// The ring's orientation (+1 counter-clockwise in the raw frame, -1 clockwise) when it is a
/// strictly convex polygon winding once, else 0. The ring's points are grid points (snapped:
/// within the grid's range, see orientInGrid()).
int convexOrientation(const std::vector<IPoint>& ring);

/// Convex pre-clip (convex_clip.cpp): Sutherland-Hodgman against each half-plane of a convex
/// ring, exactly. Inside the ring, every winding number of `rings` is preserved; outside it,
/// every winding number becomes 0. Output edges lie on integer input or clip segments: the
/// input edges lying in the convex ring as they are in `edges`, the clipped ones in `out` (both
/// cleared first). Every point of `rings` and `convexRing` lies within the grid's range
/// (orientInGrid()), as snapRings() makes them.
/// `orientation` is convexOrientation(convexRing), computed once by the caller. `known`, when
/// not null, holds for each ring what the grouping learnt of its vertices against the convex
/// ring's sides (RingGroups::sidesOf()): those masks are taken instead of classifying again.
void preclipConvex(const Rings& rings, const std::vector<IPoint>& convexRing, int orientation,
                   Workspace& workspace, std::vector<InputEdge>& edges, std::vector<ExactEdge>& out,
                   const KnownSides* known = nullptr);
/// The same on the calling thread's workspace, computing the orientation, every edge in `out`.
void preclipConvex(const Rings& rings, const std::vector<IPoint>& convexRing,
                   std::vector<ExactEdge>& out);
/// The plain pre-clip, every ring through every half-plane step whole (the tests' reference):
/// the same winding numbers as preclipConvex().
void preclipConvexReference(const Rings& rings, const std::vector<IPoint>& convexRing,
                            std::vector<ExactEdge>& out);

/// Stage 4 (nesting.cpp): give each hole its outer ring and each outer ring the hole it lies
/// in, and emit the polygons in image coordinates with roiclip's output orientation, every
/// coordinate correctly rounded (output.hpp). `grid` is the call's resolved grid, as for every
/// stage (resolveGrid()). Reads the arrangement's vertices, not its pieces (the rings carry
/// what it needs of them): a caller may free the pieces first.
PolygonSet buildNesting(const Arrangement& arrangement, const Contours& contours, const Grid& grid);
/// The same, with its working arrays from `scratch` (a Workspace's).
PolygonSet buildNesting(const Arrangement& arrangement, const Contours& contours, const Grid& grid,
                        NestingScratch& scratch);

/// Stage 5, on request (snap_round.cpp, roundTo()): snap rounding. The pixel (the half-open
/// square [c - 1/2, c + 1/2) of `unitsPerStep` working units around a point c of the step grid) of
/// every vertex of the arrangement is hot; every result piece becomes the chain through the centres
/// of the hot pixels it meets, in the order it meets them, directed with the filled side on its
/// left. Returns those chains as input edges in step units (operand 0, winding +1 inside).
std::vector<InputEdge> snapRoundPieces(const Arrangement& arrangement, std::int64_t unitsPerStep);
/// The region the chains of a rounding pass bound (winding number > 0), rebuilt by the core;
/// while the rebuild has a vertex off the step grid, it is rounded again (snapRoundPieces() in
/// step units, every vertex's pixel hot) and rebuilt, each time adding 1 to `passes` (the passes
/// that made `chains`). Snap rounding's chains never cross (Hobby; Guibas-Marimont), so the first
/// rebuild is on the grid unless a hot pixel was missed: the repeat is the guard.
/// @throws InternalError when that would make more than 8 passes.
Arrangement rebuildOnStepGrid(std::vector<InputEdge> chains, int& passes);
/// roundTo(), also giving the number of rounding passes it took (rebuildOnStepGrid()).
PolygonSet roundToCountingPasses(const PolygonSet& region, double step, int& passes);

/// The general path (every operation, no convex shortcut): stages 0 to 4.
PolygonSet booleanGeneral(const Paths& subject, const Paths* clipPaths, const BooleanSpec& spec,
                          const Grid& grid);

/// The bounding box of the finite coordinates of some paths (resolveGrid(), PreparedRegion). NaN
/// coordinates and points with an infinite one are skipped (the other coordinate of a point
/// with a NaN may count): the snapping reports them, naming the path and vertex.
struct Box {
  double minX = INFINITY, maxX = -INFINITY, minY = INFINITY, maxY = -INFINITY;
  /// Every coordinate added is a finite integer below 2^51 in magnitude (false also when one is
  /// larger): then every power-of-two grid of scale 1 or more holds them all (resolveGrid()).
  bool integral = true;
  /// No coordinate added is NaN or infinite, so every vertex of those paths lies in the box
  /// (false also when one reaches 2^51 in magnitude, where the pass does not tell them apart).
  bool finite = true;
  /// One pass over the coordinates (grid.cpp).
  void add(const Paths& paths);
  [[nodiscard]] bool empty() const { return !(minX <= maxX); }
};

/// resolveGrid() that also gives the box of the subject's vertices, which a fitted grid is made
/// from; with a fixed grid no pass is made and `subjectBox` stays empty (nothing known).
Grid resolveGrid(const Grid& grid, const Paths& subject, const Paths& clip, Box& subjectBox);

/// Where the vertices of some paths lie relative to a strictly convex ring C (of orientation
/// `convexOrientation`), decided from their box before they are snapped. Snapping is monotone, so
/// the snapped box's corners are the box's corners snapped; a half-plane is convex, so it holds
/// the box when it holds its corners. Constant time.
enum class BoxPlace {
  Unknown,  ///< the box tells nothing: it meets C's boundary, or it is empty, not finite, outside
            ///< the grid's range (the snapping reports those), or C has more than kMaxSides sides
  Outside,  ///< every vertex in a closed half-plane that holds no point inside C (the outer one
            ///< of a side, or one beyond C's extreme x or y): nothing they fill is in C
  Inside,   ///< every vertex strictly inside C
};
BoxPlace placeBox(const Box& box, const Grid& grid, const std::vector<IPoint>& convex,
                  int convexOrientation);
struct SnappedOperand;
/// The same against a snapped clip operand: Unknown unless it is one strictly convex ring.
BoxPlace placeBox(const Box& box, const Grid& grid, const SnappedOperand& clip);

/// The grids a fitted grid resolves to (grid.cpp; resolveGrid() and PreparedRegion use them).
/// The power-of-two grid fitted to a box: the largest s = 2^e with s * side <= 2^31 - 8, the
/// origin a grid point near the centre. Throws InvalidInputError when the box's side overflows.
Grid fitBinaryGrid(const Box& box);
/// True when `grid` holds every finite coordinate v of `paths` exactly: its grid point
/// n = round(v * scale) gives v back, the double nearest n / scale (for a power of two: v * scale
/// is an integer).
bool holdsExactly(const Grid& grid, const Paths& paths);
/// Which decimal grid fitDecimalGrid() picks among those that hold the data.
enum class DecimalPick {
  Coarsest,  ///< the smallest k (the decimals the data was written with)
  Finest,    ///< the largest k the box allows (PreparedRegion: room for subjects' decimals)
};
/// A decimal grid, scale 10^k (0 <= k <= 22), that holds every coordinate of `a` and `b`
/// exactly: each is the double nearest to a multiple of 10^-k, |v| * 10^k <= 2^50, and `range`
/// (a box around them) fits in +-2^30 units of the origin, a grid point near its centre.
/// nullopt when there is none.
std::optional<Grid> fitDecimalGrid(const Box& range, const Paths& a, const Paths& b,
                                   DecimalPick pick);

/// One operand, snapped and validated once: its rings, its fill rule, and the orientation of
/// its ring when it is a single strictly convex one (convexOrientation(), else 0).
struct SnappedOperand {
  Rings rings;
  FillRule rule = FillRule::EvenOdd;
  int convex = 0;
};
/// `findConvex` false leaves `convex` 0 (a caller that will not take the convex path for it).
/// With a workspace, the rings are made in the arrays its Workspace::operandRings[operand] kept
/// from the call before; giveBackRings() returns them when the call is done.
SnappedOperand snapOperand(const Paths& paths, int operand, FillRule rule, const Grid& grid,
                           bool findConvex = true, Workspace* workspace = nullptr);
/// Keeps a snapped operand's rings in the workspace for the next call (up to kKeptOutputBytes).
void giveBackRings(SnappedOperand& snapped, int operand, Workspace& workspace);

/// clip() on snapped operands (boolean_op.cpp): the convex fast path for an intersection with a
/// convex operand, else the general path. On the general path the subject's rings are freed
/// once read; on the convex path its groups borrow them (moved out and back: unchanged unless
/// the call throws). `subjectPlace`: where the subject lies relative to a convex clip
/// (placeBox()).
PolygonSet clipSnapped(ClipOp op, SnappedOperand& subject, const SnappedOperand& clip,
                       const Grid& grid, const Limits& limits, Workspace& workspace,
                       BoxPlace subjectPlace = BoxPlace::Unknown);

/// clipLines() on a snapped region (clip_lines.cpp): `edges` holds the polylines' edges from
/// appendLineEdges() (the region's are appended), `firstEdge` where each polyline starts.
Paths clipLinesSnapped(std::vector<InputEdge>& edges, const std::vector<std::size_t>& firstEdge,
                       const SnappedOperand& region, LinePart part, const Grid& grid,
                       const Limits& limits, Workspace& workspace);

}  // namespace roiclip::detail
