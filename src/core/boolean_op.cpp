// SPDX-License-Identifier: MIT
// The pipeline, in the order of the paper: snap each operand once, take the convex fast path
// when it applies, split every self- and mutual intersection, classify by winding number under
// the fill rules, trace simple contours with the stack method, fix the orientation and nest
// holes in their outer rings.
#include <optional>

#include <roiclip/roiclip.hpp>

#include "convex_sides.hpp"
#include "pipeline.hpp"
#include "workspace.hpp"

namespace roiclip {
namespace detail {
namespace {

// Stages 1 to 4 on the workspace's edges (Workspace::edges and ::clipped).
PolygonSet resolve(const BooleanSpec& spec, const Grid& grid, Workspace& ws,
                   std::uint64_t* crossings = nullptr) {
  Arrangement arrangement = splitWorkspaceEdges(spec, ws);  // stages 1 and 2
  if (crossings != nullptr) *crossings = arrangement.crossings;
  Contours contours = traceContours(arrangement, ws.trace);
  // Nesting, where a large call peaks, reads only the vertices of the arrangement: the pieces
  // (64 bytes each; 34 MB on W3-1k-evenodd) and large tracing arrays are not held through it.
  keepIfSmall(arrangement.pieces, ws.arrangement.pieces);
  keepIfSmall(arrangement.sides, ws.arrangement.sides);
  ws.trace.releaseIfAbove(kKeptOutputBytes);
  PolygonSet result = buildNesting(arrangement, contours, grid, ws.nesting);
  keepIfSmall(arrangement.vertices, ws.arrangement.vertices);
  keepIfSmall(arrangement.lines, ws.arrangement.lines);
  keepIfSmall(arrangement.offGrid, ws.arrangement.offGrid);
  keepIfSmall(arrangement.openPieces, ws.arrangement.openPieces);
  keepIfSmall(contours.rings, ws.trace.contours.rings);
  keepIfSmall(contours.ringOfPiece, ws.trace.contours.ringOfPiece);
  keepIfSmall(contours.vertices, ws.trace.contours.vertices);
  return result;
}

// What the grouping knew of the vertices of `rings` (`known`, null: nothing), for the rings
// separatePinches() left in `p`: the same when it split none, else each vertex's masks where the
// split moved it (PinchedRings::moved; p.start holds the split rings' flat offsets). A split ring
// takes its vertices from one ring.
const KnownSides* knownAfterPinches(const Rings& rings, const KnownSides* known, PinchedRings& p) {
  if (known == nullptr || p.rings == &rings) return known;
  p.known.assign(p.rings->size(), KnownSides{});
  p.knownLeft.resize(p.start.back());
  p.knownOnLine.resize(p.start.back());
  std::size_t flat = 0;  // the flat index of ring r's first vertex
  for (std::size_t r = 0; r < rings.size(); flat += rings[r++].size()) {
    const KnownSides& from = known[r];
    if (!from.inside && from.left == nullptr) continue;
    for (std::size_t i = 0; i < rings[r].size(); ++i) {
      const PinchedRings::Visit to = p.moved[flat + i];
      KnownSides& k = p.known[std::size_t(to.ring)];
      if (from.inside) {
        k.inside = true;
        continue;
      }
      const std::size_t first = p.start[std::size_t(to.ring)];
      k.left = p.knownLeft.data() + first;
      k.onLine = p.knownOnLine.data() + first;
      p.knownLeft[first + std::size_t(to.index)] = from.left[i];
      p.knownOnLine[first + std::size_t(to.index)] = from.onLine[i];
    }
  }
  return p.known.data();
}

// The sweep-free paths for rings that touch only at vertices, as separatePinches() left them in
// ws.pinched: into `out`, or false. `inside`: ringsInsideConvex(rings). `known`, when not null:
// what the grouping knew of the vertices of `rings`, the rings given to the stage.
bool intersectPinched(FillRule rule, const SnappedOperand& convex, const Grid& grid, Workspace& ws,
                      bool inside, PolygonSet& out, const Rings& rings,
                      const KnownSides* known = nullptr) {
  PinchedRings& pinched = ws.pinched;
  if (!ringsAreSimple(pinched.separated.rings, ws.chains)) return false;
  if (inside) return pinchedRingsRegion(pinched, rule, ws.chains, grid, out);
  // The pairs touching strictly inside C; a pinch on C's boundary: the general path.
  const std::vector<IPoint>& c = convex.rings[0];
  if (c.size() > std::size_t(kMaxSides)) return false;
  const SideLines sides(c, convex.convex);
  std::vector<PinchedRings::Pinch>& touching = pinched.touching;
  touching.clear();
  for (const PinchedRings::Pinch& pinch : pinched.pinches) {
    const SideLines::Masks m = sides.classify(pinch.at);
    if ((m.left | m.zeros) != sides.all()) continue;  // outside C
    if (m.left != sides.all()) return false;          // on C's boundary
    touching.push_back(pinch);
  }
  return intersectSimpleRingsConvex(*pinched.rings, rule, c, convex.convex, grid, ws.chains,
                                    ws.weiler, out, knownAfterPinches(rings, known, pinched),
                                    &touching);
}

// Whether a ring has an edge along a side's line of C (m sides) and a vertex outside C, as
// `known` has their vertices: Weiler-Atherton refuses such a ring (appendCrossings()).
bool edgeAlongSide(const Rings& rings, const KnownSides* known, std::size_t m) {
  const unsigned all = (1U << m) - 1;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const unsigned *left = known[r].left, *on = known[r].onLine;
    if (on == nullptr) continue;
    const std::size_t n = rings[r].size();
    bool along = false;
    for (std::size_t i = 0, j = n - 1; i < n && !along; j = i++) along = (on[i] & on[j]) != 0;
    if (!along) continue;
    for (std::size_t i = 0; i < n; ++i) {
      if ((left[i] | on[i]) != all) return true;
    }
  }
  return false;
}

// The sweep-free paths for rings whose edges run along each other from shared vertices, on the
// rings with those edges cancelled (cancelOverlaps()): into `out`, or false.
bool intersectOverlapping(const Rings& rings, FillRule rule, const SnappedOperand& convex,
                          const Grid& grid, Workspace& ws, bool inside, PolygonSet& out) {
  bool touching = false;
  const Rings& reduced = ws.overlaps.reduced.rings;
  if (!cancelOverlaps(rings, ws.overlaps.reduced, touching, ws.overlaps)) return false;
  if (touching) {
    return separatePinches(reduced, ws.pinched) == Pinches::separated &&
           intersectPinched(rule, convex, grid, ws, inside, out, reduced);
  }
  if (!ringsAreSimple(reduced, ws.chains)) return false;
  if (inside) {
    out = simpleRingsRegion(reduced, rule, ws.chains, grid);
    return true;
  }
  return intersectSimpleRingsConvex(reduced, rule, convex.rings[0], convex.convex, grid, ws.chains,
                                    ws.weiler, out);
}

// Some rings AND one convex ring: the sweep-free paths where they apply, else the pre-clip and
// stages 1 to 4. `budget` is what is left of Limits::maxCrossings; the sweep's crossings are
// taken from it. `inClosed`, when known (groupRingsForConvex()), is ringsInsideConvex(rings);
// `known`, when not null, what the grouping learnt of each ring's vertices.
PolygonSet intersectRings(const Rings& rings, FillRule rule, const SnappedOperand& convex,
                          const Grid& grid, std::uint64_t& budget, Workspace& ws,
                          std::optional<bool> inClosed = std::nullopt,
                          const KnownSides* known = nullptr) {
  // One contour that does not touch itself (most contours): Weiler-Atherton, no sweep, when
  // its boundary crosses the convex ring's only transversally.
  PolygonSet direct;
  ws.chains.touched = false;  // intersectSimpleConvex() may refuse before its simple-ring test
  if (rings.size() == 1 &&
      intersectSimpleConvex(rings[0], rule, convex.rings[0], convex.convex, grid, ws.chains,
                            ws.weiler, direct, known != nullptr ? known[0] : KnownSides{})) {
    return direct;
  }
  // A single ring goes on only when the simple-ring test stopped where it touches itself (a
  // pixel contour meeting itself at a pixel corner, W5 scene_05's 123-vertex contour), not
  // where it crosses itself (W2's epitrochoid: separating the repeated vertices of every ring
  // that failed the test cost it 40% more instructions).
  if (rings.size() > 1 || ws.chains.touched) {
    const bool inside =
        inClosed ? *inClosed : ringsInsideConvex(rings, convex.rings[0], convex.convex);
    // Several contours touching nothing: all inside the convex ring (a contour with its holes
    // inside the ROI), the region they fill, nested by the chain sweep; else Weiler-Atherton
    // over the rings that bound it. (Looking for shared points first, by a hash of the points,
    // cost the sets that share none more than it saved the others: W5 scene_04 SIMPLE +9.1%,
    // scene_05 -1.6% with the pinch stage's hash at 9a8a147; a lean hash at d67cfb6, +4.3% and
    // -2.3%.)
    if (rings.size() > 1 && ringsAreSimple(rings, ws.chains, /*merged=*/true)) {
      if (inside) return simpleRingsRegion(rings, rule, ws.chains, grid);
      if (intersectSimpleRingsConvex(rings, rule, convex.rings[0], convex.convex, grid, ws.chains,
                                     ws.weiler, direct, known)) {
        return direct;
      }
    }
    // Rings touching only at vertices (pixel contours meeting at a pixel corner): the same paths
    // on the rings split there, when the rings with a corner cut off at each such vertex are
    // simple and apart. Edges running along each other from a shared point (a hole sharing a
    // one-pixel wall with its contour): the same paths once they are cancelled. A ring across C
    // with an edge along a side's line: Weiler-Atherton refuses it, whatever these stages make
    // of the rings (W5 scene_01's 400-vertex group). A single ring does not try the overlap
    // stage: the W5 contours that would (in scenes 01, 06 and 07) fail after it, at a vertex on
    // an edge of another part, so the attempt cost more than it saved.
    const std::size_t m = convex.rings[0].size();
    const bool alongSide = !inside && known != nullptr && m <= std::size_t(kMaxSides) &&
                           edgeAlongSide(rings, known, m);
    ws.generalPathUsed = true;  // the pinch and overlap stages' arrays are recycled with the
                                // general path's
    const Pinches pinches = alongSide ? Pinches::refused : separatePinches(rings, ws.pinched);
    if ((pinches == Pinches::separated &&
         intersectPinched(rule, convex, grid, ws, inside, direct, rings, known)) ||
        (pinches == Pinches::overlapping && rings.size() > 1 &&
         intersectOverlapping(rings, rule, convex, grid, ws, inside, direct))) {
      return direct;
    }
  }
  // The sweep-free attempts are done: their large arrays do not stay through the general path
  // (on a 1M-vertex contour the chains and crossings took 73 MB of its peak). Smaller ones are
  // kept for the next group of the call (freeing them at 4 KB cost W5 scene_08 2% more
  // instructions).
  const auto release = [](auto& v) { releaseEachAbove(kKeptOutputBytes, v); };
  ws.chains.forEach(release);
  ws.weiler.forEach(release);
  ws.pinched.forEach(release);
  ws.overlaps.forEach(release);
  BooleanSpec spec;
  spec.subjectRule = rule;
  spec.maxCrossings = budget;
  preclipConvex(rings, convex.rings[0], convex.convex, ws, ws.edges, ws.clipped, known);
  std::uint64_t found = 0;
  PolygonSet result = resolve(spec, grid, ws, &found);
  budget -= found;  // the sweep throws before it finds more than the budget
  return result;
}

// The results of groups whose regions do not touch (groupRingsForConvex()) as one set, the
// polygons ordered as stages 1 to 4 order them: by the lexicographically smallest vertex of the
// outer ring, a group's own order kept among equal ones.
PolygonSet mergeGroups(std::vector<PolygonSet>& parts) {
  if (parts.size() == 1) return std::move(parts[0]);
  struct Entry {
    Point key;
    std::size_t part, index;
  };
  std::vector<Entry> entries;
  std::vector<std::vector<int>> position(parts.size());
  for (std::size_t p = 0; p < parts.size(); ++p) {
    position[p].resize(parts[p].polygons.size());
    for (std::size_t i = 0; i < parts[p].polygons.size(); ++i) {
      const Path& outer = parts[p].polygons[i].outer;
      Point key = outer[0];
      for (const Point& q : outer) {
        if (q.x < key.x || (q.x == key.x && q.y < key.y)) key = q;
      }
      entries.push_back({key, p, i});
    }
  }
  std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return a.key.x != b.key.x ? a.key.x < b.key.x : a.key.y < b.key.y;
  });
  for (std::size_t k = 0; k < entries.size(); ++k) {
    position[entries[k].part][entries[k].index] = int(k);
  }
  PolygonSet result;
  result.polygons.reserve(entries.size());
  for (const Entry& e : entries) {
    Polygon& polygon = parts[e.part].polygons[e.index];
    if (polygon.parent >= 0) polygon.parent = position[e.part][std::size_t(polygon.parent)];
    result.polygons.push_back(std::move(polygon));
  }
  return result;
}

