// SPDX-License-Identifier: MIT
// Stage 0, the simple-ring test: whether one snapped ring is simple, and the region it bounds.
//
// Most contours a vision pipeline clips do not touch themselves. For those the sweep of stage 1
// finds nothing to split, yet it costs a tree step, a heap step and a piece per vertex. This
// stage asks first, with a Shamos-Hoey sweep over the ring's monotone chains: a ring splits at its
// lexicographic turning vertices into chains whose vertices increase lexicographically (x, then
// y). The sweep visits only the turning vertices, sorted up front (a radix sort of their keys):
// at each, two chains enter or leave the status. Two chains next to each other in the status are
// tested lazily, when they stop being neighbours (a pair starts between them, or one of them
// ends): their vertices since they became neighbours are taken in lexicographic order, each
// against the other chain's edge that spans it, and must lie strictly on its side (walk()). Each
// chain keeps how far its vertices have been tested against the chain below and the one above.
// Before the lexicographically first contact the status is in order, and the two chains that
// meet there are neighbours just before it (Shamos and Hoey); their walk reaches it when they
// stop being neighbours, at or after it. For n vertices in c chains: the sort of the c turning
// vertices (linear, a radix sort, from 64), O(log c) per chain start (O(1) when it starts next to
// the last one started), and two orientations per vertex (one against each neighbouring chain);
// no arithmetic beyond exact int64 orientation (every point is a grid point). The test stops at
// the first contact it finds.
//
// Simple here means: the ring's vertices are distinct, consecutive edges meet only at their
// shared vertex and are not collinear (a straight-on vertex or a spike, which turnsOnce(), asked
// first, rejects), and no other two edges meet at all.
#include <algorithm>
#include <utility>

#include <roiclip/error.hpp>

#include "output.hpp"
#include "pipeline.hpp"
#include "radix_sort.hpp"
#include "workspace.hpp"

namespace roiclip::detail {
namespace {

// The edge of a chain where the status's search meets point q: its cursor `at` moves on to the
// first edge that does not end before q. The chain is in the status at q, so it starts before q
// and ends after it (a chain ending at q would be a second ring vertex on q, rejected before).
inline ChainCursor edgeAt(const ChainNode& c, const IPoint& q) {
  while (c.at.left > 0 && c.end(c.at) < q) {
    c.at = c.next(c.at);
  }
  return c.at;
}

// A chain's edge at point q passes below q (q lies strictly to its left).
struct EdgeBelowPoint {
  bool operator()(const ChainNode& c, const IPoint& q) const {
    const ChainCursor e = edgeAt(c, q);
    return orientInGrid(c.start(e), c.end(e), q) > 0;
  }
  bool operator()(const IPoint& q, const ChainNode& c) const {
    const ChainCursor e = edgeAt(c, q);
    return orientInGrid(c.start(e), c.end(e), q) < 0;
  }
};

class ChainSweep {
 public:
  // `rings[0 .. count)`; with `below`, each ring's entry receives the chain just below its
  // first (lexicographically smallest) vertex when the sweep reaches it, or -1.
  ChainSweep(const std::vector<IPoint>* rings, std::size_t count, ChainScratch& s,
             std::vector<int>* below)
      : rings_(rings), count_(count), s_(s), below_(below), status_() {}
  ChainSweep(const ChainSweep&) = delete;
  ChainSweep& operator=(const ChainSweep&) = delete;
  ~ChainSweep() { status_.clear(); }

  bool run() {
    if (!splitChains()) return false;
    const std::vector<ChainEvent>& events = s_.events;
    // Two turning vertices at one point (contours touching at a pixel corner, most often), found
    // before the sweep runs up to them.
    for (std::size_t e = 1; e < events.size(); ++e) {
      if (events[e - 1].key == events[e].key) return false;
    }
    for (std::size_t e = 0; e < events.size(); ++e) {
      const ChainEvent& x = events[e];
      const IPoint p = frame_.point(x.key);
      if (!s_.chains[std::size_t(x.chain)].started()) {
        if (!insertPair(x.chain, x.pair, p)) return false;
      } else if (!removePair(x.chain, x.pair, p)) {
        return false;
      }
    }
    return true;
  }

