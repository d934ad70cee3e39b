// SPDX-License-Identifier: MIT
// Stage 4: nesting. Each hole gets its outer ring, each outer ring the hole it lies in.
//
// The sweep recorded, for every result piece, the nearest result piece below its left end. For
// a ring's lowest-leftmost piece, that piece belongs to the ring bounding the region just
// below; whether that ring is an outer ring or a hole, and whether the region is filled, says
// who owns the ring. No point-in-polygon tests: linear after the sweep.
#include <cmath>
#include <limits>
#include <utility>

#include <roiclip/error.hpp>

#include "output.hpp"
#include "pipeline.hpp"
#include "workspace.hpp"

namespace roiclip::detail {

PolygonSet buildNesting(const Arrangement& arrangement, const Contours& contours,
                        const Grid& grid) {
  NestingScratch scratch;
  return buildNesting(arrangement, contours, grid, scratch);
}

PolygonSet buildNesting(const Arrangement& arrangement, const Contours& contours, const Grid& grid,
                        NestingScratch& scratch) {
  const auto& rings = contours.rings;
  const std::size_t pieceCount = contours.ringOfPiece.size();  // the pieces may be freed

  // Rings in the order of their reference pieces (each piece is the reference of one ring at
  // most): the piece below a ring's reference piece comes earlier in the sweep, so its ring has
  // been placed before.
  std::vector<int>& ringAtPiece = scratch.ringAtPiece;
  ringAtPiece.assign(pieceCount, -1);
  std::size_t outerCount = 0;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    ringAtPiece[std::size_t(rings[r].referencePiece)] = int(r);
    if (!rings[r].hole) ++outerCount;
  }
  std::vector<int>& order = scratch.order;
  order.clear();
  order.reserve(rings.size());
  for (int r : ringAtPiece) {
    if (r >= 0) order.push_back(r);
  }

  // For outer rings: the hole ring they lie in. For holes: their outer ring.
  std::vector<int>& owner = scratch.owner;
  std::vector<int>& polygonOf = scratch.polygonOf;
  std::vector<int>& holeIndexOf = scratch.holeIndexOf;
  std::vector<char>& dropped = scratch.dropped;  // collapsed to < 3 points by the rounding
  owner.assign(rings.size(), -1);
  polygonOf.assign(rings.size(), -1);
  holeIndexOf.assign(rings.size(), -1);
  dropped.assign(rings.size(), 0);
  PolygonSet result;
  result.polygons.reserve(outerCount);

  const OutputFrame frame(grid);  // each coordinate the double nearest its exact value
  // Each vertex is converted once: where rings touch (at every crossing of an even-odd result
  // that two rings share) the later ring takes the point the earlier one converted. The cache
  // (16 bytes a vertex, NaN until converted) costs a few instructions a vertex and saves about
  // 90 a shared one: kept only where at least one vertex in 16 is shared. It holds values, not
  // pointers into paths, since a ring that rounding collapses is dropped with its path.
  const bool cache = contours.sharedVertices * 16 >= arrangement.vertices.size();
  constexpr double kUnset = std::numeric_limits<double>::quiet_NaN();
  std::vector<Point>& converted = scratch.converted;
  converted.assign(cache ? arrangement.vertices.size() : 0, Point{kUnset, kUnset});
  // A crossing from its lines' parameter, without its exact coordinates first.
  const auto convert = [&](int v) {
    const ArrangementVertex& vertex = arrangement.vertices[std::size_t(v)];
    if (vertex.onGrid()) return frame.point(IPoint{vertex.a, vertex.b});
    if (vertex.isCrossing()) {
      const GridSegment& l1 = arrangement.lines[vertex.line1()];
      const GridSegment& l2 = arrangement.lines[vertex.line2()];
      std::int64_t num = 0, den = 0;
      Point p;
      if (crossingParameter(l1, l2, num, den) &&
          frame.alongFast(l1.lineA(), l1.direction(), num, den, p)) {
        return p;
      }
    }
    return frame.point(arrangement.exact(v));
  };
  auto pointOf = [&](int v) {
    if (!cache) return convert(v);
    Point& q = converted[std::size_t(v)];
    if (std::isnan(q.x)) q = convert(v);
    return q;
  };
  // Traced rings have the filled side on their left (outer rings counter-clockwise in the raw
  // frame); roiclip's output orientation is the opposite, as cv::findContours returns them.
  auto toPath = [&](const TracedRing& ring) {
    const std::size_t n = ring.vertices.size();
    return outputRing(n, [&](std::size_t k) { return pointOf(ring.vertices[n - 1 - k]); });
  };

  for (int r : order) {
    const TracedRing& ring = rings[r];
    const int b = ring.belowPiece;
    const int below = b >= 0 ? contours.ringOfPiece[b] : -1;
    if (below < 0) {
      if (ring.hole) throw InternalError("buildNesting: hole with nothing below it");
    } else if (!ring.hole) {
      owner[r] = rings[below].hole ? below : owner[below];
    } else {
      owner[r] = rings[below].hole ? owner[below] : below;
    }
    // A ring inside a ring that rounding collapsed is smaller still: dropped with it.
    if (owner[r] >= 0 && dropped[owner[r]]) {
      dropped[r] = 1;
      continue;
    }
    if (ring.hole && (owner[r] < 0 || polygonOf[owner[r]] < 0)) {
      throw InternalError("buildNesting: hole without an outer ring");
    }
    Path path = toPath(ring);
    if (path.size() < 3) {  // distinct exact points that round to fewer than 3 doubles
      dropped[r] = 1;
      continue;
    }
    if (!ring.hole) {
      Polygon polygon;
      polygon.outer = std::move(path);
      if (owner[r] >= 0) {
        polygon.parent = polygonOf[owner[owner[r]]];
        polygon.parentHole = holeIndexOf[owner[r]];
      }
      polygonOf[r] = int(result.polygons.size());
      result.polygons.push_back(std::move(polygon));
    } else {
      Polygon& outer = result.polygons[polygonOf[owner[r]]];
      holeIndexOf[r] = int(outer.holes.size());
      outer.holes.push_back(std::move(path));
    }
  }
  return result;
}

}  // namespace roiclip::detail
