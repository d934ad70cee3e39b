// SPDX-License-Identifier: MIT
// Stage 0, pinches: rings that touch themselves or each other only at shared vertices, made
// ready for the sweep-free paths.
//
// A pixel contour often meets itself or a neighbour at a pixel corner (two pixels touching
// diagonally, 8-connectivity): the same vertex is visited twice, and the simple-ring test
// rejects the set, so it went through the sweep, at several times the cost per vertex. Here a
// vertex visited exactly twice (a pinch) is prepared instead:
//  - A ring visiting a vertex twice is split there (the stack method of tracing: pop the loop
//    between the two visits), so each ring visits each vertex once. The edges, and so every
//    winding number, stay the same; the general path returns such rings split the same way.
//  - At each pinch the two passes (in-edge and out-edge of each of the two rings) must touch
//    without crossing: their four edges point four ways, and the other pass's two edges lie in
//    the same sector between one pass's edges. One pass's free sector (the one holding neither
//    edge of the other) is convex (under a half turn); that pass gets its corner cut off: v is
//    replaced by the grid points one primitive step from v along its two edges (no grid point
//    lies between). The other pass keeps v.
//  - The separated rings are then asked to the simple-ring test. They are pairwise disjoint and
//    simple only if the original rings meet nowhere but at the pinches, where they touch:
//    every vertex (v included, kept by the other pass) and every edge outside the cut corners is
//    still there, and the cut corner holds nothing. That last part needs the lattice: every
//    vertex is a multiple of 2^k (a fitted grid's units have their low bits zero), so an edge
//    that does not pass through v lies at least 2^2k / |edge| from it, and the corner cut
//    reaches at most one step from v; the stage asks that a step be shorter than that bound
//    for the diagonal of the set's box (no edge is longer), and than 2^(k-1) (cut corners of
//    two pinches stay apart). An edge that passes through v touches the kept pass.
//  - The nesting of the separated rings is the nesting of the rings (the corners are small and
//    hold nothing), so the chain sweep's nesting serves the rings themselves.
//  - The rings are the result's rings only as stages 1 to 4 would split them (pinchesKeepRings()):
//    the pinches between the rings of one face (an outer ring and its holes) must join them in a
//    forest. A hole touching its outer ring at two pixel corners cuts the face in two.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <optional>
#include <vector>

#include <boost/pending/disjoint_sets.hpp>

#include "pipeline.hpp"
#include "workspace.hpp"

namespace roiclip::detail {
namespace {

// Fewer common low zero bits than this: no pinch is separated (a step may then come near
// another edge). Pixel coordinates on a fitted grid have about 20.
constexpr int kMinLowZeroBits = 12;

using Visit = PinchedRings::Visit;

// The edges of a visit's ring at its vertex, as directions from it: to the vertex before and
// to the one after.
void edgesAt(const Rings& rings, const Visit& at, IPoint& in, IPoint& on) {
  const std::vector<IPoint>& ring = rings[std::size_t(at.ring)];
  const std::size_t n = ring.size(), i = std::size_t(at.index);
  in = minus(ring[(i + n - 1) % n], ring[i]);
  on = minus(ring[(i + 1) % n], ring[i]);
}

// Whether four edges at a vertex point four ways (no two overlap).
bool fourWays(IPoint a, IPoint b, IPoint c, IPoint d) {
  const IPoint dirs[4] = {a, b, c, d};
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j) {
      if (sameDirection(dirs[i], dirs[j])) return false;
    }
  }
  return true;
}