 private:
  using Status =
      boost::intrusive::set<ChainNode,
                            boost::intrusive::member_hook<ChainNode, StatusHook, &ChainNode::hook>,
                            boost::intrusive::compare<ChainNode::NeverCompared>,
                            boost::intrusive::constant_time_size<false>>;

  // Index after i in a ring of n vertices, going `step` (+1 or -1).
  static int after(int n, int i, int step) {
    i += step;
    return i == n ? 0 : i < 0 ? n - 1 : i;
  }

  // The ring's maximal runs of lexicographically increasing or decreasing edges, each as a
  // chain from its smallest vertex, and the events of the turning vertices in lexicographic
  // order: the chains of a ring are made in ring order, so chain k and the next one meet at
  // chain k's last vertex in ring order, a turning vertex where both start (chain k runs down
  // the ring) or both end.
  bool splitChains() {
    std::vector<ChainNode>& chains = s_.chains;
    std::vector<ChainEvent>& events = s_.events;
    chains.clear();
    events.clear();
    // Sized up front. A large ring's chains are counted first: a comb of 10M vertices has 5M
    // chains, which growing the array would copy and fault in again (1.3 s of 3.8 s).
    std::size_t vertices = 0;
    for (std::size_t r = 0; r < count_; ++r) vertices += rings_[r].size();
    if (vertices >= kCountChainsFrom) {
      std::size_t turns = 0;
      for (std::size_t r = 0; r < count_; ++r) {
        const std::vector<IPoint>& ring = rings_[r];
        for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
          const std::size_t j = i + 1 == n ? 0 : i + 1, k = j + 1 == n ? 0 : j + 1;
          turns += std::size_t((ring[i] < ring[j]) != (ring[j] < ring[k]));
        }
      }
      chains.reserve(turns);
      events.reserve(turns);
    }
    for (int r = 0; r < int(count_); ++r) {
      const IPoint* const points = rings_[std::size_t(r)].data();
      const int n = int(rings_[std::size_t(r)].size());
      if (n < 3) return false;
      const auto up = [&](int i) { return points[i] < points[after(n, i, 1)]; };
      // A turning vertex to begin at: the first vertex where the direction changes.
      int begin = -1;
      for (int i = 0, prev = up(n - 1); i < n; ++i) {
        const bool u = up(i);
        if (u != bool(prev)) {
          begin = i;
          break;
        }
        prev = u;
      }
      if (begin < 0) return false;  // no ring of distinct points increases all the way round
      const int first = int(chains.size());
      for (int i = begin, done = 0; done < n;) {
        const bool u = up(i);
        const int k = int(chains.size());
        int j = after(n, i, 1), edges = 1;
        for (++done; done < n && up(j) == u; ++done, ++edges) j = after(n, j, 1);
        const bool last = done >= n;
        ChainNode& chain = chains.emplace_back();
        chain.ring = r;
        chain.points = points;
        chain.size = n;
        chain.step = u ? +1 : -1;
        chain.first = u ? i : j;
        chain.edges = edges;
        // Ring order: the previous chain shares vertex i, the next one vertex j.
        const int previous = k == first ? -1 : k - 1, next = last ? first : k + 1;
        (u ? chain.startPartner : chain.endPartner) = previous;
        (u ? chain.endPartner : chain.startPartner) = next;
        // The turning vertex j, shared with the next chain (the ring's first one after its last).
        events.push_back({frame_.key(points[j]), k, next});
        i = j;
      }
      // The ring's first chain shares its vertex `begin` with the last one.
      ChainNode& head = chains[std::size_t(first)];
      (head.step > 0 ? head.startPartner : head.endPartner) = int(chains.size()) - 1;
    }
    if (below_ != nullptr) {
      below_->assign(count_, kNotReached);
      s_.reached.clear();
    }
    sortByKey(events, s_.sorted);  // the sweep visits the turning vertices in this order
    return true;
  }

