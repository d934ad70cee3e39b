// SPDX-License-Identifier: MIT
// The convex fast path: an exact Sutherland-Hodgman pre-clip of the subject against a convex
// clip ring (the quad through four tags is the common ROI).
//
// Clipping a closed path against a half-plane replaces each run outside by the stretch of the
// boundary line between where the run leaves and re-enters. Inside the half-plane no point is
// crossed by that replacement, so every winding number there is unchanged; outside it the new
// path winds 0 times around every point. Doing this for each half-plane of a convex ring C
// leaves paths inside C whose winding numbers equal the subject's in C and 0 elsewhere, so
// resolving them with the subject's fill rule gives subject AND C. Every vertex made here is the
// crossing of two integer segments and every new edge lies on an integer segment (a subject
// edge or a side of C), so the sweep handles the result exactly. Cost: O(n * c) for n subject
// edges and c sides of C; the sweep then only sees what lies inside C.
#include <algorithm>

#include <roiclip/error.hpp>

#include "pipeline.hpp"
#include "workspace.hpp"

namespace roiclip::detail {
namespace {

using Vertex = ClipVertex;

XPoint crossing(const Vertex& from, IPoint hA, IPoint hB) {
  XPoint x;
  if (!lineIntersection(from.lineA, from.lineB, hA, hB, x)) {
    throw InternalError("preclipConvex: parallel lines have no crossing");
  }
  return x;
}

// One Sutherland-Hodgman step: keep the part of the closed path on the left of hA -> hB
// (points on the line count as inside). Writes into `out` (cleared first).
void clipHalfPlane(const std::vector<Vertex>& in, IPoint hA, IPoint hB, std::vector<Vertex>& out) {
  out.clear();
  const std::size_t n = in.size();
  if (n == 0) return;
  out.reserve(n + 16);  // usually a few crossings more than the input (no growth by doubling)
  const int firstSide = orient(hA, hB, in[0].p);
  int sp = firstSide;
  for (std::size_t i = 0; i < n; ++i) {
    const Vertex& p = in[i];
    const int sq = i + 1 < n ? orient(hA, hB, in[i + 1].p) : firstSide;
    if (sp >= 0) {
      out.push_back(p);
      if (sq < 0) {
        if (sp == 0) {
          out.back().lineA = hA;  // leaves along the boundary right away
          out.back().lineB = hB;
        } else {
          out.push_back({crossing(p, hA, hB), hA, hB});
        }
      }
    } else if (sq > 0) {
      out.push_back({crossing(p, hA, hB), p.lineA, p.lineB});
    }
    sp = sq;
  }
}

}  // namespace

int convexOrientation(const std::vector<IPoint>& ring) {
  const std::size_t n = ring.size();
  if (n < 3) return 0;
  int turn = 0;
  int xFlips = 0, yFlips = 0;
  int lastDx = 0, lastDy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const IPoint a = ring[i], b = ring[(i + 1) % n], c = ring[(i + 2) % n];
    const int o = orient(a, b, c);
    if (o == 0) return 0;  // straight runs were merged: this is a reversal
    if (turn == 0) turn = o;
    if (o != turn) return 0;
    // Winding once: the edge direction's x and y signs each change exactly twice.
    const int dx = (b.x > a.x) - (b.x < a.x), dy = (b.y > a.y) - (b.y < a.y);
    if (dx != 0) {
      if (lastDx != 0 && dx != lastDx) ++xFlips;
      lastDx = dx;
    }
    if (dy != 0) {
      if (lastDy != 0 && dy != lastDy) ++yFlips;
      lastDy = dy;
    }
  }
  // Close the cycle of sign changes (first non-zero direction against the last).
  int firstDx = 0, firstDy = 0;
  for (std::size_t i = 0; i < n && (firstDx == 0 || firstDy == 0); ++i) {
    const IPoint a = ring[i], b = ring[(i + 1) % n];
    if (firstDx == 0) firstDx = (b.x > a.x) - (b.x < a.x);
    if (firstDy == 0) firstDy = (b.y > a.y) - (b.y < a.y);
  }
  if (firstDx != 0 && lastDx != 0 && firstDx != lastDx) ++xFlips;
  if (firstDy != 0 && lastDy != 0 && firstDy != lastDy) ++yFlips;
  return xFlips <= 2 && yFlips <= 2 ? turn : 0;
}

void preclipConvex(const Rings& rings, const std::vector<IPoint>& convexRing,
                   std::vector<ExactEdge>& out) {
  const WorkspaceLease workspace;
  preclipConvex(rings, convexRing, convexOrientation(convexRing), *workspace, out);
}

void preclipConvex(const Rings& rings, const std::vector<IPoint>& convexRing, int orientation,
                   Workspace& workspace, std::vector<ExactEdge>& out) {
  if (orientation == 0) throw InternalError("preclipConvex: clip ring is not convex");
  std::vector<IPoint> clipRing = convexRing;
  if (orientation < 0) std::reverse(clipRing.begin(), clipRing.end());  // inside on the left

  // Reserved up front: at 100k vertices growth by doubling doubled the bytes allocated, and
  // fresh pages cost more than the clipping (kernel page faults).
  std::size_t vertexCount = 0;
  for (const std::vector<IPoint>& ring : rings) vertexCount += ring.size();
  out.clear();
  out.reserve(vertexCount + 16);
  std::vector<Vertex>& path = workspace.path;
  std::vector<Vertex>& next = workspace.next;
  const std::size_t sides = clipRing.size();
  for (const std::vector<IPoint>& ring : rings) {
    // Rings entirely inside every half-plane pass unchanged; rings entirely outside one of them
    // wind 0 times around every point of the clip ring and are dropped.
    bool allInside = true, outsideOne = false;
    for (std::size_t k = 0; k < sides && !outsideOne; ++k) {
      const IPoint hA = clipRing[k], hB = clipRing[(k + 1) % sides];
      bool anyIn = false;
      for (const IPoint& q : ring) {
        const int o = orient(hA, hB, q);
        if (o <= 0) allInside = false;
        if (o > 0) anyIn = true;
        if (!allInside && anyIn) break;
      }
      if (!anyIn) outsideOne = true;
    }
    if (outsideOne) continue;
    path.clear();
    path.reserve(ring.size());
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const IPoint a = ring[i], b = ring[(i + 1) % ring.size()];
      path.push_back({XPoint(a), a, b});
    }
    if (!allInside) {
      for (std::size_t k = 0; k < sides && !path.empty(); ++k) {
        clipHalfPlane(path, clipRing[k], clipRing[(k + 1) % sides], next);
        path.swap(next);
      }
    }
    for (std::size_t i = 0; i < path.size(); ++i) {
      const Vertex& v = path[i];
      const XPoint& w = path[(i + 1) % path.size()].p;
      const int c = compare(v.p, w);
      if (c == 0) continue;
      ExactEdge e;
      e.lineA = v.lineA < v.lineB ? v.lineA : v.lineB;
      e.lineB = v.lineA < v.lineB ? v.lineB : v.lineA;
      e.left = c < 0 ? v.p : w;
      e.right = c < 0 ? w : v.p;
      e.direction = c < 0 ? +1 : -1;
      e.operand = 0;
      out.push_back(e);
    }
  }
  // Not kept through the sweep that follows: at 1M vertices these two are 190 MB of the peak.
  recycle(path);
  recycle(next);
}

}  // namespace roiclip::detail
