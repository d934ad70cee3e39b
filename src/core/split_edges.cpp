// SPDX-License-Identifier: MIT
// Stage 1: find every self- and mutual intersection and split the edges there.
//
// A Bentley-Ottmann sweep in lexicographic (x, then y) order. Crossings are not swapped in the
// status structure; instead, every event point P is visited once, and all active pieces that
// pass through P (ending there, crossing there, or touched there by another edge's vertex) are
// cut at P and the parts to the right re-inserted, sorted by direction. Pieces starting at P in
// the same direction are coincident (collinear overlap) and are merged, their winding
// contributions summed. Neighbours that become adjacent are tested for a crossing to the right
// of P, which becomes a future event. Because the sweep knows the piece directly below every
// new piece, it also labels each piece with the winding numbers on both of its sides. The two
// most common event points, a contour's chain going on and two adjacent pieces crossing, each
// with nothing else at the point, take a short visit that reuses the status nodes as they are.
// Where crossings are dense, the sweep finds them slab by slab instead (slab mode): between two
// consecutive x of input vertices, the pairs whose order at the slab's right end is the reverse
// of the status order, by one insertion sort, queued in a sorted list beside the heap.
//
// Cost: O((n + k) log n) time for n edges and k intersection points, O(n + k) memory.
#include <algorithm>
#include <limits>
#include <optional>

#include <boost/sort/pdqsort/pdqsort.hpp>

#include <roiclip/error.hpp>

#include "pipeline.hpp"
#include "radix_sort.hpp"
#include "workspace.hpp"

namespace roiclip::detail {
namespace {

// Every vertex lies within the grid's range, so ArrangementVertex or PackedPoint holds it: a
// sweep that made one beyond has a bug.
[[noreturn, gnu::noinline, gnu::cold]] void vertexBeyondRange() {
  throw InternalError("splitEdges: a vertex beyond the grid's range");
}

// q == p for a grid point q: grid points always have W == 1 (lineIntersection() stores
// crossings on the grid so), so an off-grid p never equals q.
inline bool atGridPoint(const XPoint& p, IPoint q) { return p.w == 1 && p.x == q.x && p.y == q.y; }

inline IPoint gridPoint(const XPoint& p) { return {std::int64_t(p.x), std::int64_t(p.y)}; }

// kSlabs: whether the sweep may take slab mode (slabs below), decided before it is built from
// what can start inside a slab; without it, none of slab mode's tests is compiled in.
template <bool kSlabs>
class Sweep {
 public:
  Sweep(const std::vector<InputEdge>& edges, const std::vector<ExactEdge>& exactEdges,
        const BooleanSpec& spec, Workspace& ws)
      : spec_(spec),
        pieces_(ws.pieces),
        pieceLines_(ws.pieceLines),
        openLefts_(ws.openLefts),
        exactRights_(ws.exactRights),
        starts_(ws.starts),
        queue_(ws.queue),
        eventPoints_(ws.eventPoints),
        freeEventPoints_(ws.freeEventPoints),
        starting_(ws.starting),
        through_(ws.through),
        slabOrder_(ws.slabOrder),
        slabEvents_(ws.slabEvents),
        slabBuckets_(ws.slabBuckets),
        slabBucketStarts_(ws.slabBucketStarts),
        slabEventScratch_(ws.slabEventScratch),
        nodes_(ws.nodes),
        freeNodes_(ws.freeNodes),
        status_() {
    const std::size_t total = edges.size() + exactEdges.size();
    // The status links pieces by address: the array must not move while the sweep runs.
    pieces_.clear();
    pieces_.reserve(total);
    pieceLines_.assign(total, -1);
    openLefts_.clear();
    exactRights_.clear();
    exactRights_.reserve(exactEdges.size());
    starts_.clear();
    queue_.clear();
    slabEvents_.clear();
    eventPoints_.clear();
    freeEventPoints_.clear();
    nodes_.clear();
    freeNodes_.clear();
    starts_.reserve(total * 2);  // exact edges with grid ends start here too
    // Each piece is built in place: a copy of its 96 bytes cost as much as building it.
    for (const InputEdge& e : edges) {
      const int id = int(pieces_.size());
      SweepPiece& a = pieces_.emplace_back();
      a.rightFx = double(e.b.x);
      a.setLine(e.a, e.b);
      a.contribution[e.operand] = e.open ? 0 : e.direction;
      a.open = e.open;
      if (e.open) {
        if (openLefts_.empty()) openLefts_.resize(total);
        openLefts_[std::size_t(id)] = XPoint(e.a);
      }
      if constexpr (kSlabs) {
        if (e.open) slabKeyEnd_ = kNoStartKey;  // an open piece: no slab mode (sweepEdges())
      }
      starts_.push_back({frame_.key(e.a), id, false});
      starts_.push_back({frame_.key(e.b), id, true});
    }
    // Edges with off-grid ends start from the event queue; their ends are plain events.
    if (!exactEdges.empty()) slabKeyEnd_ = kNoStartKey;  // an off-grid end: no slab mode
    for (const ExactEdge& e : exactEdges) {
      const int id = int(pieces_.size());
      SweepPiece& a = pieces_.emplace_back();
      a.exactRight = int(exactRights_.size());
      a.rightFx = e.right.fx;
      exactRights_.push_back(e.right);
      a.setLine(e.lineA, e.lineB);
      a.contribution[e.operand] = e.direction;
      if (e.left.w == 1) {
        starts_.push_back({frame_.key(gridPoint(e.left)), id, false});
      } else {
        push(e.left, id);
      }
      if (e.right.w == 1) {
        starts_.push_back({frame_.key(gridPoint(e.right)), id, true});
      } else {
        push(e.right, -1);
      }
    }
    sortByKey(starts_, ws.sortedStarts);
    releaseEachAbove(kKeptStageBytes, ws.sortedStarts);
    out_ = std::move(ws.arrangement);  // the kept capacity (resolve() gives it back)
    out_.vertices.clear();
    out_.lines.clear();
    out_.offGrid.clear();
    out_.pieces.clear();
    out_.sides.clear();
    out_.windings.clear();
    out_.openPieces.clear();
    out_.pieces.reserve(total / 4 + 16);
    out_.vertices.reserve(total / 4 + 16);
  }

  Sweep(const Sweep&) = delete;
  Sweep& operator=(const Sweep&) = delete;
  ~Sweep() { status_.clear(); }  // the lease recycles the arrays, also when the sweep throws

  [[gnu::always_inline]] Arrangement run() {
    XPoint p;
    while (true) {
      if constexpr (kSlabs) {
        if (cursor_ < starts_.size() && starts_[cursor_].key >= slabKeyEnd_) startSlabIfDue();
        if (slabHead_ < slabEnd_) visitSlabCrossings();
      }
      if (!nextPoint(p)) break;
      visit(p);
    }
    if (!status_.empty()) throw InternalError("splitEdges: sweep ended with active pieces");
    out_.crossings = crossings_;
    out_.slabPasses = slabPasses_;
    return std::move(out_);
  }

 private:
  // The status is kept in order by position: every node goes in next to its neighbour
  // (linkBelow(), insert_before()) and searches compare a point against the pieces (PointLess),
  // so the tree never compares two nodes: no order of its own to keep consistent (a piece's
  // left end, which such an order would read, is kept for open pieces only: openLefts_).
  struct PositionOnly {
    bool operator()(const StatusNode&, const StatusNode&) const = delete;
  };
  // Piece below point / point below piece, for finding the pieces through a point.
  struct PointLess {
    const std::vector<SweepPiece>* pieces;
    bool operator()(const StatusNode& n, const XPoint& p) const {
      const SweepPiece& a = (*pieces)[std::size_t(n.piece)];
      return orientInBox(a.lineA(), a.lineB(), p) > 0;
    }
    bool operator()(const XPoint& p, const StatusNode& n) const {
      const SweepPiece& a = (*pieces)[std::size_t(n.piece)];
      return orientInBox(a.lineA(), a.lineB(), p) < 0;
    }
  };
  using Status = boost::intrusive::set<
      StatusNode, boost::intrusive::member_hook<StatusNode, StatusHook, &StatusNode::hook>,
      boost::intrusive::compare<PositionOnly>, boost::intrusive::constant_time_size<false>>;