// Intersection with one convex ring. Many contours (all of an image's) are split first into
// groups that do not touch within the convex ring, each taking its own path: the sweep then runs
// only over the groups that need it.
// `lend`: other.rings itself when the caller lets the groups borrow its rings (moved out and
// back; when the call throws, the group's rings are lost with it), null when `other` may be
// shared (a prepared region): then each group's rings are copied.
PolygonSet intersectConvexRing(const SnappedOperand& other, const SnappedOperand& convex,
                               const Grid& grid, const Limits& limits, Workspace& ws,
                               BoxPlace otherPlace, Rings* lend) {
  if (!isFilled(convex.rule, convex.convex)) return {};
  // One simple contour strictly inside the ROI (its box is): the region it fills, as it is.
  if (otherPlace == BoxPlace::Inside && other.rings.size() == 1 && other.rings[0].size() >= 3 &&
      ringIsSimple(other.rings[0], ws.chains)) {
    return simpleRingRegion(other.rings[0], other.rule, grid);
  }
  std::uint64_t budget = limits.maxCrossings;
  RingGroups groups;
  // The grouping has seen every vertex: it tells whether a group lies in C (groupInClosed()).
  const bool grouped = other.rings.size() > 1 &&
                       groupRingsForConvex(other.rings, convex.rings[0], convex.convex, groups);
  if (grouped && (groups.count() > 1 || groups.apart > 0)) {
    std::vector<PolygonSet> parts;
    parts.reserve(groups.count());
    Rings group;
    std::vector<KnownSides> known;
    for (std::size_t g = 0; g < groups.count(); ++g) {
      const auto first = groups.rings.begin() + std::ptrdiff_t(groups.groupStart[g]);
      const auto last = groups.rings.begin() + std::ptrdiff_t(groups.groupStart[g + 1]);
      group.clear();
      known.clear();
      for (auto r = first; r != last; ++r) {
        if (lend != nullptr) {
          group.push_back(std::move((*lend)[std::size_t(*r)]));
        } else {
          group.push_back(other.rings[std::size_t(*r)]);
        }
        known.push_back(groups.sidesOf(std::size_t(*r)));
      }
      parts.push_back(intersectRings(group, other.rule, convex, grid, budget, ws,
                                     groups.groupInClosed(g), known.data()));
      for (auto r = first; lend != nullptr && r != last; ++r) {
        (*lend)[std::size_t(*r)] = std::move(group[std::size_t(r - first)]);
      }
    }
    return mergeGroups(parts);
  }
  // One group of every ring, or no grouping.
  if (grouped && groups.count() == 1) {
    std::vector<KnownSides> known(other.rings.size());
    for (std::size_t r = 0; r < known.size(); ++r) known[r] = groups.sidesOf(r);
    return intersectRings(other.rings, other.rule, convex, grid, budget, ws,
                          groups.groupInClosed(0), known.data());
  }
  return intersectRings(other.rings, other.rule, convex, grid, budget, ws);
}

