// SPDX-License-Identifier: MIT
#include "support/geos_validity.hpp"

#include <cstdio>
#include <memory>
#include <stdexcept>

#include <geos_c.h>

namespace roiclip::testing {
namespace {

void appendRing(const Path& ring, std::string& out) {
  char buffer[64];
  out += '(';
  for (std::size_t i = 0; i <= ring.size(); ++i) {
    const Point& p = ring[i % ring.size()];
    std::snprintf(buffer, sizeof buffer, "%s%.17g %.17g", i ? ", " : "", p.x, p.y);
    out += buffer;
  }
  out += ')';
}

struct Context {
  GEOSContextHandle_t handle = GEOS_init_r();
  Context() = default;
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;
  ~Context() { GEOS_finish_r(handle); }
};

}  // namespace

std::string toWkt(const PolygonSet& set) {
  if (set.empty()) return "MULTIPOLYGON EMPTY";
  std::string out = "MULTIPOLYGON (";
  for (std::size_t i = 0; i < set.polygons.size(); ++i) {
    const Polygon& polygon = set.polygons[i];
    out += i ? ", (" : "(";
    appendRing(polygon.outer, out);
    for (const Path& hole : polygon.holes) {
      out += ", ";
      appendRing(hole, out);
    }
    out += ')';
  }
  return out + ')';
}

std::string geosValidityProblem(const PolygonSet& set) {
  for (const Polygon& polygon : set.polygons) {
    if (polygon.outer.size() < 3) return "a ring with fewer than 3 vertices";
    for (const Path& hole : polygon.holes) {
      if (hole.size() < 3) return "a ring with fewer than 3 vertices";
    }
  }
  thread_local Context context;  // GEOS contexts are not shared between threads
  const std::string wkt = toWkt(set);
  GEOSWKTReader* reader = GEOSWKTReader_create_r(context.handle);
  GEOSGeometry* geometry = GEOSWKTReader_read_r(context.handle, reader, wkt.c_str());
  GEOSWKTReader_destroy_r(context.handle, reader);
  if (geometry == nullptr) return "GEOS cannot read the WKT: " + wkt;
  char* reason = GEOSisValidReason_r(context.handle, geometry);
  std::string problem = reason != nullptr ? reason : "GEOSisValidReason failed";
  GEOSFree_r(context.handle, reason);
  GEOSGeom_destroy_r(context.handle, geometry);
  if (problem == "Valid Geometry") return "";
  return problem + " in " + wkt;
}

}  // namespace roiclip::testing