  // Links node x into the status just below node `at` (null: at the top): the tree by position
  // (no comparison) and the neighbour links.
  void linkBelow(StatusNode* at, StatusNode* x) {
    x->below = at != nullptr ? at->below : top_;
    x->above = at;
    if (x->below != nullptr) x->below->above = x;
    if (at != nullptr) {
      at->below = x;
    } else {
      top_ = x;
    }
    status_.insert_before(at != nullptr ? status_.iterator_to(*at) : status_.end(), *x);
    if constexpr (kSlabs) ++active_;
  }
  // Unlinks node x; returns the node that was above it.
  StatusNode* unlink(StatusNode* x) {
    if (x->below != nullptr) x->below->above = x->above;
    if (x->above != nullptr) {
      x->above->below = x->below;
    } else {
      top_ = x->below;
    }
    status_.erase(status_.iterator_to(*x));
    if constexpr (kSlabs) --active_;
    return x->above;
  }

  // The right end of piece a, x against it, and whether it is p.
  [[nodiscard]] XPoint rightOf(const SweepPiece& a) const {
    return a.exactRight < 0 ? XPoint(a.lineB()) : exactRights_[std::size_t(a.exactRight)];
  }
  [[nodiscard]] int compareToRight(const XPoint& x, const SweepPiece& a) const {
    const int c = compareCachedInBox(x.fx, a.rightFx);
    if (c != 0) return c;
    return a.exactRight < 0 ? compareInBox(x, XPoint(a.lineB()))
                            : compareInBox(x, exactRights_[std::size_t(a.exactRight)]);
  }
  [[nodiscard]] bool endsAt(const SweepPiece& a, const XPoint& p) const {
    if (compareCachedInBox(p.fx, a.rightFx) != 0) return false;
    return a.exactRight < 0 ? atGridPoint(p, a.lineB())
                            : equalInBox(exactRights_[std::size_t(a.exactRight)], p);
  }

  // The exact point of an event: from the pool with the event's cached doubles, or for a slab's
  // crossing (kOnLines: slabCrossing()) worked out from its two pieces' lines, with the tighter
  // cached doubles of any XPoint.
  [[nodiscard, gnu::always_inline]] XPoint eventPoint(const SweepEvent& e) const {
    if (kSlabs && e.point == kOnLines) return exactCrossing(e.through, e.other);
    const ExactCoords& c = eventPoints_[std::size_t(e.point)];
    XPoint p;
    p.x = c.x;
    p.y = c.y;
    p.w = c.w;
    p.fx = e.fx;
    p.fy = e.fy;
    return p;
  }
  // The crossing of pieces i and j's lines, exactly (their lines cross: a slab found it).
  [[nodiscard, gnu::noinline]] XPoint exactCrossing(int i, int j) const {
    const SweepPiece& a = pieces_[std::size_t(i)];
    const SweepPiece& b = pieces_[std::size_t(j)];
    XPoint x;
    if (!lineIntersection(a.lineA(), a.lineB(), b.lineA(), b.lineB(), x)) {
      throw InternalError("splitEdges: parallel pieces swapped in a slab");
    }
    return x;
  }
  // Whether event a comes after event b. The events' cached x decides almost every comparison
  // (every sweep point lies within the grid's range: compareCachedInBox(), whose test this is,
  // written so that the decided case is one predictable branch and a flag, not a second branch
  // on the order); the rest compare the exact points.
  [[nodiscard]] bool eventAfter(const SweepEvent& a, const SweepEvent& b) const {
    const double d = a.fx - b.fx;  // exactly -(b.fx - a.fx): compareCachedInBox()'s two tests
    if (__builtin_expect(std::fabs(d) > kCachedInBoxBound, 1)) return d > 0;
    return eventAfterExact(a, b);
  }
  [[nodiscard, gnu::noinline]] bool eventAfterExact(const SweepEvent& a,
                                                    const SweepEvent& b) const {
    if (a.point >= 0 && a.point == b.point) return false;  // one stored point
    const XPoint p = eventPoint(b), q = eventPoint(a);
    return compareInBox(p, q) < 0;
  }

  // x must not lie in eventPoints_ (it may move).
  void push(const XPoint& x, int pieceId, int through = -1, int other = -1) {
    const int slot = storePoint(x);
    // Binary heap, earliest event at the root: the new event climbs from a new leaf.
    queue_.emplace_back();
    placeFrom(queue_.size() - 1, {x.fx, x.fy, slot, pieceId, through, other});
  }
  // x's exact coordinates in the event point pool: their slot.
  int storePoint(const XPoint& x) {
    if (!freeEventPoints_.empty()) {
      const int slot = freeEventPoints_.back();
      freeEventPoints_.pop_back();
      eventPoints_[std::size_t(slot)] = {x.x, x.y, x.w};
      return slot;
    }
    eventPoints_.push_back({x.x, x.y, x.w});
    return int(eventPoints_.size()) - 1;
  }
  // Puts ev at `hole` or, while its parent comes after it, moves the parent down and climbs.
  void placeFrom(std::size_t hole, const SweepEvent& ev) {
    while (hole > 0) {
      const std::size_t parent = (hole - 1) / 2;
      if (!eventAfter(queue_[parent], ev)) break;
      queue_[hole] = queue_[parent];
      hole = parent;
    }
    queue_[hole] = ev;
  }
  // Removes the earliest event (Floyd's order: the hole at the root sinks to a leaf along the
  // earlier child, one comparison per level, and the last event climbs back from there; it
  // mostly stays near the bottom).
  void popHeap() {
    freeEventPoints_.push_back(queue_.front().point);
    const SweepEvent last = queue_.back();
    queue_.pop_back();
    const std::size_t n = queue_.size();
    if (n == 0) return;
    std::size_t hole = 0;
    for (std::size_t child = 1; child < n; child = 2 * hole + 1) {
      if (child + 1 < n) child += std::size_t(eventAfter(queue_[child], queue_[child + 1]));
      queue_[hole] = queue_[child];
      hole = child;
    }
    placeFrom(hole, last);
  }
  // Events wait in two queues: the heap, and in slab mode the slab's crossings, sorted by the
  // slab pass (slabEvents_ from slabHead_ on). The earliest of both comes first.
  [[nodiscard]] bool anyEvent() const {
    return !queue_.empty() || (kSlabs && slabHead_ < slabEnd_);
  }
  // Whether the earliest event is the slab list's (there is one).
  [[nodiscard]] bool slabFirst() const {
    return kSlabs && slabHead_ < slabEnd_ &&
           (queue_.empty() || !eventAfter(slabEvents_[slabHead_], queue_.front()));
  }
  // The earliest event (there is one).
  [[nodiscard]] const SweepEvent& top() const {
    return slabFirst() ? slabEvents_[slabHead_] : queue_.front();
  }
  [[nodiscard]] XPoint topPoint() const { return eventPoint(top()); }
  void pop() {
    if (slabFirst()) {
      ++slabHead_;  // a slab's crossings keep no stored point (kOnLines)
    } else {
      popHeap();
    }
  }
  // Whether ev lies at p (which lies within the grid's range, as every sweep point).
  [[nodiscard]] bool isAt(const SweepEvent& ev, const XPoint& p) const {
    return compareCachedInBox(ev.fx, p.fx) == 0 && equalInBox(eventPoint(ev), p);
  }
  // Whether the heap's event at index i (none there: false) lies at p.
  [[nodiscard]] bool heapEventAt(std::size_t i, const XPoint& p) const {
    return i < queue_.size() && isAt(queue_[i], p);
  }
  // Whether the slab list's event at index i (none there: false) lies at p.
  [[nodiscard]] bool slabEventAt(std::size_t i, const XPoint& p) const {
    return i < slabEvents_.size() && isAt(slabEvents_[i], p);
  }
  // The earliest event is at p.
  [[nodiscard]] bool topAt(const XPoint& p) const { return anyEvent() && isAt(top(), p); }
  // Whether an event other than the earliest lies at p, the earliest's point: the next one of
  // the same queue (in the heap, a child of the root: each event comes no earlier than its
  // parent), or the other queue's first.
  [[nodiscard]] bool secondEventAt(const XPoint& p) const {
    if (!kSlabs) return heapEventAt(1, p) || heapEventAt(2, p);
    if (slabFirst()) return slabEventAt(slabHead_ + 1, p) || heapEventAt(0, p);
    return heapEventAt(1, p) || heapEventAt(2, p) || slabEventAt(slabHead_, p);
  }