  // Chains lo and hi (hi just above lo) have been neighbours in the status since a point where
  // lo lay strictly below hi. Their vertices after their cursors' edges, up to point t, are
  // taken in lexicographic order, each tested against the other chain's edge that spans it (the
  // cursors move on): a vertex of lo must lie strictly below hi's edge, one of hi strictly above
  // lo's. Then the vertical gap between the two chains, linear between these vertices (sheared
  // by an infinitesimal so that the lexicographic order is the order in x: orientations do not
  // change), is positive at each of them, so the chains do not meet up to t. False at a contact.
  //
  // Two chains may meet only where both end at one turning vertex (their last edges are
  // consecutive ring edges); two that start at one share its vertex, which no test here takes
  // (turnsOnce() has ruled out their first edges overlapping along each other).
  bool walk(ChainNode& lo, ChainNode& hi, const IPoint& t) const {
    ChainCursor& e = lo.up;
    ChainCursor& f = hi.down;
    IPoint a = lo.start(e), b = lo.end(e), c = hi.start(f), d = hi.end(f);
    for (;;) {
      if (b < d) {
        if (t < b) return true;
        if (orientInGrid(c, d, b) >= 0) return false;  // b on or above hi's edge
        if (e.left == 0) return true;                  // lo ends at b, which is t
        e = lo.next(e);
        a = b;
        b = lo.end(e);
      } else if (d < b) {
        if (t < d) return true;
        if (orientInGrid(a, b, d) <= 0) return false;  // d on or below lo's edge
        if (f.left == 0) return true;                  // hi ends at d, which is t
        f = hi.next(f);
        c = d;
        d = hi.end(f);
      } else {  // both edges end at one point
        return e.left == 0 && f.left == 0 && lo.endPartner == int(&hi - s_.chains.data());
      }
    }
  }

  // Two chains start at their shared (turning) vertex p.
  bool insertPair(int i, int j, const IPoint& p) {
    ChainNode* lo = &s_.chains[std::size_t(i)];
    ChainNode* hi = &s_.chains[std::size_t(j)];
    for (ChainNode* c : {lo, hi}) {
      c->down = c->up = c->at = ChainCursor{c->after(c->first), c->edges - 1};
    }
    const int turn = orientInGrid(p, lo->end(lo->at), hi->end(hi->at));
    if (turn == 0) return false;  // overlapping first edges
    if (turn < 0) std::swap(lo, hi);
    // The first chain whose edge at p does not pass below p.
    ChainNode* above = nullptr;
    Status::iterator at;
    if (!nearFinger(p, above)) {
      at = status_.lower_bound(p, EdgeBelowPoint{});
      above = at == status_.end() ? nullptr : &*at;
    } else {
      at = above != nullptr ? status_.iterator_to(*above) : status_.end();
    }
    ChainNode* below = above != nullptr ? above->below : top_;
    // The two neighbours stop being neighbours at p. The chain below passes strictly below p
    // (the search's order), the one above must pass strictly above it. A chain that had no
    // neighbour on the new chains' side has its vertices up to p tested against none: its
    // cursor moves on to p untested.
    if (below != nullptr && above != nullptr && !walk(*below, *above, p)) return false;
    if (above != nullptr && !EdgeBelowPoint{}(p, *above)) return false;  // p on its edge
    if (below != nullptr && above == nullptr) below->up = edgeAt(*below, p);
    if (above != nullptr && below == nullptr) above->down = above->at;  // set by edgeAt()
    status_.insert_before(at, *lo);
    status_.insert_before(at, *hi);
    finger_ = hi;
    lo->below = below;
    lo->above = hi;
    hi->below = lo;
    hi->above = above;
    if (below != nullptr) below->above = lo;
    (above != nullptr ? above->below : top_) = hi;
    // A ring's first pair of chains starts at its smallest vertex: what lies below it there.
    if (below_ != nullptr && (*below_)[std::size_t(lo->ring)] == kNotReached) {
      (*below_)[std::size_t(lo->ring)] = below != nullptr ? int(below - s_.chains.data()) : -1;
      s_.reached.push_back(lo->ring);
    }
    return true;
  }

  // The first chain whose edge at p does not pass below p (null: none), when it lies within
  // a few steps of the last pair inserted (finger_) along the status: chains often start in
  // order up a side (a comb's teeth start up one line), and then the tree's search, a cache miss
  // a level on a large status, is not needed. False when it lies further.
  bool nearFinger(const IPoint& p, ChainNode*& above) const {
    constexpr int kSteps = 4;
    const EdgeBelowPoint passesBelow;
    ChainNode* f = finger_;
    if (f == nullptr) return false;
    if (passesBelow(*f, p)) {  // up from the finger to the first that does not pass below
      ChainNode* g = f->above;
      for (int k = 0; g != nullptr && passesBelow(*g, p); ++k, g = g->above) {
        if (k == kSteps) return false;
      }
      above = g;
      return true;
    }
    for (int k = 0; f->below != nullptr && !passesBelow(*f->below, p); ++k, f = f->below) {
      if (k == kSteps) return false;
    }
    above = f;
    return true;
  }

