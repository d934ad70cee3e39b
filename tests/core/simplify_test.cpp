#include <gtest/gtest.h>

#include <roiclip/roiclip.hpp>

namespace roiclip {
namespace {

TEST(Simplify, SquareKeepsAreaAndOrientation) {
  const Paths square = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}};
  const PolygonSet r = simplify(square, FillRule::NonZero);
  ASSERT_EQ(r.polygons.size(), 1u);
  EXPECT_EQ(r.polygons[0].outer.size(), 4u);
  EXPECT_DOUBLE_EQ(r.area(), 100.0);
  EXPECT_LT(signedArea(r.polygons[0].outer), 0.0);
}

}  // namespace
}  // namespace roiclip