  // The next event point; pointKey_ is its start key when the next start lies there (the starts
  // at p are then the ones with that key), else a key no start has.
  bool nextPoint(XPoint& p) {
    const bool hasStart = cursor_ < starts_.size();
    pointKey_ = kNoStartKey;
    if (!hasStart && !anyEvent()) return false;
    if (!hasStart) {
      p = topPoint();
      return true;
    }
    const std::uint64_t key = starts_[cursor_].key;
    const XPoint a(frame_.point(key));
    if (anyEvent()) {
      const XPoint t = topPoint();
      if (lessInBox(t, a)) {
        p = t;
        return true;
      }
    }
    p = a;
    pointKey_ = key;
    return true;
  }

  // The vertex id of the current event point, stored on first use: only vertices of result
  // pieces are kept. Ids still follow the sweep order, i.e. lexicographic order.
  int vertexHere(const XPoint& p) {
    if (vertex_ < 0) {
      vertex_ = int(out_.vertices.size());
      // A grid point's cached doubles are its coordinates, rounded only beyond 2^53.
      constexpr double kBound = double(ArrangementVertex::kGridBound);
      out_.vertices.push_back(p.w == 1 && std::fabs(p.fx) <= kBound && std::fabs(p.fy) <= kBound
                                  ? ArrangementVertex::grid(gridPoint(p))
                                  : offGridVertex(&p));
    }
    return vertex_;
  }
  // A slab's crossing as a direct visit takes it: its cached doubles (SweepEvent::fx, fy).
  struct SlabCrossingAt {
    double fx, fy;
  };
  // The same for a slab's crossing in a direct visit, worked out exactly only where it may be a
  // grid point (rare): its cached doubles lie within 2^-19 of its coordinates (slabCrossing()),
  // so a grid point's lie within 2^-19 of integers.
  [[gnu::always_inline]] int vertexHere(const SlabCrossingAt& c) {
    if (vertex_ < 0) newCrossingVertex(c);
    return vertex_;
  }
  // The first call at the point: the vertex is stored.
  [[gnu::noinline]] void newCrossingVertex(const SlabCrossingAt& c) {
    // |v| <= 2^31 (grid range): adding and subtracting 1.5 * 2^52 rounds v to an integer.
    constexpr double kRound = 0x1.8p52;
    const auto nearInteger = [](double v) {
      return std::fabs(v - ((v + kRound) - kRound)) <= 0x1p-19;
    };
    if (nearInteger(c.fx) && nearInteger(c.fy)) {
      vertexHere(exactCrossing(crossingHere_[0], crossingHere_[1]));
      return;
    }
    vertex_ = int(out_.vertices.size());
    ArrangementVertex v;
    out_.vertices.push_back(crossingVertex(v) ? v : offGridVertex(nullptr));
  }
  // crossingHere_'s two lines as an arrangement vertex, where the first line's index fits it.
  [[gnu::always_inline]] bool crossingVertex(ArrangementVertex& v) {
    const std::int64_t line1 = lineOf(crossingHere_[0]), line2 = lineOf(crossingHere_[1]);
    if (line1 > ArrangementVertex::kMaxIndex) return false;
    v = ArrangementVertex::crossing(line1, line2);
    return true;
  }
  // p off the grid as the arrangement keeps it: where two crossing pieces met at p, the crossing
  // of their lines; else (an exact edge's end) the exact point.
  // (p null: the crossing of crossingHere_'s lines, worked out here where needed.)
  [[gnu::noinline]] ArrangementVertex offGridVertex(const XPoint* at) {
    ArrangementVertex v;
    if (crossingHere_[0] >= 0 && crossingVertex(v)) return v;
    const XPoint p = at != nullptr ? *at : exactCrossing(crossingHere_[0], crossingHere_[1]);
    if (!PackedPoint::representable(p) ||
        out_.offGrid.size() > std::size_t(ArrangementVertex::kMaxIndex)) {
      vertexBeyondRange();
    }
    out_.offGrid.push_back(PackedPoint(p));
    return ArrangementVertex::offGrid(std::int64_t(out_.offGrid.size()) - 1);
  }
  // The index of piece i's line in the arrangement's lines, added on first use.
  int lineOf(int i) {
    int& line = pieceLines_[std::size_t(i)];
    if (line < 0) {
      line = int(out_.lines.size());
      out_.lines.push_back(static_cast<const GridSegment&>(pieces_[std::size_t(i)]));
    }
    return line;
  }

  // One event point p: every active piece through p is cut there, the pieces leaving p are
  // merged where coincident, labelled and put in the status, and new neighbours are tested. A
  // chain going on and two pieces crossing, alone at p, take a short visit (below).
  void visit(const XPoint& p) {
    vertex_ = -1;
    crossingHere_ = {-1, -1};
    if (pointKey_ != kNoStartKey ? chainGoesOn(p) : twoPiecesCross(p)) return;
    starting_.clear();
    const auto [locator, known] = takeEventsAt(p);
    const auto [lo, hi] = piecesThrough(p, locator, known);
    const StatusNode* belowNode = lo != nullptr ? lo->below : top_;
    const int below = pieceIn(belowNode);
    cutAt(lo, hi, p);
    mergeCoincident();
    insertStarting(lo, hi, below, p);
    const int above = pieceIn(hi);
    if (starting_.empty()) {
      checkCrossing(below, above, p);
    } else {
      checkCrossing(below, starting_.front(), p);
      checkCrossing(starting_.back(), above, p);
    }
  }

  // The two most common event points, each without the lists and loops of the general visit:
  // a contour's chain going on (one piece ends at p, the next edge starts there) and two pieces
  // crossing. Both need that no other event lies at p and no other piece passes through it;
  // otherwise they return false before changing anything, and the general visit takes p.

  // The piece in node n, -1 for none.
  static int pieceIn(const StatusNode* n) { return n != nullptr ? n->piece : -1; }
  // Whether the active piece in node n passes through p.
  [[nodiscard]] bool passesThrough(const StatusNode* n, const XPoint& p) const {
    const SweepPiece& a = pieces_[std::size_t(n->piece)];
    return orientInBox(a.lineA(), a.lineB(), p) == 0;
  }
  // Whether no piece next to the run of nodes lo..hi (both included) passes through p.
  [[nodiscard]] bool aloneAt(const StatusNode* lo, const StatusNode* hi, const XPoint& p) const {
    return (lo->below == nullptr || !passesThrough(lo->below, p)) &&
           (hi->above == nullptr || !passesThrough(hi->above, p));
  }