  // Two chains end at their shared (turning) vertex p: they leave the status, next to each
  // other, once the vertices of each neighbouring pair are tested up to p.
  bool removePair(int i, int j, const IPoint& p) {
    ChainNode* lo = &s_.chains[std::size_t(i)];
    ChainNode* hi = &s_.chains[std::size_t(j)];
    if (lo->above != hi) std::swap(lo, hi);
    if (lo->above != hi) return false;  // something passes between them into their end
    ChainNode* below = lo->below;
    ChainNode* above = hi->above;
    if (below != nullptr && !walk(*below, *lo, p)) return false;
    if (!walk(*lo, *hi, p)) return false;
    if (above != nullptr && !walk(*hi, *above, p)) return false;
    if (below != nullptr) below->above = above;
    (above != nullptr ? above->below : top_) = below;
    status_.erase(status_.iterator_to(*lo));
    status_.erase(status_.iterator_to(*hi));
    if (finger_ == lo || finger_ == hi) finger_ = below != nullptr ? below : above;
    return true;
  }

  static constexpr int kNotReached = -2;
  static constexpr std::size_t kCountChainsFrom = std::size_t{1} << 18;  // vertices
  const std::vector<IPoint>* rings_;
  std::size_t count_;
  ChainScratch& s_;
  std::vector<int>* below_;
  const StartFrame frame_;
  Status status_;
  ChainNode* top_ = nullptr;     // the top chain of the status, null when it is empty
  ChainNode* finger_ = nullptr;  // the last chain inserted, or a chain next to where it was
};

}  // namespace

bool turnsOnce(const std::vector<IPoint>& ring) {
  const std::size_t n = ring.size();
  if (n < 3) return false;
  // Counts the edge direction passing angle 0 (the positive x axis): counter-clockwise when it
  // moves from the lower half-turn [pi, 2 pi) to the upper one [0, pi) turning left, clockwise
  // when it moves from the upper to the lower turning right. Each turn is less than a half turn
  // in magnitude, so it passes 0 at most once. Collinear consecutive edges, a spike (a half turn)
  // or a straight-on vertex (none), are not simple (ringIsSimple()): the chain sweep relies on
  // this test for them.
  const auto lower = [](IPoint d) { return d.y < 0 || (d.y == 0 && d.x < 0); };
  const IPoint* const p = ring.data();
  IPoint d{p[0].x - p[n - 1].x, p[0].y - p[n - 1].y};
  bool fromLower = lower(d);
  long long turns = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const IPoint b = p[i + 1 == n ? 0 : i + 1];
    const IPoint e{b.x - p[i].x, b.y - p[i].y};
    // The sign of d x e, exact for grid points (|differences| <= 2^31: products below 2^62).
    const std::int64_t l = d.x * e.y, r = d.y * e.x;
    if (l == r) return false;  // a spike or a straight-on vertex: not simple (see ringIsSimple())
    const bool toLower = lower(e);
    // Across angle 0: from the lower half-turn turning left, or from the upper turning right.
    turns += int(fromLower && !toLower && l > r) - int(!fromLower && toLower && l < r);
    d = e;
    fromLower = toLower;
  }
  return turns == 1 || turns == -1;
}

Path simpleRingPath(const std::vector<IPoint>& ring, LowestVertex lowest, bool hole,
                    const OutputFrame& frame) {
  const std::size_t n = ring.size(), first = lowest.index;
  const bool forward = lowest.ccw != hole;  // the ring's order has the filled side on the left
  // Vertex t steps along the filled-left order from the smallest one; output index k takes
  // t = n - 1 - k for an outer ring, and for a hole t = n - 2 - k, then n - 1 last.
  const auto traced = [&](std::size_t t) {
    return ring[forward ? (first + t) % n : (first + n - t % n) % n];
  };
  return outputRing(n, [&](std::size_t k) {
    const std::size_t t = !hole ? n - 1 - k : k + 1 < n ? n - 2 - k : n - 1;
    return frame.point(traced(t));
  });
}