// Stages 1 to 4 of the general path on snapped operands (`clip` null for simplify).
// The subject's rings are freed once its edges are made (they would add 16 bytes per vertex to
// the sweep's peak).
PolygonSet resolveGeneral(Rings& subject, const Rings* clip, const BooleanSpec& spec,
                          const Grid& grid, Workspace& ws) {
  ws.generalPathUsed = true;
  std::vector<InputEdge>& edges = ws.edges;
  edges.clear();
  appendRingEdges(subject, 0, edges);
  Rings().swap(subject);
  if (clip != nullptr) appendRingEdges(*clip, 1, edges);
  ws.clipped.clear();
  return resolve(spec, grid, ws);
}

}  // namespace

SnappedOperand snapOperand(const Paths& paths, int operand, FillRule rule, const Grid& grid,
                           bool findConvex, Workspace* workspace) {
  SnappedOperand out;
  if (workspace != nullptr) out.rings.swap(workspace->operandRings[std::size_t(operand)]);
  snapRingsInto(paths, operand, grid, out.rings);
  out.rule = rule;
  out.convex = findConvex && out.rings.size() == 1 ? convexOrientation(out.rings[0]) : 0;
  return out;
}

void giveBackRings(SnappedOperand& snapped, int operand, Workspace& workspace) {
  keepIfSmall(snapped.rings, workspace.operandRings[std::size_t(operand)]);
}

