// SPDX-License-Identifier: MIT
// Stage 0, overlaps: rings whose edges run along each other, as rings that meet only at
// vertices, with the same winding number everywhere off the overlaps.
//
// A pixel contour and its hole share the pixels of a one-pixel wall, and a contour runs back
// along a one-pixel line it traced out: their edges overlap in opposite directions, the pinch
// stage (pinches.cpp) refuses the set, and it went through the sweep. Here:
//  - Edges are grouped by their line (a hash of its direction, reduced, and its offset; axis and
//    diagonal directions, all that pixel chains have, need no gcd). On a line where edges
//    overlap, each is split at the ends of the others inside it: overlapping edges then overlap
//    as equal segments, whose ends are shared points.
//  - At each point several visits share (most are visited once), an edge and the same edge in
//    the other direction cancel: together they add nothing to any winding number. Two edges
//    along each other the same way are refused (the winding number changes by two across them),
//    as is a ring turning straight back at a vertex.
//  - Where an edge was cancelled, the edge that arrives is linked to the one that leaves the same
//    point without its in-edge; a point with two such arrivals is refused (which leaving edge
//    follows which would need the order around the point). Elsewhere each edge keeps its
//    successor.
//  - The walks are split where one comes back to a point (the stack method, as tracing splits
//    them), and a vertex where a ring now goes straight on is dropped, as stages 1 to 4 drop it;
//    one where another pass touches the point is refused (stages 1 to 4 keep it there).
// The rings may still touch at vertices, each other but not themselves; the pinch stage takes
// them from there.
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

#include "pipeline.hpp"
#include "workspace.hpp"

