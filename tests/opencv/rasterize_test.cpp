// SPDX-License-Identifier: MIT
// The exact rasteriser against an independent per-pixel winding-number computation.
#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <roiclip/opencv/rasterize.hpp>

namespace roiclip::opencv {
namespace {

constexpr double kScale = 256.0;  // the default Grid

int sign(long long v) { return (v > 0) - (v < 0); }

/// Winding number at the pixel centre (col, row) pushed to (col + d, row + e), 0 < e << d
/// infinitesimal: Sunday's crossing test with a ray to the right, the orientation of the
/// perturbed point decided symbolically. One edge at a time, no sorting, no scanlines: an
/// implementation independent of rasterize().
long long perturbedWinding(const Paths& paths, int col, int row) {
  const long long qx = std::llround(col * kScale), qy = std::llround(row * kScale);
  long long w = 0;
  for (const Path& path : paths) {
    const std::size_t n = path.size();
    for (std::size_t i = 0; i < n; ++i) {
      const long long ax = std::llround(std::nearbyint(path[i].x * kScale));
      const long long ay = std::llround(std::nearbyint(path[i].y * kScale));
      const long long bx = std::llround(std::nearbyint(path[(i + 1) % n].x * kScale));
      const long long by = std::llround(std::nearbyint(path[(i + 1) % n].y * kScale));
      // isLeft(a, b, q + (d, e)) = C + (bx - ax) e - (by - ay) d
      const long long c = (bx - ax) * (qy - ay) - (qx - ax) * (by - ay);
      const int left = c != 0 ? sign(c) : (by != ay ? -sign(by - ay) : sign(bx - ax));
      // ay <= qy + e  <=>  ay <= qy, because grid values never equal qy + e.
      if (ay <= qy) {
        if (by > qy && left > 0) ++w;
      } else if (by <= qy && left < 0) {
        --w;
      }
    }
  }
  return w;
}

cv::Mat oracleMask(const Paths& paths, FillRule rule, cv::Size size) {
  cv::Mat m(size, CV_8UC1, cv::Scalar(0));
  for (int r = 0; r < size.height; ++r) {
    for (int c = 0; c < size.width; ++c) {
      if (isFilled(rule, perturbedWinding(paths, c, r))) m.at<std::uint8_t>(r, c) = 255;
    }
  }
  return m;
}

std::string dumpPaths(const Paths& paths) {
  std::ostringstream os;
  os.precision(17);
  for (const Path& p : paths) {
    os << "[";
    for (const Point& q : p) os << "[" << q.x << "," << q.y << "]";
    os << "]";
  }
  return os.str();
}

constexpr FillRule kRules[] = {FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive,
                               FillRule::Negative};

TEST(Rasterize, OracleAgreesOnPositiveSquare) {
  // Sanity check of the oracle itself: positive shoelace sum winds +1.
  const Paths square = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}};
  ASSERT_GT(signedArea(square[0]), 0);
  EXPECT_EQ(perturbedWinding(square, 5, 5), 1);
  EXPECT_EQ(perturbedWinding(square, 0, 0), 1);
  EXPECT_EQ(perturbedWinding(square, 10, 5), 0);
  EXPECT_EQ(perturbedWinding(square, 5, 10), 0);
}

TEST(Rasterize, IntegerSquareSetsHalfOpenPixelRange) {
  // Both orientations: [2, 7] x [3, 9] sets columns 2..6 and rows 3..8.
  for (bool reversed : {false, true}) {
    Path square = {{2, 3}, {7, 3}, {7, 9}, {2, 9}};  // positive shoelace sum: winding +1
    if (reversed) std::reverse(square.begin(), square.end());
    for (FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
      const cv::Mat m = rasterize(Paths{square}, rule, {12, 12});
      for (int r = 0; r < 12; ++r) {
        for (int c = 0; c < 12; ++c) {
          const bool inside = c >= 2 && c <= 6 && r >= 3 && r <= 8;
          EXPECT_EQ(m.at<std::uint8_t>(r, c) != 0, inside) << "pixel " << c << "," << r;
        }
      }
    }
    EXPECT_EQ(cv::countNonZero(rasterize(Paths{square}, FillRule::Positive, {12, 12})),
              reversed ? 0 : 30);
    EXPECT_EQ(cv::countNonZero(rasterize(Paths{square}, FillRule::Negative, {12, 12})),
              reversed ? 30 : 0);
  }
}

TEST(Rasterize, SharedEdgesNeitherOverlapNorLeaveGaps) {
  // A square cut along a diagonal through pixel centres and a fan of triangles around an
  // interior vertex at a pixel centre: every pixel of the square is set by exactly one piece.
  const Point c{6, 5};
  const Path square = {{1, 1}, {11, 1}, {11, 9}, {1, 9}};
  cv::Mat sum(12, 12, CV_32S, cv::Scalar(0));
  for (std::size_t i = 0; i < square.size(); ++i) {
    const Paths tri = {{square[i], square[(i + 1) % 4], c}};
    cv::Mat m = rasterize(tri, FillRule::NonZero, {12, 12});
    cv::Mat m32;
    m.convertTo(m32, CV_32S, 1.0 / 255);
    sum += m32;
  }
  const cv::Mat whole = rasterize(Paths{square}, FillRule::NonZero, {12, 12});
  for (int r = 0; r < 12; ++r) {
    for (int col = 0; col < 12; ++col) {
      EXPECT_EQ(sum.at<int>(r, col), whole.at<std::uint8_t>(r, col) ? 1 : 0)
          << "pixel " << col << "," << r;
    }
  }
  EXPECT_EQ(cv::countNonZero(whole), 80);
}

