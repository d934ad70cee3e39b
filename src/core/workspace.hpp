// SPDX-License-Identifier: MIT
// roiclip private header: the one workspace. Every working array the pipeline keeps between
// calls lives here, in one object: the sweep's pieces, start events and event queue, the convex
// pre-clip's two path buffers and its output edges. A free function borrows the calling
// thread's workspace (WorkspaceLease); a PreparedRegion owns its own.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <deque>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

#include <boost/container/vector.hpp>
#include <boost/intrusive/set.hpp>

#include "pipeline.hpp"

namespace roiclip::detail {

/// Allocating the per-edge arrays afresh costs a page fault per 4 KiB touched, which on a
/// 100k-vertex contour took about as long as the clipping itself, so they are kept between
/// calls. recycle() empties an array after use and keeps its capacity up to kKeptScratchBytes;
/// a larger one is freed.
constexpr std::size_t kKeptScratchBytes = std::size_t(64) << 20;
/// The bytes an array holds (for rings, with their own arrays: bytesOf() in pipeline.hpp).
template <class V>
std::size_t bytesOf(const V& v) {
  return v.capacity() * sizeof(typename V::value_type);
}
inline std::size_t bytesOf(const KeptRings& rings) { return rings.bytes(); }
template <class V>
void recycle(V& v) {
  if (bytesOf(v) > kKeptScratchBytes) {
    V().swap(v);
  } else {
    v.clear();
  }
}

/// The general path frees each working array of a stage that holds more than this once the
/// stage is done with it: the next stage's arrays then take its place instead of adding to the
/// call's peak (W2-1k even-odd held its 481 sweep pieces, 92 KB, through tracing and nesting).
/// Smaller ones are kept, so a small call repeated on a thread allocates none of them. Freeing
/// and allocating the larger ones again costs W2 and W5 up to 2% more instructions (3 to 8% of
/// their time in alternating runs; bench/RESULTS.md, speed session 16).
constexpr std::size_t kKeptStageBytes = std::size_t(4) << 10;
/// Frees each of `arrays` that holds more than `bytes` (TraceScratch::releaseIfAbove() instead
/// frees its arrays together, by their sum).
template <class... V>
void releaseEachAbove(std::size_t bytes, V&... arrays) {
  const auto one = [bytes](auto& v) {
    if (bytesOf(v) > bytes) std::remove_reference_t<decltype(v)>().swap(v);
  };
  (..., one(arrays));
}

/// The arrays of a call's arrangement and traced contours are lent from the workspace and given
/// back when the call is done with them (keepIfSmall()), up to this size each: a small call (W4:
/// 10,000 contours of ~20 vertices) then allocates none of them. Larger ones are freed, as
/// nesting, where a large call peaks, should not hold them.
constexpr std::size_t kKeptOutputBytes = std::size_t(1) << 20;
/// (For a set of rings, a snapped operand's, by the storage of all of them together.)
template <class V>
void keepIfSmall(V& used, V& kept) {
  if (bytesOf(used) <= kKeptOutputBytes) kept.swap(used);
  V().swap(used);
}

/// The sweep's status (the active pieces bottom to top) is an intrusive red-black tree over a
/// pool of nodes: no allocation per insertion, and a node keeps its place in the tree when the
/// piece it holds changes (a chain going on, two pieces crossing). The nodes are also threaded
/// bottom to top (below / above): the sweep steps to a neighbour through these links, where a
/// tree step climbs and descends with branches no predictor learns (on W3 the tree's steps made
/// 4.6M of the call's 12.8M mispredicted branches). The tree serves searches and insertion only.
using StatusHook =
    boost::intrusive::set_member_hook<boost::intrusive::link_mode<boost::intrusive::normal_link>,
                                      boost::intrusive::optimize_size<true>>;
struct StatusNode {
  StatusHook hook;
  int piece = -1;
  StatusNode* below = nullptr;  ///< the node next below it in the status, null at the bottom
  StatusNode* above = nullptr;  ///< the node next above it, null at the top
};

/// An active piece in a slab pass (split_edges.cpp): its height at the slab's right end x = X,
/// num / dx with num = ay dx + dy (X - ax) (|num| < 2^63: coordinates within 2^30 units of the
/// origin), and dx > 0 (no vertical piece spans a slab); `height` is the quotient as a double
/// (within 2^-52 of it, relative: a cached double in the grid's range, compareCachedInBox()).
struct SlabEntry {
  std::int64_t num = 0;
  std::int64_t dx = 1;
  double height = 0;
  int piece = -1;
};

/// A vertex of a chain, as a place along it: ring index `j`, with `left` vertices of the chain
/// after it (-1: past its last vertex).
struct ChainCursor {
  int j = 0;
  int left = -1;
};
/// An x-monotone chain of a ring in the simple-ring test (simple_ring.cpp): its edges run from
/// ring index `first` (its leftmost vertex) `edges` steps in direction `step`, x never
/// decreasing (vertical edges inside); its status links; and three places along it, each only
/// moving on: `down` and `up`, its first vertex not yet tested against the chain below and the
/// one above it, and `at`, where the status's search last located an x against it.
struct ChainNode {
  StatusHook hook;
  ChainNode* below = nullptr;
  ChainNode* above = nullptr;
  const IPoint* points = nullptr;  ///< its ring's vertices (the sweep's hot path reads them here)
  int size = 0;                    ///< and their number
  int ring = 0;                    ///< which ring of the set
  int step = 0;   ///< +1 when the chain runs forward through the ring (x grows), -1 backward
  int first = 0;  ///< ring index of its first (leftmost) vertex, a turning vertex
  int edges = 0;
  /// The chains it shares its first and its last vertex with (turning vertices of the ring).
  int startPartner = -1, endPartner = -1;
  ChainCursor down, up;
  mutable ChainCursor at;  ///< moved on by the status's search (a const comparison)
  /// The ring index one step along the chain from i, and one step back.
  [[nodiscard]] int after(int i) const { return wrap(i + step); }
  [[nodiscard]] int before(int i) const { return wrap(i - step); }
  /// i in [-1, size]: one test on the path a chain takes at all but one of its steps.
  [[nodiscard]] int wrap(int i) const {
    if (__builtin_expect(unsigned(i) < unsigned(size), 1)) return i;
    return i < 0 ? size - 1 : 0;
  }
  /// The vertex before a cursor's (not at the first vertex), and the cursor's own: the edge
  /// that ends at the cursor.
  [[nodiscard]] IPoint start(ChainCursor c) const { return points[before(c.j)]; }
  [[nodiscard]] IPoint end(ChainCursor c) const { return points[c.j]; }
  /// The next vertex's cursor.
  [[nodiscard]] ChainCursor next(ChainCursor c) const { return {after(c.j), c.left - 1}; }
  /// The status is built by position (insert_before), never by comparing two nodes: the
  /// comparison the tree's type asks for.
  struct NeverCompared {
    bool operator()(const ChainNode& /*unused*/, const ChainNode& /*unused*/) const {
      return false;
    }
  };
};
/// A turning vertex of a ring as the simple-ring test visits it: its StartFrame key and the two
/// chains `chain` and `pair` that start or end there.
struct ChainEvent {
  std::uint64_t key;
  int chain;
  int pair;
  /// Left unset: the radix sort's second array is sized (resize()) and then written in full,
  /// and zero-filling it first cost W1-100k 1% of its instructions.
  ChainEvent() {}  // NOLINT(modernize-use-equals-default): = default would zero it in resize()
  ChainEvent(std::uint64_t k, int c, int p) : key(k), chain(c), pair(p) {}
};
/// What simpleRingsRegion() works out per ring: its smallest vertex and orientation, the
/// innermost ring around it, the winding number just inside, whether it bounds the result and
/// which polygon or hole it became.
struct RingNesting {
  LowestVertex lowest;
  int around = -1;        ///< the innermost ring around it, or -1
  int resultAround = -1;  ///< the innermost ring around it that bounds the result, or -1
  int winding = 0;        ///< the winding number just inside it
  bool inResult = false;  ///< filled on one side only
  bool filledInside = false;
  bool dropped = false;  ///< rounding collapsed it, or a ring around it
  int polygon = -1;      ///< its polygon (outer rings)
  int hole = -1;         ///< its index among its outer ring's holes (holes)
};

/// The working arrays of ringIsSimple() / ringsAreSimple(): the chains and the turning vertices'
/// events in lexicographic order; for a set of rings, the chain below each ring's
/// smallest vertex (-1: none) and the rings in the order the sweep reached them, then
/// simpleRingsRegion()'s per-ring results.
struct ChainScratch {
  std::vector<ChainNode> chains;
  std::vector<ChainEvent> events, sorted;  ///< sorted: the radix sort's second array
  std::vector<int> below, reached;
  std::vector<RingNesting> nesting;
  /// Set when the last test stopped at a contact where two chains meet without crossing there
  /// (a shared point, a vertex on an edge, edges along each other), not at a crossing: the
  /// rings may touch only, which the pinch stage can take.
  bool touched = false;
  template <class F>
  void forEach(F f) {
    f(chains);
    f(events);
    f(sorted);
    f(below);
    f(reached);
    f(nesting);
  }
};
/// The working arrays of cancelOverlaps() (overlaps.cpp).
struct OverlapScratch {
  /// The line of an edge: its direction reduced and turned to point right (or up), and its
  /// offset along the normal.
  struct Line {
    IPoint u;
    std::int64_t offset = 0;
    bool operator==(const Line& o) const { return u == o.u && offset == o.offset; }
  };
  /// An edge's extent along its line.
  struct Span {
    std::int64_t lo, hi;
    int edge;
  };
  /// A point to insert in an edge (by its first vertex), at position `along` from its start.
  struct Split {
    int edge;
    std::int64_t along;
    IPoint at;
  };
  // The line pass: a table of lines (the last edge on each, chained by nextOnLine).
  std::vector<int> lineHead, nextOnLine, sharedLines;
  std::vector<Line> lines;
  std::vector<Span> spans;
  std::vector<std::int64_t> stops;
  std::vector<Split> splits;
  KeptRings split;    ///< the rings with the splits inserted
  KeptRings reduced;  ///< cancelOverlaps()'s output, when intersectOverlapping() calls it
  // The vertices, flat (each ring's first at `first`): successor, predecessor, the next visit of
  // the same point (circular, -1: visited once) and the point's first visit; the table of points.
  std::vector<std::size_t> first;
  std::vector<IPoint> points;
  std::vector<int> next, prev, same, rep, sharedPoints, succ, stack, onStack;
  std::vector<std::uint64_t> table;
  std::vector<char> cancelled, claimed, walked;
  int lowZeroBits = 0;  ///< the low zero bits every coordinate has (the hash shifts them out)
  template <class F>
  void forEach(F f) {
    f(lineHead);
    f(nextOnLine);
    f(sharedLines);
    f(first);
    f(lines);
    f(spans);
    f(stops);
    f(splits);
    f(split);
    f(reduced);
    f(points);
    f(next);
    f(prev);
    f(same);
    f(rep);
    f(sharedPoints);
    f(succ);
    f(stack);
    f(onStack);
    f(table);
    f(cancelled);
    f(claimed);
    f(walked);
  }
};
/// A crossing of a simple ring's boundary with a convex ring's (simple_convex.cpp).
struct BoundaryCrossing {
  XPoint x;
  int edge = 0;  ///< the simple ring's edge it lies on (counter-clockwise index)
  int side = 0;  ///< the convex ring's side it lies on (counter-clockwise index)
  int ring = 0;  ///< the ring of a set it lies on
  bool entering = false;
};
/// A point of a ring walked by intersectSimpleConvex(): a vertex of a ring or of C (a grid
/// point), or one of the crossings (its index in WeilerScratch::crossings). 24 bytes, where an
/// XPoint takes 64: most walked points are grid vertices.
struct WalkPoint {
  IPoint p;
  int crossing = -1;  ///< -1: the grid point p
};
/// The working arrays of intersectSimpleConvex(): the sides of each vertex, the crossings in
/// both orders, and the result rings, one array of points.
struct WeilerScratch {
  /// Per vertex of the ring walked, overwritten in full by each call: sized without the zero
  /// fill of std::vector::resize() (W1-100k: 1.5% of its instructions).
  boost::container::vector<unsigned> left, onLine;
  std::vector<BoundaryCrossing> crossings;
  std::vector<int> alongC, rankOnC;
  std::vector<char> used;
  std::vector<WalkPoint> points;
  std::vector<std::size_t> ringStart;  ///< where each ring's points begin, and the end
  std::vector<std::size_t> order, lowest;
  // Sets of rings: where each ring's crossings begin (and the end), where each ring lies, the
  // walked ring along each outer ring's face, polygon and hole indices, holes by polygon.
  std::vector<int> crossStart, walkedOf, polygonOf, holeIndex;
  std::vector<char> place;
  std::vector<std::pair<int, int>> holes;
  template <class F>
  void forEach(F f) {
    f(left);
    f(onLine);
    f(crossings);
    f(crossStart);
    f(walkedOf);
    f(polygonOf);
    f(holeIndex);
    f(place);
    f(holes);
    f(alongC);
    f(rankOnC);
    f(used);
    f(points);
    f(ringStart);
    f(order);
    f(lowest);
  }
};

/// A piece of an input edge while the sweep has it (split_edges.cpp).
struct SweepPiece : LabelledSegment {
  /// Its right end's cached x, which decides most comparisons with it (exactRight below).
  double rightFx = 0;
  StatusNode* node = nullptr;  ///< its status node while in the status, else null
  int slot = -1;         ///< index of its output piece (result pieces only) while in the status
  int resultBelow = -1;  ///< nearest result piece below it when it was inserted
  /// Its right end: -1 for lineB (an input edge's end), else the index of an exact edge's end
  /// in Workspace::exactRights. A piece keeps its right end when it is cut.
  int exactRight = -1;
  /// The last pieces above it tested for a crossing (a ring; checkedNext is the oldest). A pair
  /// separated by a third piece for a moment becomes adjacent again: with only the last one
  /// remembered, W3 tested 22% of its pairs twice and queued 135k of its 465k crossings twice.
  std::array<int, 8> checkedAbove{-1, -1, -1, -1, -1, -1, -1, -1};
  std::uint8_t checkedNext = 0;
  bool open = false;  ///< a piece of an open polyline (zero contribution, never merged)
  /// Whether the result holds the points just above it (stage 2 on windAbove()), set when it
  /// is labelled: the next piece above reads it instead of asking stage 2 again.
  bool insideAbove = false;
  LinePlace place = LinePlace::Outside;  ///< open pieces: where it lies
  [[nodiscard]] int nearestResult() const { return slot >= 0 ? slot : resultBelow; }
};
static_assert(sizeof(SweepPiece) == 96, "one per input edge, all live through the sweep");

/// An input edge end on the grid, sorted once before the sweep. The point is stored as a sort
/// key relative to the sweep's corner (min x, min y of the grid ends): (x - minX) << 32 |
/// (y - minY). Grid units are at most 2^30 in magnitude (Grid::kMaxUnits), so each difference is
/// below 2^31 and the key's order is the points' lexicographic order (sortByKey() sorts it; the
/// order of equal keys is unspecified, as the sweep takes every start at a point together).
struct SweepStart {
  std::uint64_t key;
  int piece;
  bool end;  ///< the right end of `piece` (a hint: the piece may have been merged away)
};
static_assert(sizeof(SweepStart) == 16, "80k of these are sorted on W1-100k: keep them small");

/// The corner the sweep's start keys are relative to, and the conversions both ways. Every sweep
/// point lies within the grid's range (|coordinates| <= Grid::kMaxUnits, as the in-box
/// predicates assume too), so the range's own corner serves every call: no pass over the edges.
struct StartFrame {
  static_assert(Grid::kMaxUnits <= (std::int64_t{1} << 30), "differences must fit 32 bits");
  std::int64_t minX = -Grid::kMaxUnits, minY = -Grid::kMaxUnits;
  [[nodiscard]] std::uint64_t key(IPoint p) const {
    return std::uint64_t(p.x - minX) << 32 | std::uint64_t(p.y - minY);
  }
  [[nodiscard]] IPoint point(std::uint64_t key) const {
    return {minX + std::int64_t(key >> 32), minY + std::int64_t(key & 0xffffffffU)};
  }
};

/// A point the sweep must visit that is not an input vertex: a crossing, an off-grid end, or
/// where a merged coincident piece goes on. 32 bytes: the exact coordinates live in the event
/// point pool (Workspace::eventPoints, 48 bytes a slot), or for a slab's crossing nowhere
/// (kOnLines); the heap orders events by the cached doubles first and reads the exact points only
/// when they cannot decide.
struct SweepEvent {
  /// The point's cached doubles: XPoint::fx, fy, or for a slab's crossing (kOnLines) the
  /// looser ones of slabCrossing() (split_edges.cpp), which only compareCachedInBox()'s test
  /// reads (and the bucket sort, whose order the exact insertion pass settles).
  double fx = 0, fy = 0;
  int point = -1;    ///< its index in Workspace::eventPoints, or kOnLines
  int piece = -1;    ///< -1: visit the point only
  int through = -1;  ///< a crossing: one of the two pieces crossing there (locates p)
  int other = -1;    ///< a crossing: the other piece
};
/// SweepEvent::point of a slab's crossing: the crossing of pieces `through` and `other`'s lines,
/// worked out exactly only where needed (split_edges.cpp: slabCrossing()).
constexpr int kOnLines = -1;
static_assert(sizeof(SweepEvent) == 32, "the event heap moves these around: keep them small");

/// A vertex of a path being pre-clipped and the supporting segment of the edge leaving it
/// (convex_clip.cpp).
struct ClipVertex {
  XPoint p;
  IPoint lineA, lineB;
};

/// The working arrays of traceContours() (trace_contours.cpp): per-vertex rows of the result
/// pieces leaving and arriving, the pairing, and the walk. On small calls (W4: 10,000 contours of
/// ~20 vertices) their allocations cost more than the tracing.
struct TraceScratch {
  std::vector<int> outHead, outNext, inHead, shared, outs, ins, onStack, stackV, stackE;
  std::vector<char> meets;  ///< per vertex: several result pieces leave it
  /// Storage lent to the traced contours of a call (not a working array: not in forEach()).
  Contours contours;
  /// Every array, for recycleAll() / release().
  template <class F>
  void forEach(F f) {
    for (std::vector<int>* v :
         {&outHead, &outNext, &inHead, &shared, &outs, &ins, &onStack, &stackV, &stackE}) {
      f(*v);
    }
    f(meets);
  }
  /// Frees every array when together they hold more than `bytes`: the peak of a large call is
  /// in nesting, after tracing, so large tracing arrays are not kept through it; small calls
  /// keep theirs (no allocation on the next call).
  void releaseIfAbove(std::size_t bytes) {
    releaseTogetherAbove(bytes, [this](auto f) { forEach(f); });
  }
  /// The same for the pairing's arrays (the pieces leaving and arriving at each vertex), which
  /// the walk after it does not read: W3-1k even-odd held 9 MB of them through the walk, where
  /// it peaked.
  void releasePairingIfAbove(std::size_t bytes) {
    releaseTogetherAbove(bytes, [this](auto f) {
      for (std::vector<int>* v : {&outHead, &outNext, &inHead}) f(*v);
    });
  }

