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
// new piece, it also labels each piece with the winding numbers on both of its sides.
//
// Cost: O((n + k) log n) time for n edges and k intersection points, O(n + k) memory.
#include <algorithm>
#include <queue>
#include <set>

#include <boost/sort/pdqsort/pdqsort.hpp>

#include <roiclip/error.hpp>

#include "pipeline.hpp"

namespace roiclip::detail {
namespace {

struct Active {
  XPoint left, right;
  IPoint lineA, lineB;
  Windings contribution{};
  Windings windBelow{};
  int slot = -1;          // index of its output piece (result pieces only) while in the status
  int resultBelow = -1;   // nearest result piece below it when it was inserted
  int checkedAbove = -1;  // the last piece above it tested for a crossing (see checkCrossing)
  bool open = false;      // a piece of an open polyline (zero contribution, never merged)
  LinePlace place = LinePlace::Outside;  // open pieces: where it lies
  [[nodiscard]] int nearestResult() const { return slot >= 0 ? slot : resultBelow; }
  [[nodiscard]] IPoint direction() const { return {lineB.x - lineA.x, lineB.y - lineA.y}; }
};

struct Event {
  XPoint point;
  int piece = -1;    // -1: visit the point only
  int through = -1;  // a crossing: one of the two pieces crossing there (locates p in the status)
};

struct EventAfter {
  bool operator()(const Event& a, const Event& b) const { return less(b.point, a.point); }
};

class Sweep {
 public:
  Sweep(const std::vector<InputEdge>& edges, const std::vector<ExactEdge>& exactEdges,
        const Combination& how)
      : how_(how), status_(StatusLess{&active_}) {
    const std::size_t total = edges.size() + exactEdges.size();
    active_.clear();
    initial_.clear();
    active_.reserve(total);
    where_.resize(total);
    inStatus_.assign(total, 0);
    initial_.reserve(edges.size() * 2);
    for (const InputEdge& e : edges) {
      Active a;
      a.left = XPoint(e.a);
      a.right = XPoint(e.b);
      a.lineA = e.a;
      a.lineB = e.b;
      a.contribution[e.operand] = e.open ? 0 : e.direction;
      a.open = e.open;
      initial_.push_back({e.a, int(active_.size()), false});
      initial_.push_back({e.b, int(active_.size()), true});
      active_.push_back(a);
    }
    // Edges with off-grid ends start from the dynamic queue; their ends are plain events.
    for (const ExactEdge& e : exactEdges) {
      Active a;
      a.left = e.left;
      a.right = e.right;
      a.lineA = e.lineA;
      a.lineB = e.lineB;
      a.contribution[e.operand] = e.direction;
      const int id = int(active_.size());
      if (e.left.w == 1) {
        initial_.push_back({{std::int64_t(e.left.x), std::int64_t(e.left.y)}, id, false});
      } else {
        queue_.push({e.left, id});
      }
      if (e.right.w == 1) {
        initial_.push_back({{std::int64_t(e.right.x), std::int64_t(e.right.y)}, id, true});
      } else {
        queue_.push({e.right, -1});
      }
      active_.push_back(a);
    }
    // pdqsort: on the ends of a contour's edges (x rising and falling along the blob) std::sort's
    // median-of-3 quicksort hit its depth limit and fell back to heapsort, 18% of the 100k
    // contour x quad row.
    boost::sort::pdqsort(
        initial_.begin(), initial_.end(),
        [](const InitialEvent& a, const InitialEvent& b) { return a.point < b.point; });
    out_.pieces.reserve(total / 4 + 16);
    out_.vertices.reserve(total / 4 + 16);
  }

  /// Frees the arrays this thread keeps (releaseThreadBuffers()).
  static void releaseBuffers() { threadBuffers() = Buffers{}; }

  Sweep(const Sweep&) = delete;
  Sweep& operator=(const Sweep&) = delete;
  ~Sweep() {          // the arrays are recycled also when the sweep throws
    status_.clear();  // before the node handles in where_ are dropped
    recycle(active_);
    recycle(initial_);
    recycle(where_);
    recycle(inStatus_);
  }