  // p holds exactly two starts: the right end of an active closed piece and the left end of
  // a closed piece, and no queued event. The new piece takes the old one's node: nothing else
  // passes through p, so it lies where the old one did.
  bool chainGoesOn(const XPoint& p) {
    const std::size_t n = starts_.size();
    if (cursor_ + 1 >= n || starts_[cursor_ + 1].key != pointKey_ ||
        (cursor_ + 2 < n && starts_[cursor_ + 2].key == pointKey_)) {
      return false;
    }
    const SweepStart& s0 = starts_[cursor_];
    const SweepStart& s1 = starts_[cursor_ + 1];
    if (s0.end == s1.end) return false;
    const int ending = s0.end ? s0.piece : s1.piece;
    const int next = s0.end ? s1.piece : s0.piece;
    SweepPiece& a = pieces_[std::size_t(ending)];
    SweepPiece& b = pieces_[std::size_t(next)];
    StatusNode* node = a.node;
    if (node == nullptr || a.open || b.open || cancelled(b)) return false;
    if (topAt(p)) return false;
    if (!aloneAt(node, node, p)) return false;
    cursor_ += 2;
    closeAt(a, p);
    const int below = pieceIn(node->below);
    Labels at = labelsAbove(below);
    labelStarting(b, at, p);
    node->piece = next;
    b.node = node;
    checkCrossing(below, next, p);
    checkCrossing(next, pieceIn(node->above), p);
    return true;
  }

  // The queue's first event is a crossing of two adjacent closed pieces, the only event at p.
  // The crossing lies strictly inside both (checkCrossing() queues no other), so both go on
  // past p, swapped: each keeps its node's place with the other's piece.
  bool twoPiecesCross(const XPoint& p) {
    const SweepEvent& ev = top();
    if (ev.piece >= 0 || ev.through < 0) return false;
    const int first = ev.through, second = ev.other;
    SweepPiece& pf = pieces_[std::size_t(first)];
    SweepPiece& ps = pieces_[std::size_t(second)];
    StatusNode *lo = pf.node, *hi = ps.node;
    if (lo == nullptr || hi == nullptr || pf.open || ps.open) return false;
    if (lo->above != hi) {
      std::swap(lo, hi);
      if (lo->above != hi) return false;
    }
    // In slab mode a third piece through p crosses one of the two there, and that crossing is
    // queued too (a slab's crossings all are; a vertical piece's with its neighbour is): the
    // test of a second event covers it, without the neighbours' orientation tests.
    if (secondEventAt(p) || (!(kSlabs && slabMode_) && !aloneAt(lo, hi, p))) return false;
    pop();
    crossingHere_ = {first, second};
    const int below = swapAt(lo, hi, p);
    checkCrossing(below, lo->piece, p);
    checkCrossing(hi->piece, pieceIn(hi->above), p);
    return true;
  }
  // The pieces in the adjacent nodes lo (below) and hi cross at p, alone there: both end at p
  // and go on past it swapped, each taking the other's node. Returns the piece below lo.
  template <class At>
  [[gnu::always_inline]] int swapAt(StatusNode* lo, StatusNode* hi, const At& p) {
    const int lower = lo->piece, upper = hi->piece;
    SweepPiece& a = pieces_[std::size_t(lower)];
    SweepPiece& b = pieces_[std::size_t(upper)];
    endResultAt(a, p);  // both go on, in each other's node
    endResultAt(b, p);
    const int below = pieceIn(lo->below);
    Labels at = labelsAbove(below);
    // Above both, the winding numbers are the same before and after the swap.
    const bool insideAboveBoth = b.insideAbove;
    labelStarting(b, at, p);
    labelStarting(a, at, p, insideAboveBoth);
    lo->piece = upper;
    b.node = lo;
    hi->piece = lower;
    a.node = hi;
    return below;
  }
  // Slab mode: the slab's crossings strictly inside it (before the line x = slabRight_, where
  // the next start lies), each before the heap's first event and alone at its point, in the
  // sorted list's order, without the general event loop. No vertical piece is active inside a
  // slab (the slab pass checks), so no pair needs a test. Stops at the first crossing it cannot
  // take so: the loop visits that one.
  void visitSlabCrossings() {
    while (slabHead_ < slabEnd_) {
      const SweepEvent& ev = slabEvents_[slabHead_];
      if (compareCachedInBox(ev.fx, double(slabRight_)) >= 0) return;
      if (!queue_.empty() && !eventAfter(queue_.front(), ev)) return;
      StatusNode *lo = pieces_[std::size_t(ev.through)].node,
                 *hi = pieces_[std::size_t(ev.other)].node;
      if (lo == nullptr || hi == nullptr) return;
      if (lo->above != hi) {
        std::swap(lo, hi);
        if (lo->above != hi) return;
      }
      if (slabHead_ + 1 < slabEnd_) {  // the next crossing at the same point: the loop's
        const SweepEvent& next = slabEvents_[slabHead_ + 1];
        if (compareCachedInBox(next.fx, ev.fx) == 0 &&
            equalInBox(eventPoint(next), eventPoint(ev))) {
          return;
        }
      }
      vertex_ = -1;
      crossingHere_ = {ev.through, ev.other};
      const SlabCrossingAt p{ev.fx, ev.fy};
      ++slabHead_;
      swapAt(lo, hi, p);
    }
  }

  // Takes every start and queued event at p: pieces starting at p go to starting_. Returns a
  // piece known to pass through p, if any (its status node locates p without a search), else -1,
  // and another one known to pass through p (no orientation test needed for it), else -1.
  std::pair<int, int> takeEventsAt(const XPoint& p) {
    int locator = -1, known = -1;
    const std::size_t cursorBefore = cursor_;
    bool popped = false;
    while (cursor_ < starts_.size() && starts_[cursor_].key == pointKey_) {
      const SweepStart& ev = starts_[cursor_];
      // An end start lies at its piece's right end, which never changes: a piece still in the
      // status there ends at p.
      if (!ev.end) {
        starting_.push_back(ev.piece);
      } else if (pieces_[ev.piece].node != nullptr) {
        locator = ev.piece;
      }
      ++cursor_;
    }
    while (topAt(p)) {
      const SweepEvent& ev = top();
      if (ev.piece >= 0) starting_.push_back(ev.piece);
      // A crossing lies exactly on the lines of both its pieces, and a piece still in the
      // status started before p and ends at or after it (its right end is an event): so each
      // of the two still in the status passes through p, without an orientation test.
      // A crossing's two lines also give the point to the arrangement (offGridVertex()).
      if (ev.through >= 0) {
        crossingHere_ = {ev.through, ev.other};
        const bool a = pieces_[ev.through].node != nullptr, b = pieces_[ev.other].node != nullptr;
        if (locator < 0 && (a || b)) {
          locator = a ? ev.through : ev.other;
          known = a && b ? ev.other : -1;
        }
      }
      pop();
      popped = true;
    }
    // p is the first start's or event's point: a visit that takes neither would come back to
    // p for ever (an event whose cached doubles stray beyond their bound would do that).
    if (cursor_ == cursorBefore && !popped) {
      throw InternalError("splitEdges: nothing to visit at p");
    }
    return {locator, known};
  }