 private:
  // Frees the arrays `each` lists when together they hold more than `bytes`.
  template <class Each>
  static void releaseTogetherAbove(std::size_t bytes, Each&& each) {
    std::size_t held = 0;
    each([&](auto& v) { held += v.capacity() * sizeof(v[0]); });
    if (held > bytes) each([](auto& v) { std::remove_reference_t<decltype(v)>().swap(v); });
  }
};

/// The working arrays of buildNesting() (nesting.cpp): rings in sweep order, each ring's owner,
/// polygon and hole index, the rings rounding collapsed, the converted-vertex cache.
struct NestingScratch {
  std::vector<int> ringAtPiece, order, owner, polygonOf, holeIndexOf;
  std::vector<char> dropped;
  std::vector<Point> converted;
  template <class F>
  void forEach(F f) {
    for (std::vector<int>* v : {&ringAtPiece, &order, &owner, &polygonOf, &holeIndexOf}) f(*v);
    f(dropped);
    f(converted);
  }
};

/// Every kept working array of the pipeline. A workspace serves one call at a time.
struct Workspace {
  /// Storage lent to the arrangement of a call (split_edges.cpp), given back by resolve().
  Arrangement arrangement;
  /// Storage lent to a call's snapped operands (snapOperand()), given back by giveBackRings(): a
  /// small call (W4) snaps into the rings the call before it left, with no allocation.
  std::array<Rings, kOperands> operandRings;
  // Sweep (split_edges.cpp).
  std::vector<SweepPiece> pieces;
  /// Each piece's line in the arrangement's lines once a vertex refers to it, else -1 (apart
  /// from SweepPiece, which stays at 96 bytes).
  std::vector<int> pieceLines;
  /// The left end of each open piece, by piece id (for Arrangement::openPieces; empty without
  /// open pieces). A closed piece's left end is not kept: the sweep reads its line and right
  /// end only.
  std::vector<XPoint> openLefts;
  std::vector<XPoint> exactRights;               ///< the right ends of the pieces of exact edges
  std::vector<SweepStart> starts, sortedStarts;  ///< sortedStarts: the sort's second array
  std::vector<SweepEvent> queue;                 ///< a binary heap, earliest point first
  std::vector<ExactCoords> eventPoints;  ///< exact points of queued events (slots are reused)
  std::vector<int> freeEventPoints;      ///< free slots of eventPoints
  /// Status node pool, as many as the status was ever wide (a deque: nodes never move).
  std::deque<StatusNode> nodes;
  std::vector<StatusNode*> freeNodes;
  std::vector<int> starting;                    ///< pieces starting at the current event point
  std::vector<int> through;                     ///< pieces through the current event point
  std::vector<SlabEntry> slabOrder;             ///< the active pieces of a slab pass
  std::vector<SweepEvent> slabEvents;           ///< the crossings of a slab, sorted
  std::vector<std::uint32_t> slabBuckets;       ///< their sort's bucket of each crossing
  std::vector<std::uint32_t> slabBucketStarts;  ///< and where each bucket starts
  std::vector<SweepEvent> slabEventScratch;     ///< the sort's second array of crossings
  // Convex pre-clip (convex_clip.cpp, boolean_op.cpp).
  std::vector<ClipVertex> path, next;
  std::vector<ExactEdge> clipped;
  std::vector<InputEdge> edges;
  // The simple-ring test (simple_ring.cpp).
  ChainScratch chains;
  // The simple-ring AND convex-ring case (simple_convex.cpp).
  WeilerScratch weiler;
  // Pinches separated (pinches.cpp) and overlapping edges cancelled (overlaps.cpp).
  PinchedRings pinched;
  OverlapScratch overlaps;
  // Tracing (trace_contours.cpp).
  TraceScratch trace;
  // Nesting (nesting.cpp).
  NestingScratch nesting;

