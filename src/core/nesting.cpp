// Stage 4: nesting. Each hole gets its outer ring, each outer ring the hole it lies in.
//
// The sweep recorded, for every piece, the piece directly below its left end. Following that
// chain down to the first result piece finds the ring that bounds the region just below a
// ring's lowest-leftmost piece; whether that ring is an outer ring or a hole, and whether the
// region is filled, says who owns the ring. No point-in-polygon tests: O(n) after the sweep.
#include <algorithm>
#include <numeric>

#include <roiclip/error.hpp>

#include "pipeline.hpp"

namespace roiclip::detail {

PolygonSet buildNesting(const Arrangement& arrangement, const std::vector<Side>& sides,
                        const Contours& contours, const Grid& grid) {
  const auto& pieces = arrangement.pieces;
  const auto& rings = contours.rings;

  // Nearest result piece below each piece (below indices are always smaller).
  std::vector<int> resultBelow(pieces.size(), -1);
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const int b = pieces[i].below;
    if (b >= 0) resultBelow[i] = sides[b] != Side::None ? b : resultBelow[b];
  }

  std::vector<int> order(rings.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return rings[a].referencePiece < rings[b].referencePiece; });

  // For outer rings: the hole ring they lie in. For holes: their outer ring.
  std::vector<int> owner(rings.size(), -1);
  std::vector<int> polygonOf(rings.size(), -1);
  std::vector<int> holeIndexOf(rings.size(), -1);
  PolygonSet result;

  const double inv = 1.0 / grid.scale;
  auto toPath = [&](const TracedRing& ring) {
    Path path;
    path.reserve(ring.vertices.size());
    // Traced rings have the filled side on their left (outer rings counter-clockwise in the raw
    // frame); roiclip's output orientation is the opposite, as cv::findContours returns them.
    for (auto it = ring.vertices.rbegin(); it != ring.vertices.rend(); ++it) {
      const XPoint& p = arrangement.vertices[*it];
      path.emplace_back(p.dx() * inv, p.dy() * inv);
    }
    return path;
  };

  for (int r : order) {
    const TracedRing& ring = rings[r];
    const int b = resultBelow[ring.referencePiece];
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