// The points visited twice, as consecutive pairs of visits, in ring order of their second
// visit (an open-addressing hash table over the vertices, whose low `k` bits are zero). False
// when a point is visited three times or more or two edges at a point leave the same way (both
// set `overlapping`: cancelOverlaps() may take the set), or two rings cross at one. A slot holds
// a point's first visit (ring in the high half, index in the low one), kTwice once it has a
// second; all ones when empty.
bool visitsTwice(const Rings& rings, int k, std::vector<std::uint64_t>& table,
                 std::vector<Visit>& twice, bool& overlapping) {
  constexpr std::uint64_t kEmpty = ~std::uint64_t{0}, kTwice = std::uint64_t{1} << 62;
  twice.clear();
  std::size_t count = 0;
  for (const std::vector<IPoint>& ring : rings) count += ring.size();
  const int bits = tableBits(count);
  table.assign(std::size_t{1} << bits, kEmpty);
  const std::size_t mask = (std::size_t{1} << bits) - 1;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const std::vector<IPoint>& ring = rings[r];
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const IPoint p = ring[i];
      std::size_t at = std::size_t(pointHash(p, k) >> (64 - bits));
      Visit first{};
      for (;; at = (at + 1) & mask) {
        if (table[at] == kEmpty) break;
        first = {int((table[at] & ~kTwice) >> 32), int(std::uint32_t(table[at]))};
        if (rings[std::size_t(first.ring)][std::size_t(first.index)] == p) break;
      }
      std::uint64_t& slot = table[at];
      if (slot == kEmpty) {
        slot = std::uint64_t(r) << 32 | std::uint64_t(i);
        continue;
      }
      if ((slot & kTwice) != 0) {
        overlapping = true;  // as at a wall's junction; cancelOverlaps() may take it
        return false;
      }
      // Two visits: their four edges point four ways, and two rings touch without crossing
      // (checked here, so that most sets that fail stop at their first bad vertex).
      const Visit visit{int(r), int(i)};
      IPoint a, b, c, d;
      edgesAt(rings, first, a, b);
      edgesAt(rings, visit, c, d);
      if (!fourWays(a, b, c, d)) {
        overlapping = true;
        return false;
      }
      if (visit.ring != first.ring && inSectorCcw(a, b, c) != inSectorCcw(a, b, d)) return false;
      twice.push_back(first);
      twice.push_back(visit);
      slot |= kTwice;
    }
  }
  return true;
}

// Splits ring `ring` at the vertices it visits twice (p.partner[i]: the other visit of vertex
// i, or -1) into p.split, the stack method: a vertex seen again while its first visit is on the
// stack pops the loop between them as a ring. The two visits of a vertex so land in two loops.
// moved[i]: where vertex i went. False when a loop has fewer than three vertices.
bool splitAtSelfPinches(const std::vector<IPoint>& ring, PinchedRings& p, Visit* moved) {
  const int n = int(ring.size());
  std::vector<int>& stack = p.stack;
  std::vector<int>& position = p.position;
  stack.clear();
  position.assign(std::size_t(n), -1);
  const auto emit = [&](std::size_t from) {
    if (stack.size() - from < 3) return false;
    std::vector<IPoint>& loop = p.split.add();
    const int at = int(p.split.rings.size()) - 1;
    loop.reserve(stack.size() - from);
    for (std::size_t s = from; s < stack.size(); ++s) {
      moved[stack[s]] = {at, int(loop.size())};
      loop.push_back(ring[std::size_t(stack[s])]);
      position[std::size_t(stack[s])] = -1;
    }
    stack.resize(from);
    return true;
  };
  for (int t = 0; t < n; ++t) {
    const int i = p.partner[std::size_t(t)];
    if (i >= 0 && i < t && position[std::size_t(i)] >= 0) {
      if (!emit(std::size_t(position[std::size_t(i)]))) return false;
    }
    position[std::size_t(t)] = int(stack.size());
    stack.push_back(t);
  }
  return emit(0);
}

// The grid step from the origin towards d: d divided by the gcd of its components.
IPoint primitiveStep(IPoint d) {
  const std::int64_t g = std::gcd(d.x < 0 ? -d.x : d.x, d.y < 0 ? -d.y : d.y);
  return {d.x / g, d.y / g};
}

}  // namespace