  // The pieces through p are contiguous in the status: the nodes from lo up to hi, hi excluded
  // (null: above the top).
  std::pair<StatusNode*, StatusNode*> piecesThrough(const XPoint& p, int locator, int known) {
    const auto passes = [&](const StatusNode* n) {
      if (n->piece == known) return true;
      const SweepPiece& a = pieces_[std::size_t(n->piece)];
      return orientInBox(a.lineA(), a.lineB(), p) == 0;
    };
    StatusNode *lo, *hi;
    if (locator >= 0) {
      lo = pieces_[std::size_t(locator)].node;
      hi = lo->above;
      while (lo->below != nullptr && passes(lo->below)) lo = lo->below;
    } else {
      const auto it = status_.lower_bound(p, PointLess{&pieces_});
      lo = it == status_.end() ? nullptr : &*it;
      hi = lo;
    }
    while (hi != nullptr && passes(hi)) hi = hi->above;
    return {lo, hi};
  }

  // Every piece through p ends here: its result piece gets p as right end, and the ones that go
  // on start again at p. Their nodes stay in the tree for insertStarting() to reuse or drop.
  void cutAt(const StatusNode* lo, const StatusNode* hi, const XPoint& p) {
    through_.clear();
    for (const StatusNode* n = lo; n != hi; n = n->above) through_.push_back(n->piece);
    for (int i : through_) {
      SweepPiece& a = pieces_[i];
      closeAt(a, p);
      if (a.open) out_.openPieces.push_back({i, openLefts_[std::size_t(i)], p, a.place});
      if (!endsAt(a, p)) {
        if (a.open) openLefts_[std::size_t(i)] = p;
        starting_.push_back(i);
      }
    }
  }

  // Piece a leaves the status at p: its result piece, if any, ends there.
  [[gnu::always_inline]] void closeAt(SweepPiece& a, const XPoint& p) {
    a.node = nullptr;
    endResultAt(a, p);
  }
  // Piece a's result piece, if any, ends at p.
  template <class At>
  [[gnu::always_inline]] void endResultAt(const SweepPiece& a, const At& p) {
    if (a.slot >= 0) out_.pieces[a.slot].right = vertexHere(p);
  }

  // What a piece starting at p gets from just below it: the winding numbers there, whether the
  // result holds that point, and the nearest result piece below.
  struct Labels {
    Windings wind{};
    bool inside = false;
    int resultBelow = -1;
  };
  // The labels just above piece `below` (-1: none, below everything).
  [[nodiscard, gnu::always_inline]] Labels labelsAbove(int below) const {
    Labels at;
    if (below >= 0) {
      const SweepPiece& b = pieces_[std::size_t(below)];
      at.wind = b.windAbove();
      at.resultBelow = b.nearestResult();
      at.inside = b.insideAbove;
    } else {
      at.inside = insideOutside_;
    }
    return at;
  }
  // Labels piece a, starting at p just above `at`, keeps it when it bounds the result, and moves
  // `at` to just above it.
  // knownAbove: stage 2's answer just above it where the caller knows it (the same winding
  // numbers as above a piece it replaces).
  template <class At>
  [[gnu::always_inline]] void labelStarting(SweepPiece& a, Labels& at, const At& p,
                                            std::optional<bool> knownAbove = std::nullopt) {
    a.windBelow = compact(at.wind);
    a.resultBelow = at.resultBelow;
    a.slot = -1;
    at.wind = a.windAbove();
    // Stage 2 (classify): whether the piece bounds the result, and on which side; the side
    // above is the next piece's side below.
    const bool in = at.inside;
    at.inside = knownAbove ? *knownAbove : classifier_.inside(at.wind);
    a.insideAbove = at.inside;
    const Side side = a.open || !spec_.keepBoundary ? Side::None : sideBetween(in, at.inside);
    if (side != Side::None) {
      a.slot = int(out_.pieces.size());
      EdgePiece kept;
      static_cast<GridSegment&>(kept) = a;
      if (spec_.recordWindings) out_.windings.push_back(a);
      kept.left = vertexHere(p);
      kept.below = at.resultBelow;
      out_.pieces.push_back(kept);
      out_.sides.push_back(side);
    }
    at.resultBelow = a.nearestResult();
  }

  // Labels the pieces starting at p bottom to top with the winding numbers from the piece
  // below, keeps the ones stage 2 (classify) says bound the result, and puts them in the status
  // in place of the pieces through p: every one of them lies between `below` and hi, so the
  // nodes [lo, hi) are reused in order (a chain going on, two pieces crossing) and only the
  // surplus is unlinked or linked, without comparisons.
  void insertStarting(StatusNode* lo, StatusNode* hi, int below, const XPoint& p) {
    Labels at = labelsAbove(below);
    int closedRun = -1;  // the last closed piece inserted here, and the winding below it
    Windings closedRunBelow{};
    StatusNode* n = lo;  // the first node from lo up to hi not yet holding a starting piece
    for (int i : starting_) {
      SweepPiece& a = pieces_[i];
      if (a.open) {
        // An open piece coincident with the closed piece just below it lies on that piece:
        // the region's winding numbers on its two sides are the ones around that piece.
        const bool onClosed =
            closedRun >= 0 && crossSign(pieces_[closedRun].direction(), a.direction()) == 0;
        a.place = classifyOpenPiece(onClosed ? closedRunBelow : at.wind, at.wind, spec_);
      } else {
        closedRun = i;
        closedRunBelow = at.wind;
      }
      labelStarting(a, at, p);
      if (n != hi) {  // same position in the order, see above
        n->piece = i;
        a.node = n;
        n = n->above;
      } else {
        a.node = newNode(i);
        linkBelow(hi, a.node);
      }
    }
    while (n != hi) {
      freeNodes_.push_back(n);
      n = unlink(n);
    }
  }

  StatusNode* newNode(int pieceId) {
    StatusNode* n;
    if (!freeNodes_.empty()) {
      n = freeNodes_.back();
      freeNodes_.pop_back();
    } else {
      n = &nodes_.emplace_back();
    }
    n->piece = pieceId;
    return n;
  }

  // A closed piece whose contributions cancel: it changes no winding number. One flag, not three
  // branches: whether a contribution is zero is data, not a pattern.
  static bool cancelled(const SweepPiece& a) {
    return (!a.open & (a.contribution[0] == 0) & (a.contribution[1] == 0)) != 0;
  }

  // Sort the pieces in starting_ by direction; merge runs of coincident closed ones into the
  // shortest and re-start the rest where it ends. Closed pieces whose contributions cancel are
  // dropped: they change no winding number (a spike out and back along itself). Open pieces are
  // never merged or dropped; they follow the closed piece of their direction, as in the status.
  void mergeCoincident() {
    const auto before = [this](int a, int b) {
      const int s = crossSign(pieces_[a].direction(), pieces_[b].direction());
      if (s != 0) return s > 0;
      if (pieces_[a].open != pieces_[b].open) return pieces_[b].open;
      const int c = compareInBox(rightOf(pieces_[a]), rightOf(pieces_[b]));
      return c != 0 ? c < 0 : a < b;
    };
    const auto cancels = [this](int i) { return cancelled(pieces_[i]); };
    // Mostly one piece (a chain going on) or two (a crossing): no sort call for those, and two
    // in different directions (a crossing) have nothing to merge.
    if (starting_.size() == 2) {
      const int s = crossSign(pieces_[starting_[0]].direction(), pieces_[starting_[1]].direction());
      if (s != 0) {
        if (s < 0) std::swap(starting_[0], starting_[1]);
        starting_.erase(std::remove_if(starting_.begin(), starting_.end(), cancels),
                        starting_.end());
        return;
      }
      if (before(starting_[1], starting_[0])) std::swap(starting_[0], starting_[1]);
    } else if (starting_.size() > 2) {
      std::sort(starting_.begin(), starting_.end(), before);
    }
    std::size_t kept = 0;
    for (std::size_t i = 0; i < starting_.size();) {
      const int first = starting_[i];
      std::size_t j = i + 1;
      while (j < starting_.size() && !pieces_[starting_[j]].open &&
             crossSign(pieces_[first].direction(), pieces_[starting_[j]].direction()) == 0) {
        SweepPiece& other = pieces_[starting_[j]];
        for (int k = 0; k < kOperands; ++k) pieces_[first].contribution[k] += other.contribution[k];
        const XPoint firstRight = rightOf(pieces_[first]);
        if (!endsAt(other, firstRight)) push(firstRight, starting_[j]);
        ++j;
      }
      if (!cancels(first)) starting_[kept++] = first;
      i = j;
    }
    starting_.resize(kept);
  }

