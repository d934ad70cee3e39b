// SPDX-License-Identifier: MIT
// libFuzzer target: the roiclip::io readers (parsePaths, parseFeatures, the WKT readers) on the
// bytes as text.
// Only roiclip::Error may escape them. Whatever parses is also simplified (when small) and the
// GeoJSON written for the result must read back with the same number of rings.
#include <cstddef>
#include <cstdint>
#include <string>

#include <roiclip/io/geojson.hpp>
#include <roiclip/io/wkt.hpp>

#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace roiclip;
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (const bool allowDegenerate : {false, true}) {
    io::ReadOptions options;
    options.allowDegenerateRings = allowDegenerate;
    fuzz::expectDocumentedErrors("parseFeatures", [&] {
      for (const io::Feature& f : io::parseFeatures(text, "<fuzz>", options)) {
        for (const Paths& polygon : f.polygons) {
          if (polygon.empty()) fuzz::fail("parseFeatures: a polygon without rings");
        }
      }
    });
    fuzz::expectDocumentedErrors("parseWktFeatures",
                                 [&] { io::parseWktFeatures(text, "<fuzz>", options); });
    fuzz::expectDocumentedErrors("parseWktLines",
                                 [&] { io::parseWktLines(text, "<fuzz>", options); });
    Paths paths;
    bool parsed = false;
    fuzz::expectDocumentedErrors("parsePaths", [&] {
      paths = io::parsePaths(text, "<fuzz>", options);
      parsed = true;
    });
    std::size_t vertices = 0;
    for (const Path& p : paths) vertices += p.size();
    if (!parsed || vertices > 64) continue;
    // Arbitrary doubles: out-of-range coordinates are documented InvalidInputErrors.
    fuzz::expectDocumentedErrors("simplify", [&] {
      const PolygonSet result = simplify(paths, FillRule::NonZero);
      const std::string json = io::toGeoJson(result);
      Paths back;
      fuzz::expectDocumentedErrors(
          "parsePaths(toGeoJson(result))", [&] { back = io::parsePaths(json, "<written>"); }, true);
      if (back.size() != result.ringCount()) {
        fuzz::fail("toGeoJson wrote " + std::to_string(result.ringCount()) +
                   " rings, parsePaths read back " + std::to_string(back.size()) + ": " + json);
      }
    });
  }
  return 0;
}