bool ringIsSimple(const std::vector<IPoint>& ring, ChainScratch& scratch, bool turnsChecked) {
  return (turnsChecked || turnsOnce(ring)) && ChainSweep(&ring, 1, scratch, nullptr).run();
}

bool ringsAreSimple(const Rings& rings, ChainScratch& scratch) {
  for (const std::vector<IPoint>& ring : rings) {
    if (!turnsOnce(ring)) return false;
  }
  return ChainSweep(rings.data(), rings.size(), scratch, &scratch.below).run();
}

void nestSimpleRings(const Rings& rings, FillRule rule, ChainScratch& scratch) {
  std::vector<RingNesting>& rn = scratch.nesting;
  rn.assign(rings.size(), RingNesting{});
  for (std::size_t r = 0; r < rings.size(); ++r) rn[r].lowest = lowestVertex(rings[r]);
  // In the order the sweep reached the rings (their smallest vertices in lexicographic order,
  // the order stages 1 to 4 emit them in). The chain just below a ring's smallest vertex
  // belongs to the innermost ring around it when that ring's inside lies above the chain, else
  // to a ring beside it, which has the same innermost ring around it.
  for (const int r : scratch.reached) {
    RingNesting& ring = rn[std::size_t(r)];
    const int b = scratch.below[std::size_t(r)];
    if (b >= 0) {
      const ChainNode& chain = scratch.chains[std::size_t(b)];
      const RingNesting& beside = rn[std::size_t(chain.ring)];
      ring.around = (chain.step > 0) == beside.lowest.ccw ? chain.ring : beside.around;
    }
    const RingNesting* around = ring.around >= 0 ? &rn[std::size_t(ring.around)] : nullptr;
    const int outside = around != nullptr ? around->winding : 0;
    ring.winding = outside + (ring.lowest.ccw ? 1 : -1);
    ring.filledInside = isFilled(rule, ring.winding);
    ring.inResult = ring.filledInside != isFilled(rule, outside);
    ring.resultAround = around == nullptr  ? -1
                        : around->inResult ? ring.around
                                           : around->resultAround;
  }
}

PolygonSet simpleRingsRegion(const Rings& rings, FillRule rule, ChainScratch& scratch,
                             const Grid& grid) {
  nestSimpleRings(rings, rule, scratch);
  std::vector<RingNesting>& rn = scratch.nesting;
  const OutputFrame frame(grid);
  PolygonSet result;
  for (const int r : scratch.reached) {
    RingNesting& ring = rn[std::size_t(r)];
    if (!ring.inResult) continue;
    // An outer ring's owner is the hole it lies in; a hole's, its outer ring.
    const int owner = ring.resultAround;
    if (owner >= 0 && rn[std::size_t(owner)].dropped) {
      ring.dropped = true;
      continue;
    }
    const bool hole = !ring.filledInside;
    if (hole && (owner < 0 || rn[std::size_t(owner)].polygon < 0)) {
      throw InternalError("simpleRingsRegion: hole without an outer ring");
    }
    Path path = simpleRingPath(rings[std::size_t(r)], ring.lowest, hole, frame);
    if (path.size() < 3) {
      ring.dropped = true;
      continue;
    }
    if (!hole) {
      Polygon polygon;
      polygon.outer = std::move(path);
      if (owner >= 0) {
        polygon.parent = rn[std::size_t(rn[std::size_t(owner)].resultAround)].polygon;
        polygon.parentHole = rn[std::size_t(owner)].hole;
      }
      ring.polygon = int(result.polygons.size());
      result.polygons.push_back(std::move(polygon));
    } else {
      Polygon& outer = result.polygons[std::size_t(rn[std::size_t(owner)].polygon)];
      ring.hole = int(outer.holes.size());
      outer.holes.push_back(std::move(path));
    }
  }
  return result;
}

PolygonSet simpleRingRegion(const std::vector<IPoint>& ring, FillRule rule, const Grid& grid) {
  const LowestVertex lowest = lowestVertex(ring);
  PolygonSet result;
  if (!isFilled(rule, lowest.ccw ? 1 : -1)) return result;
  Path path = simpleRingPath(ring, lowest, /*hole=*/false, OutputFrame(grid));
  if (path.size() < 3) return result;  // distinct grid points that round to fewer doubles
  result.polygons.emplace_back().outer = std::move(path);
  return result;
}

}  // namespace roiclip::detail