  // Whether piece b was one of the last pieces tested above `a`; records it if not.
  static bool testedBefore(SweepPiece& a, int b) {
    bool seen = false;  // all eight compared without an early exit: one branch, not eight
    for (int c : a.checkedAbove) seen |= c == b;
    if (seen) return true;
    a.checkedAbove[a.checkedNext] = b;
    a.checkedNext = std::uint8_t((a.checkedNext + 1) % a.checkedAbove.size());
    return false;
  }

  // Tests neighbours a (below) and b for a crossing ahead of p. In slab mode the slab pass finds
  // every crossing of two pieces spanning a slab; only a vertical piece (on the current line)
  // can meet a neighbour elsewhere. (Inline: in slab mode most calls end here.)
  [[gnu::always_inline]] void checkCrossing(int a, int b, const XPoint& p) {
    if (a < 0 || b < 0) return;
    if constexpr (kSlabs) {
      const SweepPiece& pa = pieces_[std::size_t(a)];
      const SweepPiece& pb = pieces_[std::size_t(b)];
      if (slabMode_ && pa.ax != pa.bx && pb.ax != pb.bx) return;
    }
    testPair(a, b, p);
  }
  void testPair(int a, int b, const XPoint& p) {
    SweepPiece& pa = pieces_[a];
    const SweepPiece& pb = pieces_[b];
    // a lies below b along the sweep (every caller passes a pair of neighbours in that order), so
    // their lines meet ahead of the sweep only if a rises faster than b: its direction turns
    // clockwise to b's. Parallel lines never meet, and a pair that crossed behind the sweep (re-
    // adjacent after the crossing: common on random polygons) turns the other way.
    if (crossSign(pa.direction(), pb.direction()) >= 0) return;
    // Cheap exact rejection on the integer supporting segments before the rational crossing.
    if (std::max(pa.lineA().x, pb.lineA().x) > std::min(pa.lineB().x, pb.lineB().x)) return;
    if (std::max(std::min(pa.lineA().y, pa.lineB().y), std::min(pb.lineA().y, pb.lineB().y)) >
        std::min(std::max(pa.lineA().y, pa.lineB().y), std::max(pb.lineA().y, pb.lineB().y))) {
      return;
    }
    // A piece keeps its supporting segment and right end when it is cut, so a pair's crossing
    // never changes: testing the same pair again can only find the same event (pushed again, a
    // duplicate: harmless, but it costs the test, a push and a pop). Asked only of pairs whose
    // boxes overlap: the box test is cheaper than the history, and on a contour most neighbours
    // fail it.
    if (testedBefore(pa, b)) return;
    // Two supporting segments with a common right end (the two edges of a contour's vertex
    // that points right, neighbours before it) meet there or nowhere unless collinear (then
    // segmentCrossing() finds nothing either), and that end is no event to queue: it is at or
    // beyond each piece's own right end. (Other common ends are rarely tested: two pieces leaving
    // a point together are tested only once a piece between them has ended, and their lines
    // meet at that point, behind the sweep, rejected below; an edge that ends where the next
    // starts is out of the status when that one enters.)
    if (pa.lineB() == pb.lineB()) return;
    XPoint x;
    if (!segmentCrossing(pa.lineA(), pa.lineB(), pb.lineA(), pb.lineB(), x)) return;
    // x is a new crossing, mostly off the grid: its cached x decides first.
    if (compareInBoxCachedFirst(x, p) <= 0) return;
    const int ca = compareToRight(x, pa);
    const int cb = compareToRight(x, pb);
    if (ca > 0 || cb > 0) return;
    if (ca == 0 || cb == 0) return;  // already an event: the end of one of them
    queueCrossing(x, a, b);
  }

  // The one place a new crossing becomes an event: x, where pieces a and b cross; after the
  // work budget (Limits::maxCrossings) is checked, before the event takes memory.
  void queueCrossing(const XPoint& x, int a, int b) {
    countCrossing();
    push(x, -1, a, b);
  }
  void countCrossing() {
    if (++crossings_ > spec_.maxCrossings) crossingsBeyondLimit();
  }
  [[noreturn, gnu::noinline, gnu::cold]] void crossingsBeyondLimit() const {
    throw ResourceLimitError("maxCrossings", spec_.maxCrossings, "crossings");
  }

  // Slabs. Between two consecutive x of input vertices no piece starts or ends, so the pieces
  // that cross there are the pairs whose order at the slab's right end is the reverse of the
  // status order: an insertion sort of the active pieces by their height there finds each such
  // pair once, by one swap, with no test of pairs that do not cross. Where crossings are dense
  // (many per slab against the active pieces, as on random polygons) the sweep finds them so
  // instead of testing new neighbours (slab mode); it switches at the x of input vertices, by the
  // crossings found in the slab before.