namespace roiclip::detail {
namespace {

using Line = OverlapScratch::Line;
using Span = OverlapScratch::Span;
using Split = OverlapScratch::Split;

Line lineOf(IPoint a, IPoint b) {
  IPoint d = minus(b, a);
  if (d.x < 0 || (d.x == 0 && d.y < 0)) d = {-d.x, -d.y};
  if (d.y == 0) {
    d = {1, 0};
  } else if (d.x == 0) {
    d = {0, 1};
  } else if (d.x == d.y || d.x == -d.y) {
    d = {1, d.y > 0 ? 1 : -1};
  } else {
    const std::int64_t g = std::gcd(d.x, d.y < 0 ? -d.y : d.y);
    d = {d.x / g, d.y / g};
  }
  return {d, d.x * a.y - d.y * a.x};
}
std::uint64_t hashOf(const Line& l) {
  const std::uint64_t h = std::uint64_t(l.u.x) * 0x9E3779B97F4A7C15ULL ^
                          std::uint64_t(l.u.y) * 0xC2B2AE3D27D4EB4FULL ^
                          std::uint64_t(l.offset) * 0x165667B19E3779F9ULL;
  return h ^ (h >> 31);
}

// The rings flat: each vertex's point, successor and predecessor; s.first holds the flat index
// of each ring's first vertex (and the total). False when every point is the origin.
bool flatten(const Rings& rings, OverlapScratch& s) {
  ringStarts(rings, s.first);
  const std::size_t count = s.first.back();
  s.points.resize(count);
  s.next.resize(count);
  s.prev.resize(count);
  std::uint64_t bits = 0;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const int f = int(s.first[r]), n = int(rings[r].size());
    for (int i = 0; i < n; ++i) {
      const IPoint p = rings[r][std::size_t(i)];
      s.points[std::size_t(f + i)] = p;
      s.next[std::size_t(f + i)] = i + 1 < n ? f + i + 1 : f;
      s.prev[std::size_t(f + i)] = i > 0 ? f + i - 1 : f + n - 1;
      bits |= std::uint64_t(p.x) | std::uint64_t(p.y);
    }
  }
  s.lowZeroBits = bits == 0 ? -1 : __builtin_ctzll(bits);
  return bits != 0;
}

// Into s.splits: where edges on one line overlap, each edge split at the ends of the others
// inside it (the rings as flatten() left them).
void splitOverlaps(OverlapScratch& s) {
  const std::size_t count = s.points.size();
  const int bits = tableBits(count);
  const std::size_t mask = (std::size_t{1} << bits) - 1;
  s.lineHead.assign(std::size_t{1} << bits, -1);
  s.nextOnLine.resize(count);
  s.lines.resize(count);
  s.sharedLines.clear();
  for (std::size_t e = 0; e < count; ++e) {
    const Line line = lineOf(s.points[e], s.points[std::size_t(s.next[e])]);
    s.lines[e] = line;
    std::size_t at = std::size_t(hashOf(line) >> (64 - bits));
    while (s.lineHead[at] >= 0 && !(s.lines[std::size_t(s.lineHead[at])] == line)) {
      at = (at + 1) & mask;
    }
    const int head = s.lineHead[at];
    if (head >= 0 && s.nextOnLine[std::size_t(head)] < 0) s.sharedLines.push_back(int(at));
    s.nextOnLine[e] = head;
    s.lineHead[at] = int(e);
  }
  s.splits.clear();
  for (const int slot : s.sharedLines) {
    const int head = s.lineHead[std::size_t(slot)];
    const IPoint u = s.lines[std::size_t(head)].u;
    const bool byX = u.x != 0;
    const auto along = [byX](IPoint p) { return byX ? p.x : p.y; };
    s.spans.clear();
    for (int e = head; e >= 0; e = s.nextOnLine[std::size_t(e)]) {
      const std::int64_t a = along(s.points[std::size_t(e)]);
      const std::int64_t b = along(s.points[std::size_t(s.next[std::size_t(e)])]);
      s.spans.push_back({std::min(a, b), std::max(a, b), e});
    }
    // Most shared lines hold two or three spans: an insertion sort by their low ends.
    for (std::size_t i = 1; i < s.spans.size(); ++i) {
      const Span span = s.spans[i];
      std::size_t j = i;
      for (; j > 0 && span.lo < s.spans[j - 1].lo; --j) s.spans[j] = s.spans[j - 1];
      s.spans[j] = span;
    }
    // Runs of spans that overlap (more than at an end): every end in a run is a stop.
    for (std::size_t i = 0; i < s.spans.size();) {
      std::size_t j = i + 1;
      std::int64_t reach = s.spans[i].hi;
      while (j < s.spans.size() && s.spans[j].lo < reach) reach = std::max(reach, s.spans[j++].hi);
      if (j - i > 1) {
        s.stops.clear();
        for (std::size_t k = i; k < j; ++k) {
          s.stops.push_back(s.spans[k].lo);
          s.stops.push_back(s.spans[k].hi);
        }
        std::sort(s.stops.begin(), s.stops.end());
        for (std::size_t k = i; k < j; ++k) {
          const Span& span = s.spans[k];
          const IPoint a = s.points[std::size_t(span.edge)];
          const bool up = along(a) == span.lo;
          for (auto it = std::upper_bound(s.stops.begin(), s.stops.end(), span.lo);
               it != s.stops.end() && *it < span.hi; ++it) {
            if (*(it - 1) == *it) continue;  // a stop twice
            // The grid point of the line there: whole steps of u from a.
            const std::int64_t steps = (*it - along(a)) / (byX ? u.x : u.y);
            s.splits.push_back(
                {span.edge, up ? *it : -*it, {a.x + steps * u.x, a.y + steps * u.y}});
          }
        }
      }
      i = j;
    }
  }
}

// s.split: the rings with s.splits inserted (each edge's in order along it).
void insertSplits(const Rings& rings, OverlapScratch& s) {
  std::sort(s.splits.begin(), s.splits.end(), [](const Split& a, const Split& b) {
    return a.edge != b.edge ? a.edge < b.edge : a.along < b.along;
  });
  s.split.clear();
  std::size_t k = 0;
  int edge = 0;  // flat index in `rings`
  for (std::size_t r = 0; r < rings.size(); ++r) {
    std::vector<IPoint>& ring = s.split.add();
    ring.reserve(rings[r].size() + 4);
    for (const IPoint p : rings[r]) {
      ring.push_back(p);
      for (; k < s.splits.size() && s.splits[k].edge == edge; ++k) ring.push_back(s.splits[k].at);
      ++edge;
    }
  }
}

// The visits that share a point linked (s.same, s.rep, s.sharedPoints), by a hash of the points
// flatten() left.
void linkVisits(OverlapScratch& s) {
  const std::size_t count = s.points.size();
  s.rep.resize(count);
  s.same.assign(count, -1);
  s.sharedPoints.clear();
  // Grid points share their low zero bits: shifted out, the hash spreads them.
  const int k = s.lowZeroBits;
  const int tb = tableBits(count);
  const std::size_t mask = (std::size_t{1} << tb) - 1;
  constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
  s.table.assign(std::size_t{1} << tb, kEmpty);
  for (std::size_t g = 0; g < count; ++g) {
    const IPoint p = s.points[g];
    std::size_t at = std::size_t(pointHash(p, k) >> (64 - tb));
    while (s.table[at] != kEmpty && s.points[std::size_t(s.table[at])] != p) at = (at + 1) & mask;
    if (s.table[at] == kEmpty) {
      s.table[at] = g;
      s.rep[g] = int(g);
      continue;
    }
    const std::size_t f = std::size_t(s.table[at]);
    s.rep[g] = int(f);
    if (s.same[f] < 0) {
      s.sharedPoints.push_back(int(f));
      s.same[f] = int(g);
      s.same[g] = int(f);
    } else {
      s.same[g] = s.same[f];
      s.same[f] = int(g);
    }
  }
}

}  // namespace

