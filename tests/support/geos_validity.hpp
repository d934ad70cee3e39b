// SPDX-License-Identifier: MIT
// GEOS validity of roiclip results, as a GIS consumer sees them: every vertex printed with
// %.17g (which round-trips doubles exactly), read back by GEOS's WKT reader, and judged by
// GEOSisValidReason (OGC rules: simple rings, no crossings, holes inside their shell, parts not
// overlapping, interiors connected). Tests only: the library never links GEOS.
#pragma once

#include <string>

#include <roiclip/geometry.hpp>

namespace roiclip::testing {

/// The result as a WKT MULTIPOLYGON, coordinates printed with %.17g; islands in holes are
/// polygons of their own (OGC has no nesting), rings closed by repeating the first point.
std::string toWkt(const PolygonSet& set);

/// Empty when GEOS reads toWkt(set) as a valid geometry, else GEOS's reason ("Self-intersection
/// [340 460]") followed by the WKT.
std::string geosValidityProblem(const PolygonSet& set);

}  // namespace roiclip::testing