  // Called while the next start lies beyond the line x = slabRight_ (its key from slabKeyEnd_
  // on). Once the line's events are all visited: the mode for the slab up to that start's x,
  // and in slab mode that slab's pass.
  void startSlabIfDue() {
    const std::int64_t next = frame_.point(starts_[cursor_].key).x;
    // Normal mode without a crossing found since the last line: nothing to decide, and the
    // events still queued before `next` can wait (the next decision waits for them).
    if (!slabMode_ && crossings_ == crossingsAtSlab_) {
      moveLine(next);
      return;
    }
    if (anyEvent() && !beyondLine(top())) return;
    const std::uint64_t found = crossings_ - crossingsAtSlab_;
    // An empty status (before the first piece, between separate contours) is no slab to judge.
    const bool dense =
        active_ > 0 && found * (slabMode_ ? kLeaveSlabs : kEnterSlabs) >= std::uint64_t(active_);
    if (dense != slabMode_) {
      if (dense) {
        enterSlabs();
      } else {
        leaveSlabs();
      }
    }
    crossingsAtSlab_ = crossings_;
    slabEvents_.clear();  // every one visited
    slabHead_ = 0;
    slabEnd_ = 0;
    if (slabMode_) {
      slabPass(next);
      slabEnd_ = slabEvents_.size();
    }
    moveLine(next);
  }
  // The line x = slabRight_ moves to x; starts beyond it have keys from slabKeyEnd_ on.
  void moveLine(std::int64_t x) {
    slabRight_ = x;
    slabKeyEnd_ = std::uint64_t(x + 1 - frame_.minX) << 32;
  }
  // Whether event ev lies beyond the line x = slabRight_ (no event lies before it).
  [[nodiscard]] bool beyondLine(const SweepEvent& ev) const {
    const int c = compareCachedInBox(ev.fx, double(slabRight_));
    if (c != 0) return c > 0;
    const XPoint q = eventPoint(ev);
    return compareCoord(q.x, q.w, slabRight_, 1) > 0;
  }
  [[nodiscard]] StatusNode* bottom() { return status_.empty() ? nullptr : &*status_.begin(); }
  // Into slab mode: the queued crossings go (slab passes find them again, each in its slab, and
  // count them again for Limits::maxCrossings).
  void enterSlabs() {
    std::size_t kept = 0;
    for (const SweepEvent& ev : queue_) {
      if (ev.through >= 0) {
        freeEventPoints_.push_back(ev.point);
        --crossings_;
      } else {
        queue_[kept++] = ev;
      }
    }
    queue_.resize(kept);
    for (std::size_t i = 1; i < kept; ++i) placeFrom(i, SweepEvent(queue_[i]));
    slabMode_ = true;
  }
  // Out of slab mode: no crossing is queued (the last slab's are visited), so every pair of
  // neighbours is tested afresh, as in a sweep that starts here.
  void leaveSlabs() {
    slabMode_ = false;
    const XPoint line(IPoint{slabRight_, Grid::kMaxUnits});  // at or after every visited point
    for (StatusNode* n = bottom(); n != nullptr; n = n->above) {
      // A pair is remembered by its lower piece, which is cleared before its test.
      pieces_[std::size_t(n->piece)].checkedAbove.fill(-1);
      if (n->above != nullptr) checkCrossing(n->piece, n->above->piece, line);
    }
  }
  // Queues every crossing of two active pieces in the slab from x = slabRight_ (excluded) to x
  // (included). The status holds their order just after slabRight_; one that ends lower at x,
  // or meets another there and goes on lower, crossed it in the slab.
  [[gnu::noinline]] void slabPass(std::int64_t x) {
    ++slabPasses_;
    slabLeast_ = std::numeric_limits<double>::infinity();
    slabGreatest_ = -slabLeast_;
    // Written in place, one entry per active piece (active_ counts them; checked).
    slabOrder_.resize(std::size_t(active_));
    SlabEntry* entry = slabOrder_.data();
    SlabEntry* const end = entry + slabOrder_.size();
    for (const StatusNode* n = bottom(); n != nullptr; n = n->above) {
      const SweepPiece& a = pieces_[std::size_t(n->piece)];
      const std::int64_t dx = std::int64_t(a.bx) - a.ax, dy = std::int64_t(a.by) - a.ay;
      if (dx == 0) throw InternalError("splitEdges: a vertical piece spans a slab");
      if (entry == end) throw InternalError("splitEdges: a slab's pieces miscounted");
      const std::int64_t num = std::int64_t(a.ay) * dx + dy * (x - a.ax);
      *entry++ = {num, dx, double(num) / double(dx), n->piece};
    }
    if (entry != end) throw InternalError("splitEdges: a slab's pieces miscounted");
    const std::size_t n = slabOrder_.size();
    // The slab's crossings count once it is sorted; until then each checks the room left below
    // Limits::maxCrossings (crossings_ never exceeds it) before it takes memory.
    slabRoom_ = spec_.maxCrossings - crossings_;
    for (std::size_t i = 1; i < n; ++i) {
      const SlabEntry e = slabOrder_[i];
      std::size_t j = i;
      while (j > 0 && lowerAtSlabEnd(e, slabOrder_[j - 1])) {
        slabCrossing(slabOrder_[j - 1].piece, e.piece, x);
        slabOrder_[j] = slabOrder_[j - 1];
        --j;
      }
      slabOrder_[j] = e;
    }
    crossings_ += slabEvents_.size();
    sortSlabEvents();
  }
  // The slab's crossings in sweep order. By their cached x first: a bucket sort into n buckets
  // of equal width between the least and the greatest x (a slab's crossings spread along it,
  // a few to a bucket), then an insertion sort by the exact order moves the few that the
  // buckets leave out of order (one comparison each where it does not). Crossings that crowd
  // into a few buckets (a column of them on a slab's end) can leave it many moves: past 4n + 64
  // a comparison sort by the exact order takes over.
  void sortSlabEvents() {
    const std::size_t n = slabEvents_.size();
    const auto exactly = [this](const SweepEvent& a, const SweepEvent& b) {
      return eventAfter(b, a);
    };
    const double least = slabLeast_, greatest = slabGreatest_;
    if (n < kBucketSlabFrom || !(greatest > least)) {
      boost::sort::pdqsort(slabEvents_.begin(), slabEvents_.end(), exactly);
      return;
    }
    // Monotone in x (a difference, a product, a minimum and a truncation, each monotone): a
    // later bucket never holds an earlier x. The minimum is taken before the conversion, so an
    // x a rounding beyond n (or a quotient beyond any size) converts within range.
    const double perBucket = double(n) / (greatest - least), last = double(n - 1);
    slabBuckets_.resize(n);
    slabBucketStarts_.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      const auto b = std::size_t(std::min((slabEvents_[i].fx - least) * perBucket, last));
      slabBuckets_[i] = std::uint32_t(b);
      ++slabBucketStarts_[b];
    }
    std::uint32_t sum = 0;
    for (std::uint32_t& start : slabBucketStarts_) {
      const std::uint32_t count = start;
      start = sum;
      sum += count;
    }
    slabEventScratch_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      slabEventScratch_[slabBucketStarts_[slabBuckets_[i]]++] = slabEvents_[i];
    }
    slabEvents_.swap(slabEventScratch_);
    std::size_t moves = 0;
    for (std::size_t i = 1; i < n; ++i) {
      if (!eventAfter(slabEvents_[i - 1], slabEvents_[i])) continue;
      const SweepEvent e = slabEvents_[i];
      std::size_t j = i;
      do {
        slabEvents_[j] = slabEvents_[j - 1];
        --j;
      } while (j > 0 && eventAfter(slabEvents_[j - 1], e));
      slabEvents_[j] = e;
      moves += i - j;
      if (moves > 4 * n + 64) {
        boost::sort::pdqsort(slabEvents_.begin(), slabEvents_.end(), exactly);
        return;
      }
    }
  }
  static constexpr std::size_t kBucketSlabFrom = 64;  // fewer crossings: a comparison sort
  // Whether e lies below f just after the slab's right end.
  [[nodiscard]] bool lowerAtSlabEnd(const SlabEntry& e, const SlabEntry& f) const {
    const int c = compareCachedInBox(e.height, f.height);
    if (c != 0) return c < 0;
    const i128 l = i128(e.num) * f.dx, r = i128(f.num) * e.dx;
    if (l != r) return l < r;
    return crossSign(pieces_[std::size_t(e.piece)].direction(),
                     pieces_[std::size_t(f.piece)].direction()) > 0;
  }
  // Pieces lower (below upper in the status) and upper cross in the slab that ends at x: their
  // lines' crossing is queued, unless it is the right end of one of them (an input vertex, whose
  // visit cuts the other). Its exact point is not worked out here (kOnLines): a direct visit
  // needs it only where it may be a grid point, and the rest only where cached doubles cannot
  // decide. Those doubles come from the crossing's parameter along the lower piece's line,
  // t = num / den in [0, 1] (the pieces span the slab, so their crossing lies on both): each of
  // num, den (exact) rounded once, the quotient once, dx t and ax + dx t once each. With |dx| <=
  // 2^31 and |ax + dx t| <= 2^30 (grid range) that is within 2^31 * 4 * 2^-53 + 2^30 * 2^-53 =
  // 2^-20 + 2^-23 of the exact coordinate (terms of order 2^-70 aside), the same for y. That is
  // more than XPoint's 2^-21, and still inside compareCachedInBox()'s bound: two such values
  // are off by at most 2.25 * 2^-20 together, their rounded difference by 2^-22 more, and the
  // filter answers only beyond 2^-18 = 4 * 2^-20.
  [[gnu::always_inline]] void slabCrossing(int lower, int upper, std::int64_t x) {
    const SweepPiece& a = pieces_[std::size_t(lower)];
    const SweepPiece& b = pieces_[std::size_t(upper)];
    const std::int64_t d1x = std::int64_t(a.bx) - a.ax, d1y = std::int64_t(a.by) - a.ay;
    const std::int64_t d2x = std::int64_t(b.bx) - b.ax, d2y = std::int64_t(b.by) - b.ay;
    const std::int64_t cx = std::int64_t(b.ax) - a.ax, cy = std::int64_t(b.ay) - a.ay;
    // crossingParameter() (pipeline.hpp) again, specialised: its sign normalisation and wide
    // checks cost W3-1k even-odd 9.3M more here. The lower piece ends above the upper one: it is
    // the steeper (dx > 0 for both), so den = d2 x d1 > 0, and the crossing lies on the lower
    // piece: num = (b.a - a.a) x d2 lies in [0, den]. Each product of two differences lies
    // within 2^62, so both fit 64 bits but where den reaches 2^63 (the grid range's diagonals).
    std::int64_t den = 0, num = 0;
    double t = 0;
    if (!__builtin_sub_overflow(d1y * d2x, d1x * d2y, &den) &&
        !__builtin_sub_overflow(cy * d2x, cx * d2y, &num)) {
      // 0 <= num <= den with den > 0: a negative num is beyond den as an unsigned number.
      if (den <= 0 || std::uint64_t(num) > std::uint64_t(den)) notACrossing();
      t = double(num) / double(den);
    } else {
      t = slabParameterWide(a, b);
    }
    const double fx = double(a.ax) + double(d1x) * t, fy = double(a.ay) + double(d1y) * t;
    if (compareCachedInBox(fx, double(x)) >= 0) {  // perhaps on the line x: the exact test
      const XPoint p = exactCrossing(lower, upper);
      if (atGridPoint(p, a.lineB()) || atGridPoint(p, b.lineB())) return;
    }
    if (slabEvents_.size() >= slabRoom_) crossingsBeyondLimit();
    slabEvents_.push_back({fx, fy, kOnLines, -1, lower, upper});
    slabLeast_ = std::min(slabLeast_, fx);
    slabGreatest_ = std::max(slabGreatest_, fx);
  }
  // slabCrossing()'s t where num or den do not fit 64 bits signed.
  [[gnu::noinline, gnu::cold]] static double slabParameterWide(const SweepPiece& a,
                                                               const SweepPiece& b) {
    const i128 d1x = std::int64_t(a.bx) - a.ax, d1y = std::int64_t(a.by) - a.ay;
    const i128 d2x = std::int64_t(b.bx) - b.ax, d2y = std::int64_t(b.by) - b.ay;
    const i128 cx = std::int64_t(b.ax) - a.ax, cy = std::int64_t(b.ay) - a.ay;
    const i128 den = d1y * d2x - d1x * d2y, num = cy * d2x - cx * d2y;
    if (den <= 0 || num < 0 || num > den) notACrossing();
    return toDouble(num) / toDouble(den);
  }
  [[noreturn, gnu::noinline, gnu::cold]] static void notACrossing() {
    throw InternalError("splitEdges: a slab swapped pieces that do not cross");
  }
  // Slab mode from a slab whose crossings found were at least 1/16 of the active pieces, normal
  // mode from one with fewer than 1/64.
  static constexpr std::uint64_t kEnterSlabs = 16, kLeaveSlabs = 64;