Pinches separatePinches(const Rings& rings, PinchedRings& out) {
  out.rings = &rings;
  out.split.clear();
  out.separated.clear();
  out.pinches.clear();
  std::uint64_t bits = 0;
  IPoint low = rings.empty() || rings[0].empty() ? IPoint{} : rings[0][0], high = low;
  for (const std::vector<IPoint>& ring : rings) {
    if (ring.size() < 3) return Pinches::refused;
    for (const IPoint p : ring) {
      bits |= std::uint64_t(p.x) | std::uint64_t(p.y);
      low = {std::min(low.x, p.x), std::min(low.y, p.y)};
      high = {std::max(high.x, p.x), std::max(high.y, p.y)};
    }
  }
  // Every edge lies in the box: at most its diagonal long.
  const double w = double(high.x - low.x), h = double(high.y - low.y);
  const double longest = w * w + h * h;
  if (bits == 0) return Pinches::none;
  const int k = __builtin_ctzll(bits);
  if (k < kMinLowZeroBits) return Pinches::none;
  std::vector<Visit>& twice = out.twice;
  bool overlapping = false;
  if (!visitsTwice(rings, k, out.table, twice, overlapping)) {
    return overlapping ? Pinches::overlapping : Pinches::refused;
  }
  if (twice.empty()) return Pinches::none;

  // Each ring visiting a vertex twice, split there.
  std::vector<char>& selfPinched = out.selfPinched;
  selfPinched.assign(rings.size(), 0);
  bool anySelf = false;
  for (std::size_t t = 0; t < twice.size(); t += 2) {
    if (twice[t].ring == twice[t + 1].ring) {
      selfPinched[std::size_t(twice[t].ring)] = 1;
      anySelf = true;
    }
  }
  if (anySelf) {
    // Each vertex's place in the split rings (flat by ring: base[r] + index), and the pairs of
    // visits moved there, not found again: the split keeps the points, their number of visits
    // and the directions of the edges at each, so visitsTwice()'s other findings stand (a
    // crossing is found at the cut below). The earlier visit stays first: the rings are split in
    // order, and the loop holding a vertex's first visit is emitted before the ring holding its
    // second. (The pairs' order matters nowhere.)
    std::vector<std::size_t>& base = out.start;
    ringStarts(rings, base);
    std::vector<Visit>& moved = out.moved;
    moved.resize(base.back());
    for (std::size_t r = 0; r < rings.size(); ++r) {
      if (selfPinched[r] == 0) {
        const int at = int(out.split.rings.size());
        out.split.add().assign(rings[r].begin(), rings[r].end());
        for (std::size_t i = 0; i < rings[r].size(); ++i) moved[base[r] + i] = {at, int(i)};
        continue;
      }
      out.partner.assign(rings[r].size(), -1);
      for (std::size_t t = 0; t < twice.size(); t += 2) {
        if (twice[t].ring != int(r) || twice[t + 1].ring != int(r)) continue;
        out.partner[std::size_t(twice[t].index)] = twice[t + 1].index;
        out.partner[std::size_t(twice[t + 1].index)] = twice[t].index;
      }
      if (!splitAtSelfPinches(rings[r], out, moved.data() + base[r])) return Pinches::refused;
    }
    out.rings = &out.split.rings;
    for (Visit& visit : twice) {
      visit = moved[base[std::size_t(visit.ring)] + std::size_t(visit.index)];
    }
  }
  const Rings& split = *out.rings;

  // At each pinch, the pass whose corner is cut.
  std::vector<std::size_t>& start = out.start;
  ringStarts(split, start);
  std::vector<char>& cut = out.cut;
  cut.assign(start.back(), 0);
  const auto pointOf = [&](const Visit& at) {
    return split[std::size_t(at.ring)][std::size_t(at.index)];
  };
  // A step from v shorter than 2^(k-1), and than 2^2k / |longest edge| (with a margin for the
  // rounding of the doubles).
  const double reach = std::ldexp(1.0, 2 * k) / std::sqrt(longest) * 0.5;
  const double stepBound = std::min(reach, std::ldexp(1.0, k - 1));
  const auto shortStep = [&](IPoint d) {
    const IPoint s = primitiveStep(d);
    return std::sqrt(double(s.x) * double(s.x) + double(s.y) * double(s.y)) < stepBound;
  };
  for (std::size_t t = 0; t < twice.size(); t += 2) {
    const Visit& first = twice[t];
    const Visit& second = twice[t + 1];
    if (first.ring == second.ring) return Pinches::refused;
    IPoint a, b, c, d;
    edgesAt(split, first, a, b);
    edgesAt(split, second, c, d);
    // Touching, not crossing: c and d in one sector between a and b.
    const bool cInAB = inSectorCcw(a, b, c);
    if (cInAB != inSectorCcw(a, b, d)) return Pinches::refused;
    // Each pass's free sector: from in-edge to out-edge counter-clockwise, or the other one.
    const bool firstFreeAB = !cInAB;
    const bool secondFreeCD = !inSectorCcw(c, d, a);
    const auto convex = [](IPoint from, IPoint to) { return crossSign(from, to) > 0; };
    const bool cutFirst = firstFreeAB ? convex(a, b) : convex(b, a);
    const bool cutSecond = secondFreeCD ? convex(c, d) : convex(d, c);
    if (!cutFirst && !cutSecond) return Pinches::refused;
    const Visit& cutAt = cutFirst ? first : second;
    if (cutFirst ? !shortStep(a) || !shortStep(b) : !shortStep(c) || !shortStep(d)) {
      return Pinches::refused;
    }
    cut[start[std::size_t(cutAt.ring)] + std::size_t(cutAt.index)] = 1;
    out.pinches.push_back({pointOf(first), first.ring, second.ring, first.index, second.index});
  }

  // The separated rings: each cut vertex replaced by the grid points a step along its edges.
  for (std::size_t r = 0; r < split.size(); ++r) {
    const std::vector<IPoint>& ring = split[r];
    std::vector<IPoint>& separated = out.separated.add();
    const std::size_t n = ring.size();
    separated.reserve(n + out.pinches.size());  // one more point per cut vertex
    // The runs between cut vertices as they are (most rings have no cut vertex).
    const char* const cutOf = cut.data() + start[r];
    for (std::size_t from = 0; from < n;) {
      const std::size_t i = std::size_t(std::find(cutOf + from, cutOf + n, 1) - cutOf);
      separated.insert(separated.end(), ring.begin() + std::ptrdiff_t(from),
                       ring.begin() + std::ptrdiff_t(i));
      if (i == n) break;
      const IPoint v = ring[i];
      const IPoint in = primitiveStep(minus(ring[(i + n - 1) % n], v));
      const IPoint on = primitiveStep(minus(ring[(i + 1) % n], v));
      separated.push_back({v.x + in.x, v.y + in.y});
      separated.push_back({v.x + on.x, v.y + on.y});
      from = i + 1;
    }
  }
  return Pinches::separated;
}

