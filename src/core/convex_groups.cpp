// SPDX-License-Identifier: MIT
// The region-of-interest case for many contours: the subject's rings split into groups that the
// intersection with a strictly convex ring C can take one at a time.
//
// Within C, the winding number of the subject at a point is the sum over its rings. A ring that
// does not meet C (closed) adds the same winding number at every point of C: its winding number
// around a vertex of C, 0 unless it runs around C. A ring that meets C adds nothing outside its
// bounding box. So when the rings apart from C add 0 in total, and the boxes of the rings that
// meet C fall into groups whose boxes are apart (a gap on x or on y between any two groups), the
// region of the subject within C is the disjoint union of the regions of
// the groups within C, and no two of these touch. Each group is then intersected alone, by the
// sweep-free paths where they apply; the groups are found by recursive x-y cuts (as page
// segmentation cuts a page into blocks).
//
// Before any of that, placeBox() places a subject by its bounding box alone, from the unsnapped
// coordinates: outside C (nothing to snap) or strictly inside it.
#include <algorithm>
#include <optional>

#include "convex_sides.hpp"
#include "pipeline.hpp"

namespace roiclip::detail {
namespace {

// Whether the closed segment p -> q (p != q) meets the closed convex ring C: unless a side line
// of C or the line through p and q separates them (the separating-axis test, complete for two
// convex sets). `outside` holds, for p and q, the sides they lie strictly right of.
bool segmentMeetsConvex(IPoint p, IPoint q, unsigned outsideP, unsigned outsideQ,
                        const CcwRing& c) {
  if ((outsideP & outsideQ) != 0) return false;
  int sign = 0;
  for (int j = 0; j < c.size(); ++j) {
    const int o = orientInGrid(p, q, c[j]);
    if (o == 0 || (sign != 0 && o != sign)) return true;
    sign = o;
  }
  return false;
}

// Winding number of a ring around a grid point that is not on it.
int windingAround(const std::vector<IPoint>& ring, IPoint p) {
  int winding = 0;
  IPoint a = ring.back();  // each edge a -> b, from the closing one
  for (const IPoint b : ring) {
    if (a.y <= p.y) {
      if (b.y > p.y && orientInGrid(a, b, p) > 0) ++winding;  // upwards, p on its left
    } else if (b.y <= p.y && orientInGrid(a, b, p) < 0) {
      --winding;  // downwards, p on its right
    }
    a = b;
  }
  return winding;
}

enum class Place {
  Apart,   // does not meet C
  Inside,  // every vertex strictly inside C
  Meets,   // meets C otherwise
};

struct RingBox {
  std::int64_t lo[2], hi[2];
  int ring;
};

// Where a ring lies relative to C; for a ring apart from C, `winding` is its winding number
// around C; `inClosed` whether every vertex lies in C or on its boundary. kSides as
// SideLines::classify(). The corners of the ring's bounding box decide most rings: all four
// strictly inside C (convex) put every vertex there; all four strictly right of one side put
// every vertex there, and such a ring winds around no point of C. `known` tells which of these
// the ring got: inside by its box, or each vertex's masks written to `left` and `onLine`.
template <int kSides>
Place placeOf(const std::vector<IPoint>& ring, const RingBox& box, const SideLines& sides,
              const CcwRing& c, int& winding, bool& inClosed, unsigned* leftOut,
              unsigned* onLineOut, char& known) {
  winding = 0;
  inClosed = false;
  known = RingGroups::kNothing;
  if (ring.size() < 3) return Place::Apart;  // a point or a segment: it fills nothing
  const unsigned all = sides.all();
  // Not SideLines::placeBox(): a box in a side's closed outer half-plane may hold a ring on C's
  // boundary, whose inClosed its vertices tell below.
  const SideLines::BoxSides corners =
      sides.classifyBox<kSides>({box.lo[0], box.lo[1]}, {box.hi[0], box.hi[1]});
  if (corners.left == all) {
    inClosed = true;
    known = RingGroups::kInside;
    return Place::Inside;
  }
  if (corners.right != 0) return Place::Apart;
  known = RingGroups::kMasks;
  unsigned anyLeft = 0, allLeft = all, anyOut = 0;
  bool vertexInC = false, edgeMeets = false;
  // The sides each vertex lies strictly right of; an edge between two vertices outside C meets
  // it only if no one side has both ends right of it (tested as the vertices come, until a
  // vertex in C or a meeting edge has decided).
  unsigned firstOut = 0, lastOut = 0;
  IPoint last{};
  const auto edge = [&](IPoint p, unsigned outP, IPoint q, unsigned outQ) {
    if (!edgeMeets && !vertexInC && outP != 0 && outQ != 0 && (outP & outQ) == 0) {
      edgeMeets = segmentMeetsConvex(p, q, outP, outQ, c);
    }
  };
  // Every vertex lies strictly left of the sides that every corner of the ring's box lies
  // strictly left of (a half-plane is convex): only the other sides are asked per vertex.
  const SideLines::OtherSides asked = sides.otherThan(corners.left);
  const auto classify = [&](IPoint p, std::int64_t& reach) { return asked.classify(p, reach); };
  classifyPath(ring.data(), ring.size(), classify, [&](std::size_t k, SideLines::Masks m) {
    const IPoint p = ring[k];
    const unsigned left = m.left, zeros = m.zeros;
    leftOut[k] = left;
    onLineOut[k] = zeros;
    anyLeft |= left;
    allLeft &= left;
    const unsigned out = all & ~(left | zeros);
    anyOut |= out;
    vertexInC = vertexInC || out == 0;
    if (k == 0) {
      firstOut = out;
    } else {
      edge(last, lastOut, p, out);
    }
    last = p;
    lastOut = out;
  });
  edge(last, lastOut, ring[0], firstOut);
  inClosed = anyOut == 0;
  // In the closed outer half-plane of one side: at most on C's boundary, around no point of C.
  if (anyLeft != all) return Place::Apart;
  if (allLeft == all) return Place::Inside;
  // A vertex in C, or every vertex outside C and an edge crossing it.
  if (vertexInC || edgeMeets) return Place::Meets;
  winding = windingAround(ring, c[0]);
  return Place::Apart;
}

// Splits boxes[begin, end) into groups by x-y cuts: sorted on one axis, a cut falls wherever no
// box reaches past it; each part is cut again on the other axis, until neither axis cuts.
// Parts deeper than kMaxDepth stay whole (a staircase of boxes would cut one box a level).
void cutIntoGroups(std::vector<RingBox>& boxes, RingGroups& out) {
  constexpr int kMaxDepth = 48;
  struct Part {
    std::size_t begin, end;
    int axis;
    bool otherFailed;  // the other axis cut this part into nothing
    int depth;
  };
  std::vector<Part> stack{{0, boxes.size(), 0, false, 0}};
  while (!stack.empty()) {
    const Part part = stack.back();
    stack.pop_back();
    const auto first = boxes.begin() + std::ptrdiff_t(part.begin);
    const auto last = boxes.begin() + std::ptrdiff_t(part.end);
    bool whole = part.end - part.begin == 1 || part.depth >= kMaxDepth;
    if (!whole) {
      const int axis = part.axis;
      std::sort(first, last, [axis](const RingBox& a, const RingBox& b) {
        return a.lo[axis] != b.lo[axis] ? a.lo[axis] < b.lo[axis] : a.ring < b.ring;
      });
      std::size_t from = part.begin;
      std::int64_t reach = boxes[from].hi[axis];
      const std::size_t stackBefore = stack.size();
      for (std::size_t i = part.begin + 1; i <= part.end; ++i) {
        if (i == part.end || boxes[i].lo[axis] > reach) {
          if (i < part.end || from > part.begin) {
            stack.push_back({from, i, 1 - axis, false, part.depth + 1});
          }
          from = i;
        }
        if (i < part.end) reach = std::max(reach, boxes[i].hi[axis]);
      }
      if (stack.size() == stackBefore) {  // no cut on this axis
        if (part.otherFailed) {
          whole = true;
        } else {
          stack.push_back({part.begin, part.end, 1 - axis, true, part.depth});
        }
      }
    }
    if (whole) {
      for (auto it = first; it != last; ++it) out.rings.push_back(it->ring);
      out.groupStart.push_back(out.rings.size());
    }
  }
}

}  // namespace

BoxPlace placeBox(const Box& box, const Grid& grid, const std::vector<IPoint>& convex,
                  int convexOrientation) {
  if (box.empty() || !box.finite || convex.size() > std::size_t(kMaxSides)) {
    return BoxPlace::Unknown;
  }
  const std::optional<std::int64_t> x0 = grid.toUnits(box.minX, grid.origin.x),
                                    x1 = grid.toUnits(box.maxX, grid.origin.x),
                                    y0 = grid.toUnits(box.minY, grid.origin.y),
                                    y1 = grid.toUnits(box.maxY, grid.origin.y);
  if (!x0 || !x1 || !y0 || !y1) return BoxPlace::Unknown;
  // Most subjects around a ROI lie apart from its box: decided before the side lines are made.
  IPoint lo = convex[0], hi = convex[0];
  for (const IPoint p : convex) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  if (boxesApart({*x0, *y0}, {*x1, *y1}, lo, hi)) return BoxPlace::Outside;
  const SideLines sides(convex, convexOrientation);
  return withSideCount(sides, [&](auto k) {
    return sides.placeBox<k()>(IPoint{*x0, *y0}, IPoint{*x1, *y1});
  });
}

BoxPlace placeBox(const Box& box, const Grid& grid, const SnappedOperand& clip) {
  return clip.convex != 0 ? placeBox(box, grid, clip.rings[0], clip.convex) : BoxPlace::Unknown;
}

bool groupRingsForConvex(const Rings& rings, const std::vector<IPoint>& convex,
                         int convexOrientation, RingGroups& out) {
  out.rings.clear();
  out.groupStart.assign(1, 0);
  out.apart = 0;
  if (convex.size() > std::size_t(kMaxSides)) return false;
  const SideLines sides(convex, convexOrientation);
  const CcwRing c{&convex, convexOrientation < 0};
  std::vector<RingBox> boxes;
  int windingAroundC = 0;
  // The side masks of every vertex the grouping classifies, kept for Weiler-Atherton.
  out.vertexStart.resize(rings.size() + 1);
  out.vertexStart[0] = 0;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    out.vertexStart[r + 1] = out.vertexStart[r] + rings[r].size();
  }
  // Without the zeros a vector would write first (1.5% of W5 scene_03 CHAIN_APPROX_SIMPLE).
  out.left.reset(new unsigned[out.vertexStart.back()]);
  out.onLine.reset(new unsigned[out.vertexStart.back()]);
  out.known.assign(rings.size(), RingGroups::kNothing);
  const auto place = [&](std::size_t r, const RingBox& box, int& winding, bool& inClosed) {
    return withSideCount(sides, [&](auto k) {
      return placeOf<k()>(rings[r], box, sides, c, winding, inClosed,
                          out.left.get() + out.vertexStart[r],
                          out.onLine.get() + out.vertexStart[r], out.known[r]);
    });
  };
  out.inClosed.assign(rings.size(), 0);
  for (std::size_t r = 0; r < rings.size(); ++r) {
    if (rings[r].empty()) {
      ++out.apart;
      continue;
    }
    RingBox box{{rings[r][0].x, rings[r][0].y}, {rings[r][0].x, rings[r][0].y}, int(r)};
    for (const IPoint p : rings[r]) {
      box.lo[0] = std::min(box.lo[0], p.x), box.hi[0] = std::max(box.hi[0], p.x);
      box.lo[1] = std::min(box.lo[1], p.y), box.hi[1] = std::max(box.hi[1], p.y);
    }
    int winding = 0;
    bool inClosed = false;
    const Place where = place(r, box, winding, inClosed);
    out.inClosed[r] = inClosed ? 1 : 0;
    if (where == Place::Apart) {
      windingAroundC += winding;
      ++out.apart;
      continue;
    }
    boxes.push_back(box);
  }
  if (windingAroundC != 0) return false;
  if (!boxes.empty()) cutIntoGroups(boxes, out);
  return true;
}

}  // namespace roiclip::detail
