// SPDX-License-Identifier: MIT
// simplify() cases computed in code (the pentagram's corners and its inner pentagon's area) and
// the names of fill rules and operations. The hand-worked cases with literal coordinates (bow-tie,
// figure-eight, a square wound twice, touching rings, collinear overlaps, spikes, duplicate
// points, the paper's example, an island in a hole) are data: tests/data/core/cases/, run by
// case_test.cpp; validation, nesting and range-edge tests are in stages/.
#include <gtest/gtest.h>

#include <cmath>

#include <roiclip/roiclip.hpp>

#include "support/oracle.hpp"

namespace roiclip {
namespace {

bool covers(const PolygonSet& r, Point p) {
  int w = 0;
  for (const Path& ring : r.toPaths()) w -= testing::ringWinding(ring, p);
  return w == 1;
}

TEST(Simplify, PentagramCentreDependsOnFillRule) {
  Path star;
  for (int k = 0; k < 5; ++k) {
    const double a = (90.0 + 144.0 * k) * M_PI / 180.0;
    star.emplace_back(std::round(100 * std::cos(a) * 256) / 256,
                      std::round(100 * std::sin(a) * 256) / 256);
  }
  const Paths in = {star};
  const PolygonSet evenOdd = simplify(in, FillRule::EvenOdd);
  const PolygonSet nonZero = simplify(in, FillRule::NonZero);
  EXPECT_FALSE(covers(evenOdd, {0.1, 0.1}));
  EXPECT_TRUE(covers(nonZero, {0.1, 0.1}));
  // Non-zero: one ring of 10 vertices. Even-odd: the 5 tips (w = 1) without the centre (w = 2).
  EXPECT_EQ(nonZero.ringCount(), 1u);
  EXPECT_EQ(nonZero.polygons[0].outer.size(), 10u);
  const double pentagon = nonZero.area() - evenOdd.area();
  // Inner pentagon of a {5/2} star with circumradius R has circumradius R*sin(18)/sin(126).
  const double r = 100 * std::sin(M_PI / 10) / std::sin(7 * M_PI / 10);
  EXPECT_NEAR(pentagon, 2.5 * r * r * std::sin(2 * M_PI / 5), 0.5);
  EXPECT_EQ(testing::structureProblems(evenOdd), "");
}

TEST(Simplify, ParsesNames) {
  EXPECT_EQ(parseFillRule("even-odd"), FillRule::EvenOdd);
  EXPECT_EQ(parseFillRule("NonZero"), FillRule::NonZero);
  EXPECT_EQ(parseClipOp("xor"), ClipOp::Xor);
  EXPECT_THROW(parseFillRule("odd"), InvalidInputError);
  EXPECT_THROW(parseClipOp("merge"), InvalidInputError);
}

}  // namespace
}  // namespace roiclip