bool cancelOverlaps(const Rings& input, KeptRings& out, bool& touching, OverlapScratch& s) {
  out.clear();
  touching = false;
  if (!flatten(input, s)) return false;
  splitOverlaps(s);
  if (!s.splits.empty()) {
    insertSplits(input, s);
    flatten(s.split.rings, s);
  }
  linkVisits(s);
  const std::size_t count = s.points.size();
  const auto outEdge = [&](int g) {
    return minus(s.points[std::size_t(s.next[std::size_t(g)])], s.points[std::size_t(g)]);
  };
  const auto inEdge = [&](int g) {
    return minus(s.points[std::size_t(s.prev[std::size_t(g)])], s.points[std::size_t(g)]);
  };

  // Equal edges in opposite directions cancel (by edge: its first vertex).
  s.cancelled.assign(count, 0);
  bool any = false;
  for (const int f : s.sharedPoints) {
    int x = f;
    do {
      const IPoint xo = outEdge(x), xi = inEdge(x);
      if (sameDirection(xo, xi)) return false;  // straight back along itself
      for (int y = s.same[std::size_t(x)]; y != f; y = s.same[std::size_t(y)]) {
        const IPoint yo = outEdge(y), yi = inEdge(y);
        if (sameDirection(xo, yo) || sameDirection(xi, yi))
          return false;  // along each other, one way
        // x's out-edge back along y's in-edge, and y's out-edge back along x's in-edge.
        for (const auto& [a, b] : {std::pair{x, y}, std::pair{y, x}}) {
          const IPoint ao = a == x ? xo : yo, bi = a == x ? yi : xi;
          if (!sameDirection(ao, bi)) continue;
          if (ao != bi) return false;  // cannot happen after the split
          s.cancelled[std::size_t(a)] = s.cancelled[std::size_t(s.prev[std::size_t(b)])] = 1;
          any = true;
        }
      }
      x = s.same[std::size_t(x)];
    } while (x != f);
  }
  if (!any) return false;

  // Each kept edge's successor: the edge after it in its ring, or where that one is cancelled,
  // the kept edge leaving the point whose in-edge is cancelled (one only).
  s.succ.assign(count, -1);
  s.claimed.assign(count, 0);
  for (std::size_t e = 0; e < count; ++e) {
    if (s.cancelled[e] != 0) continue;
    const int t = s.next[e];
    if (s.cancelled[std::size_t(t)] == 0) {
      s.succ[e] = t;
      continue;
    }
    for (int z = s.same[std::size_t(t)]; z >= 0 && z != t; z = s.same[std::size_t(z)]) {
      if (s.cancelled[std::size_t(z)] != 0 ||
          s.cancelled[std::size_t(s.prev[std::size_t(z)])] == 0) {
        continue;
      }
      if (s.succ[e] >= 0 || s.claimed[std::size_t(z)] != 0) return false;  // several to pair
      s.succ[e] = z;
      s.claimed[std::size_t(z)] = 1;
    }
    if (s.succ[e] < 0) return false;
  }

  // Passes through the point of visit g: its visits whose out-edge is kept.
  const auto passes = [&](int g) {
    int n = 0, z = g;
    do {
      n += s.cancelled[std::size_t(z)] == 0 ? 1 : 0;
      z = s.same[std::size_t(z)];
    } while (z >= 0 && z != g);
    return n;
  };
  for (const int f : s.sharedPoints) touching = touching || passes(f) > 1;

  // The walks, split where one comes back to a point, straight-on vertices dropped.
  s.walked.assign(count, 0);
  s.stack.clear();
  s.onStack.assign(count, -1);
  const auto emit = [&](std::size_t from) {
    std::vector<IPoint>& ring = out.add();
    const std::size_t n = s.stack.size() - from;
    ring.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      const int e = s.stack[from + i];
      const int before = s.stack[from + (i == 0 ? n : i) - 1];
      s.onStack[std::size_t(s.rep[std::size_t(e)])] = -1;
      const IPoint v = s.points[std::size_t(e)];
      const IPoint din = minus(v, s.points[std::size_t(before)]);
      const IPoint dout = outEdge(e);
      if (crossSign(din, dout) == 0) {
        if (!sameDirection(din, dout)) return false;                     // back along itself
        if (s.same[std::size_t(e)] >= 0 && passes(e) > 1) return false;  // straight through a touch
        continue;
      }
      ring.push_back(v);
    }
    s.stack.resize(from);
    return ring.size() >= 3;
  };
  for (std::size_t start = 0; start < count; ++start) {
    if (s.cancelled[start] != 0 || s.walked[start] != 0) continue;
    for (int e = int(start); s.walked[std::size_t(e)] == 0; e = s.succ[std::size_t(e)]) {
      s.walked[std::size_t(e)] = 1;
      const std::size_t at = std::size_t(s.rep[std::size_t(e)]);
      if (s.same[std::size_t(e)] >= 0 && s.onStack[at] >= 0 && !emit(std::size_t(s.onStack[at]))) {
        return false;
      }
      s.onStack[at] = int(s.stack.size());
      s.stack.push_back(e);
    }
    if (!emit(0)) return false;
  }
  return !out.rings.empty();
}

}  // namespace roiclip::detail