namespace {

// The face of the region whose boundary a pinch joins two rings of (the index of its outer
// ring, -1 when it has none), or nullopt when it joins none: a ring bounds nothing (the vertex is
// on the region's boundary once), or the rings bound two faces (two outer rings side by side, an
// island in a hole).
std::optional<int> faceOf(const PinchedRings::Pinch& pinch,
                          const std::vector<RingNesting>& nesting) {
  const RingNesting& a = nesting[std::size_t(pinch.ring)];
  const RingNesting& b = nesting[std::size_t(pinch.other)];
  if (!a.inResult || !b.inResult) return std::nullopt;
  const int face = a.filledInside ? pinch.ring : a.resultAround;
  if (face != (b.filledInside ? pinch.other : b.resultAround)) return std::nullopt;
  return face;
}

// Into p.traced: the region's boundary as stages 1 to 4 trace it. Each ring that bounds the
// region is walked with the region on its left (so the traced rings' winding number is 1 in
// the region and 0 outside it, whatever the fill rule was); a ring that bounds nothing is left
// out. At a pinch joining two rings of one face, the two filled sectors are each bounded by an
// edge of both rings (the other ring lies in one's filled sector), and the trace arriving along
// one ring leaves along the other: the two visits swap their successors. The walks (closed,
// each through a vertex as often as it arrives there) are the traced rings; a walk through a
// vertex twice is split by separatePinches() afterwards, as tracing splits it. False when the
// face of a pinch has no outer ring.
bool traceFaces(const Rings& rings, const std::vector<PinchedRings::Pinch>& pinches,
                const std::vector<RingNesting>& nesting, PinchedRings& p) {
  std::vector<std::size_t>& start = p.start;
  ringStarts(rings, start);
  std::vector<int>& succ = p.partner;  // the next vertex along the trace (flat)
  succ.resize(start.back());
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const int n = int(rings[r].size()), f = int(start[r]);
    const bool forward = nesting[r].lowest.ccw == nesting[r].filledInside;
    for (int i = 0; i < n; ++i) {
      succ[std::size_t(f + i)] = f + (forward ? (i + 1) % n : (i + n - 1) % n);
    }
  }
  for (const PinchedRings::Pinch& pinch : pinches) {
    const std::optional<int> face = faceOf(pinch, nesting);
    if (!face) continue;
    if (*face < 0) return false;
    const std::size_t x = start[std::size_t(pinch.ring)] + std::size_t(pinch.index);
    const std::size_t y = start[std::size_t(pinch.other)] + std::size_t(pinch.otherIndex);
    std::swap(succ[x], succ[y]);
  }
  p.traced.clear();
  std::vector<char>& walked = p.cut;
  walked.assign(start.back(), 0);
  const auto pointAt = [&](std::size_t g) {
    const std::size_t r =
        std::size_t(std::upper_bound(start.begin(), start.end(), g) - start.begin()) - 1;
    return rings[r][g - start[r]];
  };
  for (std::size_t r = 0; r < rings.size(); ++r) {
    if (!nesting[r].inResult) continue;
    for (std::size_t g = start[r]; g < start[r + 1]; ++g) {
      if (walked[g] != 0) continue;
      std::vector<IPoint>& ring = p.traced.add();
      for (std::size_t e = g; walked[e] == 0; e = std::size_t(succ[e])) {
        walked[e] = 1;
        ring.push_back(pointAt(e));
      }
    }
  }
  return true;
}

