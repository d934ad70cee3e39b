// SPDX-License-Identifier: MIT
// Conversions between roiclip paths and the native types of the libraries it is compared with:
// Clipper 1 (integer units, scaled exactly like roiclip's default grid; the adapter the tests
// use), Boost.Geometry and the GEOS C API. Conversions run outside the timed loops; only the
// operations are timed.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include <geos_c.h>
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/point_xy.hpp>

#include <roiclip/geometry.hpp>

#include "support/clipper1.hpp"

namespace roiclip::bench {

// ---- Clipper 1: tests/support/clipper1.hpp (shared with the tests) -------------------------

using testing::clipperArea;
using testing::toClipper;

// ---- Boost.Geometry -----------------------------------------------------------------------

using BoostPoint = boost::geometry::model::d2::point_xy<double>;
/// Clockwise, closed: Boost's defaults. "Clockwise" in Boost's y-up reading is a negative
/// shoelace sum, i.e. the orientation roiclip gives outer rings.
using BoostPolygon = boost::geometry::model::polygon<BoostPoint>;
using BoostMultiPolygon = boost::geometry::model::multi_polygon<BoostPolygon>;

/// The paths as one polygon (first path outer, the others holes), orientation corrected.
BoostPolygon toBoost(const Paths& paths);
std::size_t ringCount(const BoostMultiPolygon& polygons);

// ---- GEOS (C API, re-entrant) -------------------------------------------------------------

/// One GEOS context for the whole run; errors and notices are printed to stderr.
GEOSContextHandle_t geosContext();

struct GeosDeleter {
  void operator()(GEOSGeometry* g) const { GEOSGeom_destroy_r(geosContext(), g); }
};
using GeosGeometry = std::unique_ptr<GEOSGeometry, GeosDeleter>;

/// The paths as one polygon (first path outer, the others holes).
GeosGeometry toGeos(const Paths& paths);
double geosArea(const GEOSGeometry* g);
std::size_t geosRingCount(const GEOSGeometry* g);

}  // namespace roiclip::bench