  const BooleanSpec& spec_;
  const PieceClassifier classifier_{spec_};                    // stage 2 for every closed piece
  const bool insideOutside_ = classifier_.inside(Windings{});  // below every piece
  std::uint64_t crossings_ = 0;  // crossings found so far (Limits::maxCrossings)
  int vertex_ = -1;
  std::array<int, 2> crossingHere_{-1, -1};  // two pieces crossing at the current event point
  std::vector<SweepPiece>& pieces_;
  std::vector<int>& pieceLines_;
  std::vector<XPoint>& openLefts_;
  std::vector<XPoint>& exactRights_;
  std::vector<SweepStart>& starts_;
  const StartFrame frame_;  // the grid range's corner
  std::size_t cursor_ = 0;
  // StartFrame keys are below 2^63 (two differences below 2^31): this one is no start's.
  static constexpr std::uint64_t kNoStartKey = ~std::uint64_t{0};
  std::uint64_t pointKey_ = kNoStartKey;
  std::vector<SweepEvent>& queue_;
  std::vector<ExactCoords>& eventPoints_;
  std::vector<int>& freeEventPoints_;
  std::vector<int>& starting_;
  std::vector<int>& through_;
  std::vector<SlabEntry>& slabOrder_;
  std::vector<SweepEvent>& slabEvents_;           // the slab's crossings, sorted (slab mode)
  std::vector<std::uint32_t>& slabBuckets_;       // their sort's bucket of each
  std::vector<std::uint32_t>& slabBucketStarts_;  // and where each bucket starts
  std::vector<SweepEvent>& slabEventScratch_;
  double slabLeast_ = 0, slabGreatest_ = 0;  // the least and greatest cached x of its crossings
  std::size_t slabHead_ = 0;                 // the first not visited
  std::size_t slabEnd_ = 0;       // slabEvents_.size(), kept here for the tests of every event
  std::uint64_t slabKeyEnd_ = 0;  // start keys beyond the line x = slabRight_ (moveLine())
  bool slabMode_ = false;
  std::int64_t slabRight_ = std::numeric_limits<std::int64_t>::min();
  std::uint64_t crossingsAtSlab_ = 0;  // crossings_ when the slab began
  std::uint64_t slabRoom_ = 0;         // crossings a slab pass may still find (slabPass())
  std::uint64_t slabPasses_ = 0;
  int active_ = 0;  // pieces in the status
  std::deque<StatusNode>& nodes_;
  std::vector<StatusNode*>& freeNodes_;
  Status status_;
  StatusNode* top_ = nullptr;  // the top node of the status, null when it is empty
  Arrangement out_;
};

// The sweep over edges and exactEdges; with releaseEdges, the workspace's edge arrays are
// released once the sweep has its pieces (it does not read them again).
template <bool kSlabs>
Arrangement sweepEdges(const std::vector<InputEdge>& edges,
                       const std::vector<ExactEdge>& exactEdges, const BooleanSpec& spec,
                       Workspace& workspace, bool releaseEdges) {
  Arrangement result;
  {
    Sweep<kSlabs> sweep(edges, exactEdges, spec, workspace);
    if (releaseEdges) releaseEachAbove(kKeptStageBytes, workspace.edges, workspace.clipped);
    result = sweep.run();
  }
  workspace.releaseSweepIfAbove(kKeptStageBytes);
  return result;
}

// Slab mode needs every piece to start at an input vertex: no edge with an off-grid end (the
// convex pre-clip's cut edges) and no open polyline (clipLines(), the only caller that keeps no
// boundary; the sweep checks each edge too).
Arrangement sweepEdges(const std::vector<InputEdge>& edges,
                       const std::vector<ExactEdge>& exactEdges, const BooleanSpec& spec,
                       Workspace& workspace, bool releaseEdges) {
  workspace.generalPathUsed = true;
  if (spec.slabs && exactEdges.empty() && spec.keepBoundary) {
    return sweepEdges<true>(edges, exactEdges, spec, workspace, releaseEdges);
  }
  return sweepEdges<false>(edges, exactEdges, spec, workspace, releaseEdges);
}

}  // namespace

Arrangement splitEdges(const std::vector<InputEdge>& edges,
                       const std::vector<ExactEdge>& exactEdges, const BooleanSpec& spec,
                       Workspace& workspace) {
  return sweepEdges(edges, exactEdges, spec, workspace, false);
}

Arrangement splitWorkspaceEdges(const BooleanSpec& spec, Workspace& workspace) {
  return sweepEdges(workspace.edges, workspace.clipped, spec, workspace, true);
}

Arrangement splitEdges(const std::vector<InputEdge>& edges,
                       const std::vector<ExactEdge>& exactEdges, const BooleanSpec& spec) {
  const WorkspaceLease workspace;
  return splitEdges(edges, exactEdges, spec, *workspace);
}

}  // namespace roiclip::detail