// The rings in the order stages 1 to 4 emit them: by their smallest vertex, then, for two rings
// through a pinch there, by their reference pieces, the lower edge first (edges from the
// smallest vertex point right or straight up, and the two rings' edges there do not interleave:
// one's lie below the other's, or between them, the enclosing ring's lower edge lowest). The
// chain sweep reached them by their separated rings, where a ring cut at its smallest vertex
// starts a step to the right of it, after any ring whose smallest vertex lies straight above.
// A ring around another comes first in this order too, as nestedRingsRegion() needs.
void orderAsTraced(const Rings& rings, ChainScratch& scratch) {
  const auto lowestOf = [&](int r) {
    return rings[std::size_t(r)][scratch.nesting[std::size_t(r)].lowest.index];
  };
  const auto lowerEdge = [&](int r) {  // the clockwise one of the two: the out-edge at a left turn
    const std::vector<IPoint>& ring = rings[std::size_t(r)];
    const LowestVertex lowest = scratch.nesting[std::size_t(r)].lowest;
    const std::size_t n = ring.size(), i = lowest.index;
    return minus(ring[lowest.ccw ? (i + 1) % n : (i + n - 1) % n], ring[i]);
  };
  std::sort(scratch.reached.begin(), scratch.reached.end(), [&](int a, int b) {
    const IPoint p = lowestOf(a), q = lowestOf(b);
    if (p != q) return p < q;
    return crossSign(lowerEdge(a), lowerEdge(b)) > 0;
  });
}

}  // namespace

bool pinchesKeepRings(const std::vector<PinchedRings::Pinch>& pinches,
                      const std::vector<RingNesting>& nesting,
                      const std::vector<char>* joinedInFace) {
  // Nodes: the rings, then one per face for the rings joined in it.
  const std::size_t n = nesting.size();
  boost::disjoint_sets_with_storage<> joined(2 * n);
  for (const PinchedRings::Pinch& pinch : pinches) {
    const std::optional<int> face = faceOf(pinch, nesting);
    if (!face) continue;
    if (*face < 0) return false;
    const auto node = [&](int r) {
      return joinedInFace != nullptr && (*joinedInFace)[std::size_t(r)] != 0
                 ? n + std::size_t(*face)
                 : std::size_t(r);
    };
    const std::size_t r = joined.find_set(node(pinch.ring)), q = joined.find_set(node(pinch.other));
    if (r == q) return false;  // a cycle
    joined.link(r, q);
  }
  return true;
}

bool pinchedRingsRegion(PinchedRings& pinched, FillRule rule, ChainScratch& scratch,
                        const Grid& grid, PolygonSet& out) {
  nestSimpleRings(*pinched.rings, rule, scratch);
  if (!pinchesKeepRings(pinched.pinches, scratch.nesting)) {
    // A cycle of pinches in a face (W5 scene_08: a hole touching its contour at three pixel
    // corners): the rings stages 1 to 4 trace there, which the stage must take as they are.
    if (!traceFaces(*pinched.rings, pinched.pinches, scratch.nesting, pinched)) return false;
    if (separatePinches(pinched.traced.rings, pinched) != Pinches::separated ||
        !ringsAreSimple(pinched.separated.rings, scratch)) {
      return false;
    }
    nestSimpleRings(*pinched.rings, FillRule::Positive, scratch);  // winding 1 in the region
    if (!pinchesKeepRings(pinched.pinches, scratch.nesting)) return false;
  }
  orderAsTraced(*pinched.rings, scratch);
  out = nestedRingsRegion(*pinched.rings, scratch, grid);
  return true;
}

}  // namespace roiclip::detail
