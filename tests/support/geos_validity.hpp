// SPDX-License-Identifier: MIT
// OGC validity of a result as a GIS consumer sees it: the PolygonSet's doubles (what the writers
// print, 17 significant digits round-trip) as a GEOS MultiPolygon, judged by GEOSisValid. Header
// only; the test target links GEOS::geos_c.
#pragma once

#include <string>
#include <vector>

#include <geos_c.h>

#include <roiclip/geometry.hpp>

namespace roiclip::testing {

/// "" when GEOS finds `set` valid as a MultiPolygon (each Polygon a shell and its holes), else
/// GEOS's reason ("Self-intersection[x y]", ...).
inline std::string geosValidityProblem(const PolygonSet& set) {
  GEOSContextHandle_t ctx = GEOS_init_r();
  const auto ring = [ctx](const Path& path) {
    GEOSCoordSequence* seq = GEOSCoordSeq_create_r(ctx, unsigned(path.size() + 1), 2);
    for (std::size_t i = 0; i <= path.size(); ++i) {
      const Point& p = path[i % path.size()];
      GEOSCoordSeq_setX_r(ctx, seq, unsigned(i), p.x);
      GEOSCoordSeq_setY_r(ctx, seq, unsigned(i), p.y);
    }
    return GEOSGeom_createLinearRing_r(ctx, seq);
  };
  std::vector<GEOSGeometry*> polygons;
  for (const Polygon& polygon : set.polygons) {
    std::vector<GEOSGeometry*> holes;
    for (const Path& hole : polygon.holes) holes.push_back(ring(hole));
    polygons.push_back(
        GEOSGeom_createPolygon_r(ctx, ring(polygon.outer), holes.data(), unsigned(holes.size())));
  }
  GEOSGeometry* all = GEOSGeom_createCollection_r(ctx, GEOS_MULTIPOLYGON, polygons.data(),
                                                  unsigned(polygons.size()));
  std::string problem;
  if (all == nullptr) {
    problem = "GEOS could not build the MultiPolygon";
  } else if (GEOSisValid_r(ctx, all) != 1) {
    char* reason = GEOSisValidReason_r(ctx, all);
    problem = reason != nullptr ? reason : "invalid";
    GEOSFree_r(ctx, reason);
  }
  if (all != nullptr) GEOSGeom_destroy_r(ctx, all);
  GEOS_finish_r(ctx);
  return problem;
}

}  // namespace roiclip::testing