  Arrangement run() {
    XPoint p;
    while (nextPoint(p)) visit(p);
    if (!status_.empty()) throw InternalError("splitEdges: sweep ended with active pieces");
    return std::move(out_);
  }

 private:
  // Order of active pieces along the sweep line, bottom to top. Pieces in the status never cross
  // to the left of the sweep point, so comparing where the later-starting piece begins against
  // the other's supporting line is enough.
  struct StatusLess {
    using is_transparent = void;
    const std::vector<Active>* active;
    bool operator()(int a, int b) const {
      const Active& pa = (*active)[a];
      const Active& pb = (*active)[b];
      const int c = compare(pa.left, pb.left);
      int o = 0;
      if (c < 0) {
        o = orient(pa.lineA, pa.lineB, pb.left);
      } else if (c > 0) {
        o = -orient(pb.lineA, pb.lineB, pa.left);
      }
      if (o != 0) return o > 0;
      const int s = crossSign(pa.direction(), pb.direction());
      if (s != 0) return s > 0;
      // Coincident: the (single, merged) closed piece below the open ones, as visit() labels.
      return pa.open != pb.open ? pb.open : a < b;
    }
    // Piece below point / point below piece, for finding the pieces through a point.
    bool operator()(int a, const XPoint& p) const {
      const Active& pa = (*active)[a];
      return orient(pa.lineA, pa.lineB, p) > 0;
    }
    bool operator()(const XPoint& p, int a) const {
      const Active& pa = (*active)[a];
      return orient(pa.lineA, pa.lineB, p) < 0;
    }
  };
  using Status = std::set<int, StatusLess>;

  struct InitialEvent {
    IPoint point;
    int piece;
    bool end;  // the right end of `piece` (a hint: the piece may have been merged away)
  };

  // The per-edge working arrays, kept per thread between sweeps (see recycle()).
  struct Buffers {
    std::vector<Active> active;
    std::vector<InitialEvent> initial;
    std::vector<Status::iterator> where;
    std::vector<char> inStatus;
  };
  static Buffers& threadBuffers() {
    thread_local Buffers buffers;
    return buffers;
  }

  bool nextPoint(XPoint& p) const {
    const bool hasInitial = cursor_ < initial_.size();
    if (!hasInitial && queue_.empty()) return false;
    if (!hasInitial) {
      p = queue_.top().point;
    } else if (queue_.empty()) {
      p = XPoint(initial_[cursor_].point);
    } else {
      const XPoint a(initial_[cursor_].point);
      p = less(queue_.top().point, a) ? queue_.top().point : a;
    }
    return true;
  }

  // The vertex id of the current event point, stored on first use: only vertices of result
  // pieces are kept. Ids still follow the sweep order, i.e. lexicographic order.
  int vertexHere(const XPoint& p) {
    if (vertex_ < 0) {
      vertex_ = int(out_.vertices.size());
      out_.vertices.push_back(p);
    }
    return vertex_;
  }