  /// Set by the stages of the general path (preclipConvex(), resolveGeneral(), splitEdges())
  /// and by the pinch and overlap stages, the only ones that take arrays beyond `chains`,
  /// `weiler` and `operandRings`: recycleAll()
  /// recycles the others only after a call that set it. A call that only took the paths of
  /// single contours (W4's small contours) then walks the arrays of `chains` and `weiler` alone.
  bool generalPathUsed = false;

  /// Re-entry guard: set while a call uses this workspace (see WorkspaceLease).
  std::atomic<bool> busy{false};

  /// Empty every array the call used, keeping the capacity of those up to kKeptScratchBytes.
  void recycleAll();
  /// Free each of the sweep's arrays (pieces, events, status) that holds more than `bytes` (see
  /// kKeptStageBytes).
  void releaseSweepIfAbove(std::size_t bytes);
  /// Free every array.
  void release();

 private:
  /// The arrays lent to a call's arrangement and contours (workspace.cpp).
  template <class F>
  void forEachLent(F f);
};

/// The calling thread's workspace, or `preferred`'s, for the length of one call. When that
/// workspace is already in use (a second thread calling the same PreparedRegion, or a re-entry),
/// the lease makes a private one instead, so a call never sees another call's arrays. On exit,
/// also by an exception, every array is recycled.
class WorkspaceLease {
 public:
  WorkspaceLease();  ///< the calling thread's workspace
  explicit WorkspaceLease(Workspace& preferred);
  WorkspaceLease(const WorkspaceLease&) = delete;
  WorkspaceLease& operator=(const WorkspaceLease&) = delete;
  ~WorkspaceLease();
  Workspace& operator*() const { return *ws_; }
  Workspace* operator->() const { return ws_; }

 private:
  void acquire(Workspace& preferred);
  std::unique_ptr<Workspace> own_;
  Workspace* ws_ = nullptr;
};

/// Free the calling thread's workspace (roiclip::releaseThreadBuffers()).
void releaseThreadWorkspace();

}  // namespace roiclip::detail
