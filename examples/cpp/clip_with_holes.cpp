// SPDX-License-Identifier: MIT
// Clip a polygon with a hole (a frame) by a rectangle, and walk the result: each polygon's outer
// ring, its holes, and where it is nested. Core only (standard library + GLM).
//
//   clip_with_holes
#include <roiclip/roiclip.hpp>

#include <cstdio>

int main() {
  // A 10 x 10 square with a 4 x 4 hole: the outer ring and the hole go into one path set and the
  // fill rule decides (even-odd: inside the hole the winding number is 2 or 0, so it is empty).
  const roiclip::Paths frame = {
      {{0, 0}, {10, 0}, {10, 10}, {0, 10}},  // outer ring
      {{3, 3}, {7, 3}, {7, 7}, {3, 7}},      // hole
  };
  // A rectangle over all but the left 2 px of the frame: it contains the hole.
  const roiclip::Paths rect = {{{2, -1}, {12, -1}, {12, 11}, {2, 11}}};

  // Inside: one polygon, 8 x 10 px, with the hole. Outside: the 2 x 10 px strip on the left.
  const roiclip::PolygonSet inside = roiclip::intersect(frame, rect, roiclip::FillRule::EvenOdd);
  const roiclip::PolygonSet outside = roiclip::subtract(frame, rect, roiclip::FillRule::EvenOdd);

  for (const auto* set : {&inside, &outside}) {
    std::printf("%s: area %.1f, %zu polygon(s), %zu ring(s)\n",
                set == &inside ? "inside" : "outside", set->area(), set->polygons.size(),
                set->ringCount());
    for (const roiclip::Polygon& p : set->polygons) {
      // Outer rings have a negative shoelace sum (counter-clockwise on screen, y down), holes a
      // positive one, as cv::findContours returns them.
      std::printf("  outer ring: %zu vertices, signed area %.1f; %zu hole(s); parent %d\n",
                  p.outer.size(), roiclip::signedArea(p.outer), p.holes.size(), p.parent);
    }
  }
  // Exact areas: 80 - 16 and 20.
  const bool ok = inside.area() == 64.0 && inside.polygons.size() == 1 &&
                  inside.polygons[0].holes.size() == 1 && outside.area() == 20.0;
  return ok ? 0 : 1;
}