  void visit(const XPoint& p) {
    vertex_ = -1;
    starts_.clear();
    int locator = -1;  // a piece known to pass through p, if any: its status node locates p
    while (cursor_ < initial_.size() && equal(XPoint(initial_[cursor_].point), p)) {
      const InitialEvent& ev = initial_[cursor_];
      if (!ev.end) {
        starts_.push_back(ev.piece);
      } else if (inStatus_[ev.piece] && equal(active_[ev.piece].right, p)) {
        locator = ev.piece;
      }
      ++cursor_;
    }
    while (!queue_.empty() && equal(queue_.top().point, p)) {
      const Event& ev = queue_.top();
      if (ev.piece >= 0) starts_.push_back(ev.piece);
      // A piece still in the status whose line passes through p goes through p (it started
      // before p and ends at or after it): its node locates p without a search.
      if (locator < 0 && ev.through >= 0 && inStatus_[ev.through] &&
          orient(active_[ev.through].lineA, active_[ev.through].lineB, p) == 0) {
        locator = ev.through;
      }
      queue_.pop();
    }

    // Every active piece through p ends here; the ones that go on are cut and re-inserted.
    // The pieces through p are contiguous in the status.
    auto passes = [&](Status::iterator it) {
      return orient(active_[*it].lineA, active_[*it].lineB, p) == 0;
    };
    Status::iterator lo, hi;
    if (locator >= 0) {
      lo = where_[locator];
      hi = std::next(lo);
      while (lo != status_.begin() && passes(std::prev(lo))) --lo;
    } else {
      lo = status_.lower_bound(p);
      hi = lo;
    }
    while (hi != status_.end() && passes(hi)) ++hi;
    const int belowPiece = lo == status_.begin() ? -1 : *std::prev(lo);
    through_.assign(lo, hi);
    for (int id : through_) {
      Active& a = active_[id];
      inStatus_[id] = 0;
      if (a.slot >= 0) out_.pieces[a.slot].right = vertexHere(p);
      if (a.open) out_.openPieces.push_back({id, a.left, p, a.place});
      if (!equal(a.right, p)) {
        a.left = p;
        starts_.push_back(id);
      }
    }

    mergeCoincident();

    // The pieces starting at p take the status positions of the pieces through p: every one of
    // them lies between belowPiece and the piece above, so the nodes [lo, hi) are reused in
    // order (a chain going on, two pieces crossing), and only the surplus is erased or inserted.
    auto node = lo;

    // Insert bottom to top, labelling winding numbers from the piece below; keep only the
    // pieces that bound the result (stage 2, classify, decides).
    Windings wind = belowPiece >= 0 ? windAbove(active_[belowPiece]) : Windings{};
    int resultBelow = belowPiece >= 0 ? active_[belowPiece].nearestResult() : -1;
    int closedRun = -1;  // the last closed piece inserted here, and the winding below it
    Windings closedRunBelow{};
    for (int id : starts_) {
      Active& a = active_[id];
      a.windBelow = wind;
      a.resultBelow = resultBelow;
      a.slot = -1;
      if (a.open) {
        // An open piece coincident with the closed piece just below it lies on that piece:
        // the region's winding numbers on its two sides are the ones around that piece.
        const bool onClosed =
            closedRun >= 0 && crossSign(active_[closedRun].direction(), a.direction()) == 0;
        a.place = classifyOpenPiece(onClosed ? closedRunBelow : wind, wind, how_);
      } else {
        closedRun = id;
        closedRunBelow = wind;
      }
      const Side side =
          a.open || !how_.keepBoundary ? Side::None : classifyPiece(wind, a.contribution, how_);
      if (side != Side::None) {
        a.slot = int(out_.pieces.size());
        EdgePiece piece;
        piece.left = vertexHere(p);
        piece.lineA = a.lineA;
        piece.lineB = a.lineB;
        piece.contribution = a.contribution;
        piece.windBelow = wind;
        piece.below = resultBelow;
        out_.pieces.push_back(piece);
        out_.sides.push_back(side);
      }
      wind = windAbove(a);
      resultBelow = a.nearestResult();
      if (node != hi) {
        const_cast<int&>(*node) = id;  // same position in the order, see above
        where_[id] = node++;
      } else {
        where_[id] = status_.emplace_hint(hi, id);
      }
      inStatus_[id] = 1;
    }
    status_.erase(node, hi);

    const int abovePiece = hi == status_.end() ? -1 : *hi;
    if (starts_.empty()) {
      checkCrossing(belowPiece, abovePiece, p);
    } else {
      checkCrossing(belowPiece, starts_.front(), p);
      checkCrossing(starts_.back(), abovePiece, p);
    }
  }

  static Windings windAbove(const Active& a) {
    return {a.windBelow[0] + a.contribution[0], a.windBelow[1] + a.contribution[1]};
  }

