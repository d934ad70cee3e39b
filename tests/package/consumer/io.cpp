// SPDX-License-Identifier: MIT
// roiclip::io through the installed package: read a square from GeoJSON text.
#include <roiclip/io/geojson.hpp>

#include <iostream>

int main() {
  const roiclip::Paths paths = roiclip::io::parsePaths(
      R"({"type": "Polygon", "coordinates": [[[0, 0], [10, 0], [10, 5], [0, 5], [0, 0]]]})");
  const double area = roiclip::simplify(paths, roiclip::FillRule::NonZero).area();
  std::cout << "area " << area << "\n";
  return area == 50.0 ? 0 : 1;
}
