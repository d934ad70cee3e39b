// SPDX-License-Identifier: MIT
#include "adapters.hpp"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <stdexcept>

namespace roiclip::bench {

BoostPolygon toBoost(const Paths& paths) {
  BoostPolygon polygon;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    std::vector<BoostPoint> ring;
    ring.reserve(paths[i].size() + 1);
    for (const Point& p : paths[i]) ring.emplace_back(p.x, p.y);
    ring.push_back(ring.front());
    if (i == 0) {
      polygon.outer().assign(ring.begin(), ring.end());
    } else {
      polygon.inners().emplace_back(ring.begin(), ring.end());
    }
  }
  boost::geometry::correct(polygon);
  return polygon;
}

std::size_t ringCount(const BoostMultiPolygon& polygons) {
  std::size_t rings = 0;
  for (const BoostPolygon& p : polygons) rings += 1 + p.inners().size();
  return rings;
}

namespace {

void printGeosMessage(const char* format, ...) {
  va_list args;
  va_start(args, format);
  std::fputs("GEOS: ", stderr);
  std::vfprintf(stderr, format, args);
  std::fputc('\n', stderr);
  va_end(args);
}

GEOSGeometry* geosRing(const Path& path) {
  GEOSContextHandle_t ctx = geosContext();
  GEOSCoordSequence* seq = GEOSCoordSeq_create_r(ctx, unsigned(path.size() + 1), 2);
  for (std::size_t i = 0; i <= path.size(); ++i) {
    const Point& p = path[i % path.size()];
    GEOSCoordSeq_setXY_r(ctx, seq, unsigned(i), p.x, p.y);
  }
  return GEOSGeom_createLinearRing_r(ctx, seq);
}

}  // namespace

GEOSContextHandle_t geosContext() {
  static GEOSContextHandle_t ctx = [] {
    GEOSContextHandle_t handle = GEOS_init_r();
    GEOSContext_setNoticeHandler_r(handle, printGeosMessage);
    GEOSContext_setErrorHandler_r(handle, printGeosMessage);
    return handle;
  }();
  return ctx;
}

GeosGeometry toGeos(const Paths& paths) {
  if (paths.empty()) throw std::invalid_argument("toGeos: no rings");
  std::vector<GEOSGeometry*> holes;
  for (std::size_t i = 1; i < paths.size(); ++i) holes.push_back(geosRing(paths[i]));
  return GeosGeometry(GEOSGeom_createPolygon_r(geosContext(), geosRing(paths[0]), holes.data(),
                                               unsigned(holes.size())));
}

double geosArea(const GEOSGeometry* g) {
  double area = 0.0;
  if (GEOSArea_r(geosContext(), g, &area) == 0) return std::nan("");
  return area;
}

std::size_t geosRingCount(const GEOSGeometry* g) {
  GEOSContextHandle_t ctx = geosContext();
  std::size_t rings = 0;
  const int parts = GEOSGetNumGeometries_r(ctx, g);
  for (int i = 0; i < parts; ++i) {
    const GEOSGeometry* part = GEOSGetGeometryN_r(ctx, g, i);
    if (GEOSGeomTypeId_r(ctx, part) != GEOS_POLYGON) continue;
    rings += 1 + std::size_t(GEOSGetNumInteriorRings_r(ctx, part));
  }
  return rings;
}

}  // namespace roiclip::bench