  // Sort the pieces in starts_ by direction; merge runs of coincident closed ones into the
  // shortest and re-start the rest where it ends. Closed pieces whose contributions cancel are
  // dropped: they change no winding number (a spike out and back along itself). Open pieces are
  // never merged or dropped; they follow the closed piece of their direction, as in the status.
  void mergeCoincident() {
    std::sort(starts_.begin(), starts_.end(), [this](int a, int b) {
      const int s = crossSign(active_[a].direction(), active_[b].direction());
      if (s != 0) return s > 0;
      if (active_[a].open != active_[b].open) return active_[b].open;
      const int c = compare(active_[a].right, active_[b].right);
      return c != 0 ? c < 0 : a < b;
    });
    std::size_t kept = 0;
    for (std::size_t i = 0; i < starts_.size();) {
      const int first = starts_[i];
      std::size_t j = i + 1;
      while (j < starts_.size() && !active_[starts_[j]].open &&
             crossSign(active_[first].direction(), active_[starts_[j]].direction()) == 0) {
        Active& other = active_[starts_[j]];
        for (int k = 0; k < kOperands; ++k) active_[first].contribution[k] += other.contribution[k];
        if (!equal(other.right, active_[first].right)) {
          other.left = active_[first].right;
          queue_.push({other.left, starts_[j]});
        }
        ++j;
      }
      const Windings& c = active_[first].contribution;
      if (active_[first].open || c[0] != 0 || c[1] != 0) starts_[kept++] = first;
      i = j;
    }
    starts_.resize(kept);
  }

  void checkCrossing(int a, int b, const XPoint& p) {
    if (a < 0 || b < 0) return;
    Active& pa = active_[a];
    const Active& pb = active_[b];
    // A piece keeps its supporting segment and right end when it is cut, so a pair's crossing
    // never changes: testing the same pair again can only find the same event.
    if (pa.checkedAbove == b) return;
    pa.checkedAbove = b;
    // Two pieces leaving the same point (right after their crossing) cannot cross again.
    if (equal(pa.left, pb.left)) return;
    // Cheap exact rejection on the integer supporting segments before the rational crossing.
    if (std::max(pa.lineA.x, pb.lineA.x) > std::min(pa.lineB.x, pb.lineB.x)) return;
    if (std::max(std::min(pa.lineA.y, pa.lineB.y), std::min(pb.lineA.y, pb.lineB.y)) >
        std::min(std::max(pa.lineA.y, pa.lineB.y), std::max(pb.lineA.y, pb.lineB.y))) {
      return;
    }
    const int o1 = orient(pa.lineA, pa.lineB, pb.lineA), o2 = orient(pa.lineA, pa.lineB, pb.lineB);
    if (o1 * o2 > 0 || (o1 == 0 && o2 == 0)) return;
    const int o3 = orient(pb.lineA, pb.lineB, pa.lineA), o4 = orient(pb.lineA, pb.lineB, pa.lineB);
    if (o3 * o4 > 0) return;
    XPoint x;
    if (!lineIntersection(pa.lineA, pa.lineB, pb.lineA, pb.lineB, x)) return;
    if (compare(x, p) <= 0) return;
    const int ca = compare(x, pa.right);
    const int cb = compare(x, pb.right);
    if (ca > 0 || cb > 0) return;
    if (ca == 0 || cb == 0) return;  // already an event: the end of one of them
    // The work budget (Limits::maxCrossings), before the event takes memory.
    if (++crossings_ > how_.maxCrossings) {
      throw ResourceLimitError("maxCrossings", how_.maxCrossings, "crossings");
    }
    queue_.push({x, -1, a});
  }

  const Combination& how_;
  std::uint64_t crossings_ = 0;  // crossings found so far (Limits::maxCrossings)
  int vertex_ = -1;
  Buffers& buffers_ = threadBuffers();
  std::vector<Active>& active_ = buffers_.active;
  std::vector<InitialEvent>& initial_ = buffers_.initial;
  std::size_t cursor_ = 0;
  std::priority_queue<Event, std::vector<Event>, EventAfter> queue_;
  Status status_;
  std::vector<Status::iterator>& where_ =
      buffers_.where;  // status node of each piece while inStatus_
  std::vector<char>& inStatus_ = buffers_.inStatus;
  std::vector<int> starts_;
  std::vector<int> through_;
  Arrangement out_;
};

}  // namespace

void releaseSweepBuffers() { Sweep::releaseBuffers(); }

Arrangement splitEdges(const std::vector<InputEdge>& edges,
                       const std::vector<ExactEdge>& exactEdges, const Combination& how) {
  return Sweep(edges, exactEdges, how).run();
}

}  // namespace roiclip::detail