PolygonSet clipSnapped(ClipOp op, SnappedOperand& subject, const SnappedOperand& clip,
                       const Grid& grid, const Limits& limits, Workspace& ws,
                       BoxPlace subjectPlace) {
  if (op == ClipOp::Intersection) {
    // The region-of-interest case: a convex operand takes the linear pre-clip path.
    if (clip.convex != 0) {
      return intersectConvexRing(subject, clip, grid, limits, ws, subjectPlace, &subject.rings);
    }
    if (subject.convex != 0) {  // the clip may be shared (a prepared region)
      return intersectConvexRing(clip, subject, grid, limits, ws, BoxPlace::Unknown, nullptr);
    }
  }
  BooleanSpec spec;
  spec.maxCrossings = limits.maxCrossings;
  spec.binary = true;
  spec.op = op;
  spec.subjectRule = subject.rule;
  spec.clipRule = clip.rule;
  return resolveGeneral(subject.rings, &clip.rings, spec, grid, ws);
}

PolygonSet booleanGeneral(const Paths& subject, const Paths* clipPaths, const BooleanSpec& spec,
                          const Grid& grid) {
  Rings s = snapRings(subject, 0, grid);
  const Rings c = clipPaths != nullptr ? snapRings(*clipPaths, 1, grid) : Rings{};
  const WorkspaceLease ws;
  // One contour that does not touch itself (most contours) is its own region, and contours that
  // touch nothing nest by what lies below each: no sweep.
  if (clipPaths == nullptr && spec.keepBoundary && !s.empty()) {
    if (s.size() == 1 && ringIsSimple(s[0], ws->chains)) {
      return simpleRingRegion(s[0], spec.subjectRule, grid);
    }
    if (s.size() > 1 && ringsAreSimple(s, ws->chains, /*merged=*/true)) {
      return simpleRingsRegion(s, spec.subjectRule, ws->chains, grid);
    }
  }
  return resolveGeneral(s, clipPaths != nullptr ? &c : nullptr, spec, grid, *ws);
}

}  // namespace detail

