// SPDX-License-Identifier: MIT
// Stage 0, the simple-ring test: whether one snapped ring is simple, and the region it bounds.
//
// Most contours a vision pipeline clips do not touch themselves. For those the sweep of stage 1
// finds nothing to split, yet it costs a tree step, a heap step and a piece per vertex. This
// stage asks first, with a Shamos-Hoey sweep over the ring's x-monotone chains: a ring splits
// where its edges turn from running right to running left or back into chains along which x
// never decreases. A vertical edge belongs to the chain of the edge before it, so a pixel
// contour's staircases, whose vertical steps run both up and down, stay whole: a contour has a
// chain pair per x extreme (W1-100k: 556 chains for 101k vertices, where chains increasing in
// (x, y) order were 18,952). The sweep line is vertical. It visits only the turning vertices,
// sorted up front (a radix sort of their keys); at one x, the pairs of chains starting there
// enter the status first (bottom to top), then the pairs ending there leave it. At an x a chain
// covers a point, or a segment where it has a vertical edge. Two chains next to each other in
// the status are tested lazily, when they stop being neighbours (a pair enters between them, or
// one of them ends): at each x where one of them has vertices since they became neighbours, up
// to the current x, its extent there must lie strictly below the other's (walk()). The gap
// between two chains is linear between those x, so they do not meet. Before the first contact
// (in x) the status is in order, and the two chains that meet there are neighbours just before
// it (Shamos and Hoey); their walk reaches it when they stop being neighbours, at or after it.
// For n vertices in c chains: the sort of the c turning vertices (linear, a radix sort, from
// 64), O(log c) per chain start (O(1) when it starts next to the last one started), and two
// orientations per vertex (one against each neighbouring chain); no arithmetic beyond exact
// int64 orientation (every point is a grid point). The test stops at the first contact it
// finds, and answers "not simple" wherever its invariants do not hold (the general path then
// runs): only a simple ring is ever called simple.
//
// Simple here means: the ring's vertices are distinct, consecutive edges meet only at their
// shared vertex and are not collinear (a straight-on vertex or a spike, which turnsOnce(), asked
// first, rejects; snapped rings have none), and no other two edges meet at all.
#include <algorithm>
#include <limits>
#include <utility>

#include <roiclip/error.hpp>

#include "output.hpp"
#include "pipeline.hpp"
#include "radix_sort.hpp"
#include "workspace.hpp"

