// SPDX-License-Identifier: MIT
// libFuzzer target: roiclip::clipLines, both parts, checked against the exact winding numbers of
// the region at points sampled along the input lines (tests/support/oracle.hpp).
//
// Input bytes: [h0: region fill rule (bits 0-1), region is the convex hull of its points
//               (bit 2), reverse that hull (bit 3)]
//              [h1: coordinate mode (bits 0-2), line count - 1 (bits 3-4)]
//              then the lines and the region's paths as in fuzz_simplify (a line is a path read
//              as open).
// A hull is one strictly convex ring, which takes clipLines' half-plane path; every other
// region goes through the sweep.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace roiclip;
  if (size < 2) return 0;
  fuzz::ByteReader in(data, size);
  const std::uint8_t h0 = in.next();
  const std::uint8_t h1 = in.next();
  const auto rule = static_cast<FillRule>(h0 & 3);
  const int mode = h1 & 7;
  const Paths lines = fuzz::decodePaths(in, mode, 1 + ((h1 >> 3) & 3), 24);
  Paths region = fuzz::decodePaths(in, mode, 3, 32);
  if ((h0 & 4) != 0) region = testing::convexHull(region, (h0 & 8) != 0);
  Paths inside, outside;
  fuzz::expectDocumentedErrors(
      "clipLines",
      [&] {
        inside = clipLines(lines, region, rule, LinePart::Inside);
        outside = clipLines(lines, region, rule, LinePart::Outside);
      },
      true);
  const auto describe = [&] {
    return std::string("clipLines, region fill rule ") + toString(rule) +
           "\nlines: " + testing::describe(lines) + "\nregion: " + testing::describe(region);
  };
  // The two parts split every line once.
  const double total = testing::length(lines);
  const double split = testing::length(inside) + testing::length(outside);
  if (!(std::fabs(split - total) <= 1e-9 * (1 + total))) {
    fuzz::fail("inside + outside length " + std::to_string(split) + " but the lines are " +
               std::to_string(total) + "\n" + describe());
  }
  // Points along the input: off the region's boundary in exactly the part their winding number
  // says; on it (where a side settles it) in the inside part when a side is filled.
  for (const Path& line : lines) {
    for (std::size_t i = 1; i < line.size(); ++i) {
      if (line[i] == line[i - 1]) continue;
      for (int j = 1; j < 8; ++j) {
        const Point q = line[i - 1] + (line[i] - line[i - 1]) * (double(j) / 8);
        const std::string where = " at " + std::to_string(q.x) + "," + std::to_string(q.y) + "\n";
        if (testing::distanceToEdges(region, q) < 1e-4) {
          const std::optional<bool> closure = testing::inClosure(region, rule, q);
          if (closure && testing::onPolylines(inside, q) != *closure) {
            fuzz::fail("boundary point in the wrong part" + where + describe());
          }
          continue;
        }
        const auto w = testing::exactWinding(region, q);
        if (!w) continue;  // on a region edge after all (distance rounding)
        const bool filled = isFilled(rule, *w);
        if (testing::onPolylines(inside, q) != filled ||
            testing::onPolylines(outside, q) == filled) {
          fuzz::fail(std::string(filled ? "inside" : "outside") + " point in the wrong part" +
                     where + describe());
        }
      }
    }
  }
  return 0;
}
