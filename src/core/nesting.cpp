// SPDX-License-Identifier: MIT
// Stage 4: nesting. Each hole gets its outer ring, each outer ring the hole it lies in.
//
// The sweep recorded, for every result piece, the nearest result piece below its left end. For
// a ring's lowest-leftmost piece, that piece belongs to the ring bounding the region just
// below; whether that ring is an outer ring or a hole, and whether the region is filled, says
// who owns the ring. No point-in-polygon tests: linear after the sweep.
#include <roiclip/error.hpp>

#include "output.hpp"
#include "pipeline.hpp"

namespace roiclip::detail {

PolygonSet buildNesting(const Arrangement& arrangement, const Contours& contours,
                        const Grid& grid) {
  const auto& pieces = arrangement.pieces;
  const auto& rings = contours.rings;

  // Rings in the order of their reference pieces (each piece is the reference of one ring at
  // most): the piece below a ring's reference piece comes earlier in the sweep, so its ring has
  // been placed before.
  std::vector<int> ringAtPiece(pieces.size(), -1);
  std::size_t outerCount = 0;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    ringAtPiece[std::size_t(rings[r].referencePiece)] = int(r);
    if (!rings[r].hole) ++outerCount;
  }
  std::vector<int> order;
  order.reserve(rings.size());
  for (int r : ringAtPiece) {
    if (r >= 0) order.push_back(r);
  }

  // For outer rings: the hole ring they lie in. For holes: their outer ring.
  std::vector<int> owner(rings.size(), -1);
  std::vector<int> polygonOf(rings.size(), -1);
  std::vector<int> holeIndexOf(rings.size(), -1);
  PolygonSet result;
  result.polygons.reserve(outerCount);

  const OutputFrame frame(grid);  // each coordinate the double nearest its exact value
  // Each vertex is converted once: where rings touch (at every crossing of an even-odd result
  // that two rings share) the later ring copies the point from the earlier ring's path. A path's
  // storage is reserved before it is filled and moves with the path, so the pointers stay
  // valid; 8 bytes a vertex, not the 16 of a copy. The cache costs a few instructions a vertex
  // and saves about 90 a shared one: kept only where at least one vertex in 16 is shared.
  const bool cache = contours.sharedVertices * 16 >= arrangement.vertices.size();
  std::vector<const Point*> converted(cache ? arrangement.vertices.size() : 0, nullptr);
  auto toPath = [&](const TracedRing& ring) {
    Path path;
    path.reserve(ring.vertices.size());
    // Traced rings have the filled side on their left (outer rings counter-clockwise in the raw
    // frame); roiclip's output orientation is the opposite, as cv::findContours returns them.
    for (auto it = ring.vertices.rbegin(); it != ring.vertices.rend(); ++it) {
      if (!cache) {
        path.push_back(frame.point(arrangement.vertices[*it]));
        continue;
      }
      const Point*& q = converted[std::size_t(*it)];
      path.push_back(q != nullptr ? *q : frame.point(arrangement.vertices[*it]));
      if (q == nullptr) q = &path.back();
    }
    return path;
  };

  for (int r : order) {
    const TracedRing& ring = rings[r];
    const int b = pieces[ring.referencePiece].below;
    const int below = b >= 0 ? contours.ringOfPiece[b] : -1;
    if (below < 0) {
      if (ring.hole) throw InternalError("buildNesting: hole with nothing below it");
    } else if (!ring.hole) {
      owner[r] = rings[below].hole ? below : owner[below];
    } else {
      owner[r] = rings[below].hole ? owner[below] : below;
    }
    if (!ring.hole) {
      Polygon polygon;
      polygon.outer = toPath(ring);
      if (owner[r] >= 0) {
        polygon.parent = polygonOf[owner[owner[r]]];
        polygon.parentHole = holeIndexOf[owner[r]];
      }
      polygonOf[r] = int(result.polygons.size());
      result.polygons.push_back(std::move(polygon));
    } else {
      if (owner[r] < 0 || polygonOf[owner[r]] < 0) {
        throw InternalError("buildNesting: hole without an outer ring");
      }
      Polygon& outer = result.polygons[polygonOf[owner[r]]];
      holeIndexOf[r] = int(outer.holes.size());
      outer.holes.push_back(toPath(ring));
    }
  }
  return result;
}

}  // namespace roiclip::detail