TEST(Rasterize, PolygonSetOverloadUsesItsRings) {
  PolygonSet set;
  Polygon p;
  p.outer = {{0, 0}, {0, 8}, {8, 8}, {8, 0}};  // negative shoelace, as the core outputs
  p.holes = {{{2, 2}, {6, 2}, {6, 6}, {2, 6}}};
  set.polygons.push_back(p);
  EXPECT_EQ(cv::countNonZero(rasterize(set, {10, 10})), 64 - 16);
}

TEST(Rasterize, RejectsBadInput) {
  EXPECT_THROW(rasterize(Paths{{{0, 0}, {NAN, 1}, {2, 2}}}, FillRule::EvenOdd, {4, 4}),
               InvalidInputError);
  EXPECT_THROW(rasterize(Paths{{{0, 0}, {1e12, 1}, {2, 2}}}, FillRule::EvenOdd, {4, 4}),
               InvalidInputError);
  Grid odd;
  odd.scale = 100.5;
  EXPECT_THROW(rasterize(Paths{}, FillRule::EvenOdd, {4, 4}, odd), InvalidInputError);
  try {
    rasterize(Paths{{{0, 0}, {1, 1}}, {{0, 0}, {1, INFINITY}}}, FillRule::EvenOdd, {4, 4});
    FAIL() << "no exception";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("path 1, vertex 1"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(rasterize(Paths{}, FillRule::EvenOdd, {0, 0}).empty());
}

// Random self-intersecting paths with vertices on coarse grids (so many centres lie exactly on
// edges and vertices) and on the fine 1/256 grid, partly outside the image.
Paths randomPaths(std::mt19937& rng, cv::Size size) {
  std::uniform_int_distribution<int> pathCount(1, 3), vertexCount(3, 9), gridPick(0, 3);
  const double steps[] = {1.0, 0.5, 0.25, 1.0 / 256};
  Paths paths(std::size_t(pathCount(rng)));
  for (Path& path : paths) {
    const double step = steps[gridPick(rng)];
    std::uniform_int_distribution<int> xs(int(-3 / step), int((size.width + 3) / step));
    std::uniform_int_distribution<int> ys(int(-3 / step), int((size.height + 3) / step));
    const int n = vertexCount(rng);
    for (int i = 0; i < n; ++i) path.push_back({xs(rng) * step, ys(rng) * step});
    if (gridPick(rng) == 0 && n > 3) path[2] = path[0];  // a repeated vertex
  }
  return paths;
}

TEST(Rasterize, MatchesPerPixelWindingOnRandomPaths) {
  std::mt19937 rng(20261122);
  const cv::Size size(23, 17);
  int pixelsChecked = 0, pixelsSet = 0;
  for (int iter = 0; iter < 600; ++iter) {
    const Paths paths = randomPaths(rng, size);
    for (FillRule rule : kRules) {
      const cv::Mat expected = oracleMask(paths, rule, size);
      const cv::Mat actual = rasterize(paths, rule, size);
      ASSERT_EQ(cv::countNonZero(expected != actual), 0)
          << "iteration " << iter << " rule " << toString(rule) << " paths " << dumpPaths(paths);
      pixelsChecked += size.area();
      pixelsSet += cv::countNonZero(actual);
    }
  }
  // The random paths must exercise both outcomes.
  EXPECT_GT(pixelsSet, pixelsChecked / 10);
  EXPECT_LT(pixelsSet, pixelsChecked * 9 / 10);
}

TEST(Rasterize, MatchesPerPixelWindingOnDegenerateCases) {
  const cv::Size size(9, 9);
  const std::vector<Paths> cases = {
      // horizontal edges through centres, collinear overlapping edges, doubled paths
      {{{1, 2}, {6, 2}, {6, 6}, {1, 6}}, {{1, 2}, {6, 2}, {6, 6}, {1, 6}}},
      {{{1, 2}, {6, 2}, {6, 6}, {1, 6}}, {{3, 2}, {8, 2}, {8, 4}, {3, 4}}},
      {{{1, 1}, {7, 1}, {7, 7}, {4, 1}, {1, 7}}},          // vertex on an edge
      {{{0, 0}, {4, 4}, {8, 0}, {8, 8}, {4, 4}, {0, 8}}},  // touching at a pixel centre
      {{{2, 2}, {6, 2}, {2, 2}}},                          // zero-area spike
      {{{1.5, 1.5}, {7.5, 1.5}, {7.5, 7.5}, {1.5, 7.5}}},
      {{{0, 0}, {8, 0}, {8, 8}, {0, 8}}, {{2, 2}, {6, 2}, {6, 6}, {2, 6}}},  // same orientation
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    for (FillRule rule : kRules) {
      const cv::Mat expected = oracleMask(cases[i], rule, size);
      EXPECT_EQ(cv::countNonZero(expected != rasterize(cases[i], rule, size)), 0)
          << "case " << i << " rule " << toString(rule);
    }
  }
}

}  // namespace
}  // namespace roiclip::opencv