namespace roiclip::detail {
namespace {

// A chain's cursor one vertex on; past the last vertex, `left` is -1.
inline ChainCursor advance(const ChainNode& c, ChainCursor k) {
  return k.left > 0 ? c.next(k) : ChainCursor{k.j, -1};
}

// Chain c's vertices at x from cursor k, which is at the first of them (one, or the two ends
// of a vertical edge): their lowest and highest y, and the cursor past them.
inline ChainCursor extentAt(const ChainNode& c, ChainCursor k, std::int64_t x, std::int64_t& low,
                            std::int64_t& high) {
  low = high = c.end(k).y;
  k = advance(c, k);
  if (k.left >= 0 && c.end(k).x == x) {
    low = std::min(low, c.end(k).y);
    high = std::max(high, c.end(k).y);
    k = advance(c, k);
  }
  return k;
}

// Where chain c lies at x = q.x, against q: -1 wholly below q, +1 wholly above it, 0 through q.
// Its cursor `at` moves on to its first vertex at or right of q.x (the sweep's x only grows).
// At that x the chain covers a vertex, or a vertical edge, or crosses it along an edge. A chain
// that does not reach q.x is not in the status there: 0, as for a contact.
inline int sideOf(const ChainNode& c, const IPoint& q) {
  while (c.end(c.at).x < q.x) {
    if (c.at.left == 0) return 0;
    c.at = c.next(c.at);
  }
  const IPoint v = c.end(c.at);
  if (v.x == q.x) {
    std::int64_t low = 0, high = 0;
    extentAt(c, c.at, q.x, low, high);
    return high < q.y ? -1 : low > q.y ? 1 : 0;
  }
  if (c.at.left == c.edges) return 0;  // the chain starts right of q
  const int o = orientInGrid(c.start(c.at), v, q);
  return o > 0 ? -1 : o < 0 ? 1 : 0;
}

// The status's search: a chain before point q when it lies wholly below q.
struct ChainBelowPoint {
  bool operator()(const ChainNode& c, const IPoint& q) const { return sideOf(c, q) < 0; }
  bool operator()(const IPoint& q, const ChainNode& c) const { return sideOf(c, q) > 0; }
};

// Moves cursor k of chain c past its vertices at x <= t.
inline void skipThrough(const ChainNode& c, ChainCursor& k, std::int64_t t) {
  while (k.left >= 0 && c.end(k).x <= t) k = advance(c, k);
}

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
      if (events[e - 1].key == events[e].key) return touch();
    }
    // The events at one x (one key's high half): the pairs starting there bottom to top, then
    // the pairs ending there. A chain that ends at x is still in the status while the pairs
    // starting at x are placed against what it covers there.
    for (std::size_t g = 0, h = 0; g < events.size(); g = h) {
      while (h < events.size() && (events[h].key >> 32) == (events[g].key >> 32)) ++h;
      for (std::size_t e = g; e < h; ++e) {
        const ChainEvent& x = events[e];
        if (startsAt(x) && !insertPair(x.chain, x.pair, frame_.point(x.key))) return false;
      }
      for (std::size_t e = g; e < h; ++e) {
        const ChainEvent& x = events[e];
        if (!startsAt(x) && !removePair(x.chain, x.pair, frame_.point(x.key))) return false;
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

  // Whether an event's two chains start at its vertex (a leftmost turn), rather than end there.
  // Chain `chain` shares its last vertex in ring order with `pair`: its leftmost when it runs
  // backward through the ring.
  [[nodiscard]] bool startsAt(const ChainEvent& e) const {
    return s_.chains[std::size_t(e.chain)].step < 0;
  }

  // The ring's maximal runs of edges going right (x grows) or going left, a vertical edge in the
  // run of the edge before it, each as a chain from its leftmost vertex, and the events of the
  // turning vertices: the chains of a ring are made in ring order, so chain k and the next one
  // meet at chain k's last vertex in ring order, a turning vertex where both start (chain k runs
  // left) or both end. Of the two chains at a turning vertex at most one has a vertical edge
  // there (two consecutive edges are not collinear).
  bool splitChains() {
    std::vector<ChainNode>& chains = s_.chains;
    std::vector<ChainEvent>& events = s_.events;
    chains.clear();
    events.clear();
    // The x direction of edge i -> i + 1: +1, -1, or 0 for a vertical edge.
    const auto direction = [](const IPoint* points, int n, int i) {
      const std::int64_t dx = points[after(n, i, 1)].x - points[i].x;
      return int(dx > 0) - int(dx < 0);
    };
    // Sized up front. A large ring's chains are counted first: a comb of 10M vertices has 5M
    // chains, which growing the array would copy and fault in again (1.3 s of 3.8 s).
    std::size_t vertices = 0;
    for (std::size_t r = 0; r < count_; ++r) vertices += rings_[r].size();
    if (vertices >= kCountChainsFrom) {
      std::size_t turns = 0;
      for (std::size_t r = 0; r < count_; ++r) {
        const IPoint* const points = rings_[r].data();
        const int n = int(rings_[r].size());
        int run = 0;
        for (int i = 0; i < n; ++i) {
          const int d = direction(points, n, i);
          turns += std::size_t(d != 0 && d != run);
          run = d != 0 ? d : run;
        }
      }
      chains.reserve(turns + 1);
      events.reserve(turns + 1);
    }
    for (int r = 0; r < int(count_); ++r) {
      const IPoint* const points = rings_[std::size_t(r)].data();
      const int n = int(rings_[std::size_t(r)].size());
      if (n < 3) return false;
      // The run of the last edge that is not vertical, which the first edges continue when
      // they are vertical.
      int run = 0;
      for (int i = n - 1; i >= 0 && run == 0; --i) run = direction(points, n, i);
      if (run == 0) return false;
      // A turning vertex to begin at: the first vertex where the run changes.
      int begin = -1;
      for (int i = 0; i < n; ++i) {
        const int d = direction(points, n, i);
        if (d != 0 && d != run) {
          begin = i;
          break;
        }
        run = d != 0 ? d : run;
      }
      if (begin < 0) return false;  // no closed ring runs one way all the way round
      const int first = int(chains.size());
      for (int i = begin, done = 0; done < n;) {
        const int u = direction(points, n, i);  // a run's first edge is not vertical
        const int k = int(chains.size());
        int j = after(n, i, 1), edges = 1;
        // On along edges that keep x or move it the run's way (u); j is the run's last vertex.
        std::int64_t xj = points[j].x;
        for (++done; done < n; ++done, ++edges) {
          const int next = j + 1 == n ? 0 : j + 1;
          const std::int64_t x = points[next].x;
          if (u > 0 ? x < xj : x > xj) break;
          j = next;
          xj = x;
        }
        const bool last = done >= n;
        ChainNode& chain = chains.emplace_back();
        chain.ring = r;
        chain.points = points;
        chain.size = n;
        chain.step = u;
        chain.first = u > 0 ? i : j;
        chain.edges = edges;
        // Ring order: the previous chain shares vertex i, the next one vertex j.
        const int previous = k == first ? -1 : k - 1, next = last ? first : k + 1;
        (u > 0 ? chain.startPartner : chain.endPartner) = previous;
        (u > 0 ? chain.endPartner : chain.startPartner) = next;
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

  // A contact where the chains meet without crossing (ChainScratch::touched): false.
  bool touch() const {
    s_.touched = true;
    return false;
  }

  // Chains lo and hi (hi just above lo) have been neighbours since an x where they lay apart;
  // their cursors (lo's `up`, hi's `down`) are at their first vertices right of it. Their
  // vertices from there up to x = t are taken in x order. At each x where one of them has
  // vertices, its extent there (a vertex, or a vertical edge) must lie strictly below the
  // other's: the other's vertices there, or its edge across that x. Between two such x the gap
  // between the chains is linear, so they do not meet up to t. End partners meet at their
  // shared last vertex, at t: each reaches it from its own side. False at a contact.
  bool walk(ChainNode& lo, ChainNode& hi, std::int64_t t) const {
    ChainCursor& e = lo.up;
    ChainCursor& f = hi.down;
    for (;;) {
      if (e.left < 0 || f.left < 0) {  // a chain past its last vertex: nothing of it is left
        constexpr std::int64_t kNone = std::numeric_limits<std::int64_t>::max();
        return (e.left >= 0 ? lo.end(e).x : f.left >= 0 ? hi.end(f).x : kNone) > t;
      }
      // The cursors lie past both chains' first vertices (insertPair()), so each has an edge
      // ending at its cursor; the one with the smaller x crosses the other's vertex's x.
      const IPoint b = lo.end(e), d = hi.end(f);
      if (b.x < d.x) {
        if (b.x > t) return true;
        if (const int o = orientInGrid(hi.start(f), d, b); o >= 0) {
          return o == 0 && touch();  // b on or above hi's edge
        }
        e = advance(lo, e);
      } else if (d.x < b.x) {
        if (d.x > t) return true;
        if (const int o = orientInGrid(lo.start(e), b, d); o <= 0) {
          return o == 0 && touch();  // d on or below lo's edge
        }
        f = advance(hi, f);
      } else {  // both have vertices at this x: lo's highest must lie below hi's lowest
        if (b.x > t) return true;
        std::int64_t loLow = 0, loHigh = 0, hiLow = 0, hiHigh = 0;
        e = extentAt(lo, e, b.x, loLow, loHigh);
        f = extentAt(hi, f, b.x, hiLow, hiHigh);
        if (loHigh < hiLow) continue;
        // They share a point at this x (vertices, or a vertex on a vertical edge).
        return (loHigh == hiLow && e.left < 0 && f.left < 0 &&
                lo.endPartner == int(&hi - s_.chains.data())) ||
               touch();
      }
    }
  }

  // Two chains start at their shared (turning) vertex p.
  bool insertPair(int i, int j, const IPoint& p) {
    ChainNode* lo = &s_.chains[std::size_t(i)];
    ChainNode* hi = &s_.chains[std::size_t(j)];
    for (ChainNode* c : {lo, hi}) c->at = c->down = c->up = ChainCursor{c->first, c->edges};
    // What the pair covers at p.x: p, and the other end of a vertical first edge. The chain
    // going down from p lies below the other; else their first edges turn at p.
    const IPoint a = lo->end(lo->next(lo->at)), b = hi->end(hi->next(hi->at));
    std::int64_t low = p.y, high = p.y;
    if (a.x == p.x || b.x == p.x) {
      if (a.x == p.x && b.x == p.x) return touch();  // two vertical edges (turnsOnce() rejects)
      const IPoint v = a.x == p.x ? a : b;
      const ChainNode* vertical = a.x == p.x ? lo : hi;
      if ((v.y < p.y) != (vertical == lo)) std::swap(lo, hi);
      low = std::min(low, v.y);
      high = std::max(high, v.y);
    } else {
      const int turn = orientInGrid(p, a, b);
      if (turn == 0) return touch();  // overlapping first edges
      if (turn < 0) std::swap(lo, hi);
    }
    const IPoint bottom{p.x, low}, top{p.x, high};
    // The first chain that does not lie wholly below the pair's bottom.
    ChainNode* above = nullptr;
    Status::iterator at;
    if (!nearFinger(bottom, above)) {
      at = status_.lower_bound(bottom, ChainBelowPoint{});
      above = at == status_.end() ? nullptr : &*at;
    } else {
      at = above != nullptr ? status_.iterator_to(*above) : status_.end();
    }
    ChainNode* below = above != nullptr ? above->below : top_;
    // The pair's neighbours must lie wholly below and above what it covers at p.x; the two
    // stop being neighbours at p.x.
    if (above != nullptr) {
      if (const int side = sideOf(*above, top); side <= 0) return side == 0 && touch();
    }
    if (below != nullptr) {
      if (const int side = sideOf(*below, bottom); side >= 0) return side == 0 && touch();
    }
    if (below != nullptr && above != nullptr && !walk(*below, *above, p.x)) return false;
    // The new neighbours lie apart at p.x: each is tested from its first vertex right of it.
    if (below != nullptr) skipThrough(*below, below->up, p.x);
    if (above != nullptr) skipThrough(*above, above->down, p.x);
    for (ChainNode* c : {lo, hi}) {
      skipThrough(*c, c->down, p.x);
      skipThrough(*c, c->up, p.x);
    }
    status_.insert_before(at, *lo);
    status_.insert_before(at, *hi);
    finger_ = hi;
    lo->below = below;
    lo->above = hi;
    hi->below = lo;
    hi->above = above;
    if (below != nullptr) below->above = lo;
    (above != nullptr ? above->below : top_) = hi;
    // A ring's first pair of chains covers its smallest vertex: what lies below it there.
    if (below_ != nullptr && (*below_)[std::size_t(lo->ring)] == kNotReached) {
      (*below_)[std::size_t(lo->ring)] = below != nullptr ? int(below - s_.chains.data()) : -1;
      s_.reached.push_back(lo->ring);
    }
    return true;
  }

  // The first chain that does not lie wholly below q (null: none), when it lies within a few
  // steps of the last pair inserted (finger_) along the status: chains often start in order up
  // a side (a comb's teeth start up one line), and then the tree's search, a cache miss a level
  // on a large status, is not needed. False when it lies further.
  bool nearFinger(const IPoint& q, ChainNode*& above) const {
    constexpr int kSteps = 4;
    ChainNode* f = finger_;
    if (f == nullptr) return false;
    if (sideOf(*f, q) < 0) {  // up from the finger to the first that does not lie below q
      ChainNode* g = f->above;
      for (int k = 0; g != nullptr && sideOf(*g, q) < 0; ++k, g = g->above) {
        if (k == kSteps) return false;
      }
      above = g;
      return true;
    }
    for (int k = 0; f->below != nullptr && sideOf(*f->below, q) >= 0; ++k, f = f->below) {
      if (k == kSteps) return false;
    }
    above = f;
    return true;
  }

  // Two chains end at their shared (turning) vertex p: they leave the status, next to each
  // other, once the vertices of each neighbouring pair are tested up to p.x.
  bool removePair(int i, int j, const IPoint& p) {
    ChainNode* lo = &s_.chains[std::size_t(i)];
    ChainNode* hi = &s_.chains[std::size_t(j)];
    if (lo->above != hi) std::swap(lo, hi);
    if (lo->above != hi) return false;  // something passes between them into their end
    ChainNode* below = lo->below;
    ChainNode* above = hi->above;
    if (below != nullptr && !walk(*below, *lo, p.x)) return false;
    if (!walk(*lo, *hi, p.x)) return false;
    if (above != nullptr && !walk(*hi, *above, p.x)) return false;
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
  const IPoint* const p = ring.data();
  IPoint d{p[0].x - p[n - 1].x, p[0].y - p[n - 1].y};
  bool fromLower = inLowerHalfTurn(d);
  long long turns = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const IPoint b = p[i + 1 == n ? 0 : i + 1];
    const IPoint e{b.x - p[i].x, b.y - p[i].y};
    // The sign of d x e, exact for grid points (|differences| <= 2^31: products below 2^62).
    const std::int64_t l = d.x * e.y, r = d.y * e.x;
    if (l == r) return false;  // a spike or a straight-on vertex: not simple (see ringIsSimple())
    const bool toLower = inLowerHalfTurn(e);
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
  // t = n - 1 - k for an outer ring, and for a hole t = n - 2 - k, then n - 1 last: the ring
  // rotated, from one step (outer) or two (hole) before the smallest vertex in the filled-left
  // order, backwards through that order (down the stored order when `forward`).
  const std::size_t back = hole ? 2 : 1;
  const std::size_t s = forward ? (first + n - back) % n : (first + back) % n;
  if (frame.gridPointsExact()) {  // distinct vertices give distinct doubles: each is taken
    Path path;
    path.reserve(n);
    const auto put = [&](std::size_t i) { path.push_back(frame.point(ring[i])); };
    if (forward) {
      for (std::size_t i = s + 1; i-- > 0;) put(i);
      for (std::size_t i = n; i-- > s + 1;) put(i);
    } else {
      for (std::size_t i = s; i < n; ++i) put(i);
      for (std::size_t i = 0; i < s; ++i) put(i);
    }
    return path;
  }
  // outputRing() asks k = 0, 1, ... in turn: each index is a step on from the last.
  std::size_t i = s;
  return outputRing(n, [&](std::size_t) {
    const IPoint p = ring[i];
    i = forward ? (i == 0 ? n - 1 : i - 1) : (i + 1 == n ? 0 : i + 1);
    return frame.point(p);
  });
}

bool ringIsSimple(const std::vector<IPoint>& ring, ChainScratch& scratch, bool turnsChecked) {
  scratch.touched = false;
  return (turnsChecked || turnsOnce(ring)) && ChainSweep(&ring, 1, scratch, nullptr).run();
}

bool ringsAreSimple(const Rings& rings, ChainScratch& scratch, bool merged) {
  scratch.touched = false;
  for (const std::vector<IPoint>& ring : rings) {
    if (merged ? ring.size() < 3 : !turnsOnce(ring)) return false;
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
  return nestedRingsRegion(rings, scratch, grid);
}

PolygonSet nestedRingsRegion(const Rings& rings, ChainScratch& scratch, const Grid& grid) {
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