void releaseThreadBuffers() { detail::releaseThreadWorkspace(); }

PolygonSet simplify(const Paths& paths, FillRule rule, const Options& options) {
  detail::BooleanSpec spec;
  spec.subjectRule = rule;
  spec.maxCrossings = options.limits.maxCrossings;
  return detail::booleanGeneral(paths, nullptr, spec, resolveGrid(options.grid, paths));
}

PolygonSet clip(ClipOp op, const Paths& subject, const Paths& clipPaths, FillRule subjectRule,
                FillRule clipRule, const Options& options) {
  detail::Box subjectBox;  // one grid for both operands, fitted to their box
  const Grid grid = detail::resolveGrid(options.grid, subject, clipPaths, subjectBox);
  const detail::WorkspaceLease ws;
  // Each operand is snapped and validated once, into the rings the last call left; an
  // intersection reads the clip first (its errors are reported first, as the ROI is usually the
  // clip).
  detail::SnappedOperand s, c;
  detail::BoxPlace place = detail::BoxPlace::Unknown;  // of the subject, for a convex clip
  if (op == ClipOp::Intersection) {
    c = detail::snapOperand(clipPaths, 1, clipRule, grid, true, &*ws);
    // A subject whose box lies outside a convex ROI (most contours of an image, for a tag's
    // ROI) leaves with nothing, unsnapped: its box has shown every vertex valid.
    place = detail::placeBox(subjectBox, grid, c);
    if (place == detail::BoxPlace::Outside) {
      detail::giveBackRings(c, 1, *ws);
      return {};
    }
    // With a convex clip the fast path never asks whether the subject is convex.
    s = detail::snapOperand(subject, 0, subjectRule, grid, c.convex == 0, &*ws);
  } else {
    s = detail::snapOperand(subject, 0, subjectRule, grid, true, &*ws);
    c = detail::snapOperand(clipPaths, 1, clipRule, grid, true, &*ws);
  }
  PolygonSet result = detail::clipSnapped(op, s, c, grid, options.limits, *ws, place);
  detail::giveBackRings(s, 0, *ws);
  detail::giveBackRings(c, 1, *ws);
  return result;
}

PolygonSet intersect(const Paths& subject, const Paths& clipPaths, FillRule rule,
                     const Options& options) {
  return clip(ClipOp::Intersection, subject, clipPaths, rule, rule, options);
}
PolygonSet unite(const Paths& subject, const Paths& clipPaths, FillRule rule,
                 const Options& options) {
  return clip(ClipOp::Union, subject, clipPaths, rule, rule, options);
}
PolygonSet subtract(const Paths& subject, const Paths& clipPaths, FillRule rule,
                    const Options& options) {
  return clip(ClipOp::Difference, subject, clipPaths, rule, rule, options);
}
PolygonSet symmetricDifference(const Paths& subject, const Paths& clipPaths, FillRule rule,
                               const Options& options) {
  return clip(ClipOp::Xor, subject, clipPaths, rule, rule, options);
}

}  // namespace roiclip
