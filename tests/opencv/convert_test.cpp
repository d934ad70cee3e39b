// SPDX-License-Identifier: MIT
// Conversions between OpenCV contours and roiclip paths / polygon sets.
#include <algorithm>
#include <climits>
#include <cmath>
#include <functional>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include <roiclip/opencv/convert.hpp>
#include <roiclip/opencv/mask_check.hpp>
#include <roiclip/opencv/rasterize.hpp>

namespace roiclip::opencv {
namespace {

std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InvalidInputError& e) {
    return e.what();
  }
  return "<no InvalidInputError>";
}

TEST(FromContours, AcceptsEveryPointType) {
  const std::vector<std::vector<cv::Point>> ints = {{{1, 2}, {3, 4}, {5, 0}}};
  const std::vector<std::vector<cv::Point2f>> floats = {{{1.5f, 2}, {3, 4.25f}, {5, 0}}};
  const std::vector<std::vector<cv::Point2d>> doubles = {{{1.5, 2}, {3, 4.125}, {5, 0}}};
  EXPECT_EQ(fromContours(ints), (Paths{{{1, 2}, {3, 4}, {5, 0}}}));
  EXPECT_EQ(fromContours(floats), (Paths{{{1.5, 2}, {3, 4.25}, {5, 0}}}));
  EXPECT_EQ(fromContours(doubles), (Paths{{{1.5, 2}, {3, 4.125}, {5, 0}}}));
  // std::vector<cv::Mat> of N x 1 CV_32SC2 and of N x 2 single-channel CV_64F.
  const std::vector<cv::Mat> mats = {cv::Mat(ints[0]).clone(),
                                     (cv::Mat_<double>(3, 2) << 0, 1, 2, 3, 4, 5.5)};
  EXPECT_EQ(fromContours(mats), (Paths{{{1, 2}, {3, 4}, {5, 0}}, {{0, 1}, {2, 3}, {4, 5.5}}}));
  EXPECT_EQ(fromContour(ints[0]), (Path{{1, 2}, {3, 4}, {5, 0}}));
  // Vectors of two-int points are read in place (no cv::Mat per contour): the same paths as
  // through cv::Mat, for cv::Vec2i too, with empty contours kept and extreme ints exact.
  const std::vector<std::vector<cv::Point>> several = {
      {{-7, 9}, {INT_MAX, INT_MIN}, {0, 0}}, {}, {{4, 4}}, {{1, 1}, {2, 5}, {6, 2}, {3, -1}}};
  std::vector<cv::Mat> severalMats;
  for (const auto& c : several) severalMats.push_back(cv::Mat(c, true));
  const Paths expected = {{{-7, 9}, {double(INT_MAX), double(INT_MIN)}, {0, 0}},
                          {},
                          {{4, 4}},
                          {{1, 1}, {2, 5}, {6, 2}, {3, -1}}};
  EXPECT_EQ(fromContours(several), expected);
  EXPECT_EQ(fromContours(severalMats), expected);
  std::vector<std::vector<cv::Vec2i>> vecs;
  for (const auto& c : several) {
    auto& v = vecs.emplace_back();
    for (const cv::Point& q : c) v.emplace_back(q.x, q.y);
  }
  EXPECT_EQ(fromContours(vecs), expected);
  EXPECT_TRUE(fromContours(std::vector<std::vector<cv::Point>>{}).empty());
  EXPECT_EQ(fromContours(std::vector<std::vector<cv::Point>>{{}}), Paths{Path{}});
}

TEST(FromContours, AcceptsFindContoursAndApproxPolyDpOutput) {
  cv::Mat img(40, 40, CV_8UC1, cv::Scalar(0));
  cv::rectangle(img, cv::Rect(5, 5, 30, 30), 255, cv::FILLED);
  cv::rectangle(img, cv::Rect(12, 12, 10, 10), 0, cv::FILLED);
  std::vector<std::vector<cv::Point>> contours;
  std::vector<cv::Vec4i> hierarchy;
  cv::findContours(img, contours, hierarchy, cv::RETR_CCOMP, cv::CHAIN_APPROX_SIMPLE);
  ASSERT_EQ(contours.size(), 2u);
  const Paths paths = fromContours(contours);
  ASSERT_EQ(paths.size(), 2u);
  for (std::size_t i = 0; i < paths.size(); ++i) {
    // Orientation is kept: the sign of roiclip's shoelace sum matches cv::contourArea.
    EXPECT_DOUBLE_EQ(signedArea(paths[i]), cv::contourArea(contours[i], true)) << i;
  }
  std::vector<std::vector<cv::Point2f>> approx(1);
  cv::approxPolyDP(contours[0], approx[0], 2.0, true);
  EXPECT_EQ(fromContours(approx).front().size(), approx[0].size());
}

TEST(FromContours, NamesTheBadInput) {
  const std::vector<std::vector<cv::Point2f>> withNan = {{{0, 0}, {1, 1}, {2, 2}},
                                                         {{0, 0}, {1, NAN}, {2, 2}}};
  EXPECT_EQ(messageOf([&] { fromContours(withNan); }),
            "contour 1, point 1: y is not a finite number");
  const std::vector<cv::Mat> wrongDepth = {cv::Mat(3, 1, CV_8UC2, cv::Scalar(1, 2))};
  EXPECT_NE(messageOf([&] { fromContours(wrongDepth); }).find("contour 0: point type CV_8U"),
            std::string::npos);
  const std::vector<cv::Mat> threeChannels = {cv::Mat(3, 1, CV_32SC3, cv::Scalar(1, 2, 3))};
  EXPECT_NE(messageOf([&] { fromContours(threeChannels); }).find("3 channel(s)"),
            std::string::npos);
  const std::vector<cv::Mat> infinite = {cv::Mat(2, 1, CV_64FC2, cv::Scalar(INFINITY, 0))};
  EXPECT_EQ(messageOf([&] { fromContours(infinite); }),
            "contour 0, point 0: x is not a finite number");
  // A single matrix is one contour, not an array of contours.
  EXPECT_NE(messageOf([&] {
              fromContours(cv::Mat(3, 1, CV_32SC2, cv::Scalar(1, 2)));
            }).find("single array"),
            std::string::npos);
}

TEST(FromContours, HierarchyOrientsOuterRingsAndHoles) {
  // Every contour given clockwise on screen (positive shoelace); depths 0, 1, 2, 0.
  const std::vector<std::vector<cv::Point>> contours = {{{0, 0}, {30, 0}, {30, 30}, {0, 30}},
                                                        {{5, 5}, {25, 5}, {25, 25}, {5, 25}},
                                                        {{10, 10}, {20, 10}, {20, 20}, {10, 20}},
                                                        {{40, 0}, {50, 0}, {50, 10}, {40, 10}}};
  const std::vector<cv::Vec4i> hierarchy = {
      {3, -1, 1, -1}, {-1, -1, 2, 0}, {-1, -1, -1, 1}, {-1, 0, -1, -1}};
  const Paths paths = fromContours(contours, hierarchy);
  EXPECT_LT(signedArea(paths[0]), 0);
  EXPECT_GT(signedArea(paths[1]), 0);
  EXPECT_LT(signedArea(paths[2]), 0);
  EXPECT_LT(signedArea(paths[3]), 0);
  // Now NonZero and EvenOdd give the same region.
  EXPECT_DOUBLE_EQ(simplify(paths, FillRule::NonZero).area(), 900 - 400 + 100 + 100);
  EXPECT_DOUBLE_EQ(simplify(paths, FillRule::EvenOdd).area(), 900 - 400 + 100 + 100);
  EXPECT_EQ(fromContours(contours, cv::noArray()), fromContours(contours));
}

TEST(FromContours, RejectsBadHierarchy) {
  const std::vector<std::vector<cv::Point>> two = {{{0, 0}, {1, 0}, {1, 1}},
                                                   {{0, 0}, {1, 0}, {1, 1}}};
  EXPECT_NE(messageOf([&] {
              fromContours(two, std::vector<cv::Vec4i>{{-1, -1, -1, -1}});
            }).find("1 entries for 2 contours"),
            std::string::npos);
  EXPECT_NE(messageOf([&] {
              fromContours(two, std::vector<cv::Vec4i>{{-1, -1, -1, 7}, {-1, -1, -1, -1}});
            }).find("does not exist"),
            std::string::npos);
  EXPECT_NE(messageOf([&] {
              fromContours(two, std::vector<cv::Vec4i>{{-1, -1, -1, 1}, {-1, -1, -1, 0}});
            }).find("cycle"),
            std::string::npos);
  EXPECT_NE(messageOf([&] {
              fromContours(two, std::vector<cv::Vec3i>{{-1, -1, -1}, {-1, -1, -1}});
            }).find("CV_32SC4"),
            std::string::npos);
}

PolygonSet twoPolygonsWithHoles() {
  // An outer square with two holes, an island in the first hole, and a separate triangle:
  // 5 rings.
  return simplify({{{0, 0}, {40, 0}, {40, 40}, {0, 40}},
                   {{4, 4}, {18, 4}, {18, 18}, {4, 18}},
                   {{8, 8}, {12, 8}, {12, 12}, {8, 12}},
                   {{24, 24}, {34, 24}, {34, 34}, {24, 34}},
                   {{50, 0}, {60, 0}, {55.25, 9.75}}},
                  FillRule::EvenOdd);
}

TEST(ToContours, CcompHierarchyLayout) {
  const PolygonSet set = twoPolygonsWithHoles();
  ASSERT_EQ(set.ringCount(), 5u);
  const Contours<cv::Point2d> c = toContours2d(set);
  ASSERT_EQ(c.contours.size(), 5u);
  ASSERT_EQ(c.hierarchy.size(), 5u);
  int topLevel = 0, holes = 0;
  for (std::size_t i = 0; i < c.hierarchy.size(); ++i) {
    const cv::Vec4i h = c.hierarchy[i];
    const double area = signedArea(fromContour(c.contours[i]));
    if (h[3] < 0) {
      ++topLevel;
      EXPECT_LT(area, 0) << i;  // outer contour, as cv::findContours
      // Children are holes whose parent is this contour, linked by next / previous.
      for (int child = h[2], prev = -1; child >= 0; prev = child, child = c.hierarchy[child][0]) {
        EXPECT_EQ(c.hierarchy[child][3], int(i));
        EXPECT_EQ(c.hierarchy[child][1], prev);
      }
    } else {
      ++holes;
      EXPECT_GT(area, 0) << i;
      EXPECT_LT(c.hierarchy[h[3]][3], 0) << "RETR_CCOMP has two levels only";
      EXPECT_EQ(h[2], -1);
    }
    if (h[0] >= 0) {
      EXPECT_EQ(c.hierarchy[h[0]][1], int(i));
    }
    if (h[1] >= 0) {
      EXPECT_EQ(c.hierarchy[h[1]][0], int(i));
    }
  }
  EXPECT_EQ(topLevel, 3);  // square, island, triangle
  EXPECT_EQ(holes, 2);
  // Reading the contours back with their hierarchy gives the same region.
  EXPECT_DOUBLE_EQ(simplify(fromContours(c.contours, c.hierarchy), FillRule::NonZero).area(),
                   set.area());
}

TEST(ToContours, PointTypesAndRounding) {
  const PolygonSet set = twoPolygonsWithHoles();
  const Contours<cv::Point> ints = toContours(set);
  const Contours<cv::Point2f> floats = toContours2f(set);
  const Contours<cv::Point2d> doubles = toContours2d(set);
  ASSERT_EQ(ints.hierarchy, doubles.hierarchy);
  ASSERT_EQ(floats.hierarchy, doubles.hierarchy);
  bool sawFraction = false;
  for (std::size_t i = 0; i < doubles.contours.size(); ++i) {
    ASSERT_EQ(ints.contours[i].size(), doubles.contours[i].size());
    for (std::size_t j = 0; j < doubles.contours[i].size(); ++j) {
      const cv::Point2d p = doubles.contours[i][j];
      EXPECT_EQ(ints.contours[i][j], cv::Point(int(std::lround(p.x)), int(std::lround(p.y))));
      EXPECT_EQ(floats.contours[i][j], cv::Point2f(float(p.x), float(p.y)));
      sawFraction |= p.x != std::floor(p.x);
    }
  }
  EXPECT_TRUE(sawFraction);
}

TEST(ToContours, FixedPointKeepsSubPixelPositions) {
  const PolygonSet set = twoPolygonsWithHoles();
  const FixedPointContours fixed = toFixedPointContours(set, 4);
  EXPECT_EQ(fixed.shift, 4);
  const Contours<cv::Point2d> doubles = toContours2d(set);
  for (std::size_t i = 0; i < doubles.contours.size(); ++i) {
    for (std::size_t j = 0; j < doubles.contours[i].size(); ++j) {
      const cv::Point q = fixed.contours.contours[i][j];
      EXPECT_NEAR(q.x / 16.0, doubles.contours[i][j].x, 1.0 / 32);
      EXPECT_NEAR(q.y / 16.0, doubles.contours[i][j].y, 1.0 / 32);
    }
  }
  EXPECT_THROW(toFixedPointContours(set, 17), InvalidInputError);
  EXPECT_THROW(toFixedPointContours(set, -1), InvalidInputError);
  EXPECT_THROW(toFixedPointContours(Paths{{{1e7, 0}, {0, 1}, {1, 1}}}, 8), InvalidInputError);
  const FixedPointContours roi = toFixedPointContours(Paths{{{0.5, 0}, {3, 0}, {3, 3}}, {}});
  EXPECT_EQ(roi.contours.contours[0][0], cv::Point(128, 0));
  EXPECT_EQ(roi.contours.hierarchy[0], cv::Vec4i(1, -1, -1, -1));
  EXPECT_EQ(roi.contours.hierarchy[1], cv::Vec4i(-1, 0, -1, -1));
}

TEST(ToContours, ThinPartsVanishInsteadOfTouchingThemselves) {
  // A simple thin ring whose two long sides are 0.4 px apart: rounded vertex by vertex they
  // would coincide (a ring of area 0 touching itself). Snap-rounded, the part vanishes.
  const PolygonSet set = simplify({{{0, 0}, {10, 0.1}, {10, 0.4}, {0, 0.45}}}, FillRule::NonZero);
  ASSERT_EQ(set.polygons.size(), 1u);
  EXPECT_GT(set.area(), 3.0);
  const Contours<cv::Point> ints = toContours(set);
  EXPECT_TRUE(ints.contours.empty());
  EXPECT_TRUE(ints.hierarchy.empty());
}

// Sign of (b - a) x (c - a) for integer points.
int turn(cv::Point a, cv::Point b, cv::Point c) {
  const long long v = (long long)(b.x - a.x) * (c.y - a.y) - (long long)(b.y - a.y) * (c.x - a.x);
  return (v > 0) - (v < 0);
}

// The number of pairs of contour edges that cross or overlap along a stretch (exact, integer).
// Edges of rings that touch at a shared vertex are fine.
int crossingEdgePairs(const std::vector<std::vector<cv::Point>>& contours) {
  struct Edge {
    cv::Point a, b;
  };
  std::vector<Edge> edges;
  for (const auto& c : contours) {
    for (std::size_t i = 0; i < c.size(); ++i) edges.push_back({c[i], c[(i + 1) % c.size()]});
  }
  const auto between = [](cv::Point a, cv::Point b, cv::Point p) {  // p on line ab, inside ab
    return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
           p.y <= std::max(a.y, b.y) && p != a && p != b;
  };
  int count = 0;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const Edge& e = edges[i];
      const Edge& f = edges[j];
      const int o1 = turn(e.a, e.b, f.a), o2 = turn(e.a, e.b, f.b);
      const int o3 = turn(f.a, f.b, e.a), o4 = turn(f.a, f.b, e.b);
      const bool proper = o1 * o2 < 0 && o3 * o4 < 0;
      // A vertex inside another edge (a T, or a collinear overlap).
      const bool touch = (o1 == 0 && between(e.a, e.b, f.a)) ||
                         (o2 == 0 && between(e.a, e.b, f.b)) ||
                         (o3 == 0 && between(f.a, f.b, e.a)) || (o4 == 0 && between(f.a, f.b, e.b));
      count += proper || touch || (e.a == f.a && e.b == f.b) || (e.a == f.b && e.b == f.a);
    }
  }
  return count;
}

// The set's vertices times `scale`, each rounded on its own (what the conversions used to do).
std::vector<std::vector<cv::Point>> roundEachVertex(const PolygonSet& set, double scale) {
  std::vector<std::vector<cv::Point>> out;
  for (const auto& c : toContours2d(set).contours) {
    out.emplace_back();
    for (const cv::Point2d& p : c) {
      out.back().emplace_back(int(std::lround(p.x * scale)), int(std::lround(p.y * scale)));
    }
  }
  return out;
}

// Dense random self-intersecting polygons in [0, 30]^2 (coordinates on the 1/`units` grid),
// simplified and clipped (3 sets per pair), with sub-pixel crossings.
std::vector<PolygonSet> denseRandomSets(unsigned seed, int pairs, int units) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coord(0, 30 * units);
  const auto polygon = [&](int n) {
    Path p;
    for (int i = 0; i < n; ++i)
      p.emplace_back(coord(rng) / double(units), coord(rng) / double(units));
    return p;
  };
  std::vector<PolygonSet> sets;
  for (int iter = 0; iter < pairs; ++iter) {
    const Paths a = {polygon(10 + iter % 25)};
    const Paths b = {polygon(4 + iter % 6)};
    sets.push_back(simplify(a, FillRule::EvenOdd));
    sets.push_back(intersect(a, b));
    sets.push_back(subtract(a, b, FillRule::NonZero));
  }
  return sets;
}

TEST(ToContours, FillPolyNeverSeesACrossing) {
  int naiveCrossing = 0, cases = 0;
  double areaError = 0;
  for (const PolygonSet& set : denseRandomSets(77, 80, 256)) {
    ++cases;
    const Contours<cv::Point> ints = toContours(set);
    ASSERT_EQ(crossingEdgePairs(ints.contours), 0) << "case " << cases;
    // Rounded vertex by vertex, many of the same sets cross.
    naiveCrossing += crossingEdgePairs(roundEachVertex(set, 1.0)) > 0;
    // fillPoly draws the rounded region: its area (pixel count) is close to the exact one.
    cv::Mat mask(32, 32, CV_8UC1, cv::Scalar(0));
    if (!ints.contours.empty()) cv::fillPoly(mask, ints.contours, cv::Scalar(255));
    double rounded = 0;
    for (const auto& c : ints.contours) rounded -= cv::contourArea(c, true);
    areaError = std::max(areaError, std::fabs(rounded - set.area()) / (set.area() + 1));
    EXPECT_GE(cv::countNonZero(mask), rounded * 0.5) << "case " << cases;
  }
  EXPECT_GT(naiveCrossing, 30);
  EXPECT_LT(areaError, 0.5);
}

double perimeter(const PolygonSet& set) {
  double total = 0;
  for (const auto& c : toContours2f(set).contours) total += cv::arcLength(c, true);
  return total;
}

TEST(ToFixedPointContours, FillPolyNeverSeesACrossing) {
  // As ToContours.FillPolyNeverSeesACrossing, at sub-pixel shifts: coordinates on a 1/4096 px
  // grid, so crossings and vertices lie between the 2^-shift steps.
  int naiveCrossing[17] = {}, cases = 0;
  for (const PolygonSet& set : denseRandomSets(78, 60, 4096)) {
    ++cases;
    for (const int shift : {2, 4, kDefaultShift}) {
      const double scale = std::ldexp(1.0, shift);
      const FixedPointContours fixed = toFixedPointContours(set, shift);
      ASSERT_EQ(fixed.shift, shift);
      ASSERT_EQ(crossingEdgePairs(fixed.contours.contours), 0)
          << "case " << cases << " shift " << shift;
      ASSERT_EQ(fixed.contours.hierarchy.size(), fixed.contours.contours.size());
      // The rounded region is within the snap-rounding bound of the exact one.
      double rounded = 0;
      for (const auto& c : fixed.contours.contours) rounded -= cv::contourArea(c, true);
      rounded /= scale * scale;
      EXPECT_LE(std::fabs(rounded - set.area()), perimeter(set) / scale / 2)
          << "case " << cases << " shift " << shift;
      // Rounded vertex by vertex, some of the same sets cross.
      naiveCrossing[shift] += crossingEdgePairs(roundEachVertex(set, scale)) > 0;
    }
    // fillPolygonSet() (cv::fillPoly at kDefaultShift) fills about the same area.
    cv::Mat mask(32, 32, CV_8UC1, cv::Scalar(0));
    fillPolygonSet(mask, set, cv::Scalar(255));
    EXPECT_GE(cv::countNonZero(mask), set.area() * 0.5) << "case " << cases;
  }
  EXPECT_GT(naiveCrossing[2], 30);
  EXPECT_GT(naiveCrossing[4], 10);
  EXPECT_GT(naiveCrossing[kDefaultShift], 0);
  std::cout << "rounded vertex by vertex, sets with crossing edges: " << naiveCrossing[2]
            << " at shift 2, " << naiveCrossing[4] << " at shift 4, "
            << naiveCrossing[kDefaultShift] << " at shift " << kDefaultShift << " (of " << cases
            << ")\n";
}

TEST(DrawPolygonSet, FillsSubPixelGeometry) {
  const PolygonSet set = twoPolygonsWithHoles();
  cv::Mat filled(48, 64, CV_8UC1, cv::Scalar(0));
  fillPolygonSet(filled, set, cv::Scalar(255));
  // Interior pixels of the island, the holes and the triangle.
  EXPECT_EQ(filled.at<std::uint8_t>(10, 10), 255);  // island
  EXPECT_EQ(filled.at<std::uint8_t>(6, 6), 0);      // first hole
  EXPECT_EQ(filled.at<std::uint8_t>(29, 29), 0);    // second hole
  EXPECT_EQ(filled.at<std::uint8_t>(2, 2), 255);    // outer ring
  EXPECT_EQ(filled.at<std::uint8_t>(3, 55), 255);   // triangle
  EXPECT_EQ(filled.at<std::uint8_t>(20, 55), 0);
  cv::Mat outlines(48, 64, CV_8UC3, cv::Scalar::all(0));
  drawPolygonSet(outlines, set, cv::Scalar(0, 0, 255));
  cv::Mat red;
  cv::extractChannel(outlines, red, 2);
  EXPECT_EQ(red.at<std::uint8_t>(0, 20), 255);
  EXPECT_EQ(red.at<std::uint8_t>(10, 10), 0);
  EXPECT_GT(cv::countNonZero(red), 4 * 40);
  // An empty set draws nothing and does not throw.
  fillPolygonSet(filled, PolygonSet{}, cv::Scalar(0));
}

TEST(GroupContours, OuterContoursWithTheirHolesInFindContoursOrder) {
  // A frame with three holes, an island in one of them, a second frame with one hole, a dot.
  cv::Mat img(80, 120, CV_8UC1, cv::Scalar(0));
  cv::rectangle(img, cv::Rect(5, 5, 60, 60), 255, cv::FILLED);
  cv::rectangle(img, cv::Rect(10, 10, 20, 20), 0, cv::FILLED);
  cv::rectangle(img, cv::Rect(15, 15, 6, 6), 255, cv::FILLED);
  cv::rectangle(img, cv::Rect(40, 10, 15, 15), 0, cv::FILLED);
  cv::rectangle(img, cv::Rect(10, 40, 40, 15), 0, cv::FILLED);
  cv::rectangle(img, cv::Rect(75, 5, 30, 30), 255, cv::FILLED);
  cv::rectangle(img, cv::Rect(82, 12, 10, 10), 0, cv::FILLED);
  cv::rectangle(img, cv::Rect(100, 60, 3, 3), 255, cv::FILLED);
  std::vector<std::vector<cv::Point>> contours;
  std::vector<cv::Vec4i> hierarchy;
  cv::findContours(img, contours, hierarchy, cv::RETR_CCOMP, cv::CHAIN_APPROX_SIMPLE);
  const std::vector<ContourGroup> groups = groupContours(contours, hierarchy);
  // The same as walking the hierarchy: each top-level contour, then its firstChild/next chain.
  const Paths rings = fromContours(contours, hierarchy);
  std::vector<ContourGroup> walked;
  for (std::size_t i = 0; i < contours.size(); ++i) {
    if (hierarchy[i][3] != -1) continue;
    ContourGroup g{int(i), {rings[i]}};
    for (int h = hierarchy[i][2]; h >= 0; h = hierarchy[std::size_t(h)][0]) {
      g.rings.push_back(rings[std::size_t(h)]);
    }
    walked.push_back(g);
  }
  ASSERT_EQ(groups.size(), 4u);  // two frames, the island, the dot
  ASSERT_EQ(groups.size(), walked.size());
  std::size_t mostHoles = 0;
  for (std::size_t i = 0; i < groups.size(); ++i) {
    EXPECT_EQ(groups[i].index, walked[i].index);
    EXPECT_EQ(groups[i].rings, walked[i].rings) << i;
    EXPECT_LT(signedArea(groups[i].rings[0]), 0);
    for (std::size_t h = 1; h < groups[i].rings.size(); ++h) {
      EXPECT_GT(signedArea(groups[i].rings[h]), 0);
    }
    mostHoles = std::max(mostHoles, groups[i].rings.size() - 1);
  }
  EXPECT_EQ(mostHoles, 3u);

  // RETR_TREE: the island (depth 2) is a group of its own too; the same region in total.
  std::vector<std::vector<cv::Point>> treeContours;
  std::vector<cv::Vec4i> tree;
  cv::findContours(img, treeContours, tree, cv::RETR_TREE, cv::CHAIN_APPROX_SIMPLE);
  const std::vector<ContourGroup> treeGroups = groupContours(treeContours, tree);
  ASSERT_EQ(treeGroups.size(), 4u);
  double ccompArea = 0, treeArea = 0;
  for (const ContourGroup& g : groups) ccompArea += simplify(g.rings, FillRule::NonZero).area();
  for (const ContourGroup& g : treeGroups) treeArea += simplify(g.rings, FillRule::NonZero).area();
  EXPECT_DOUBLE_EQ(treeArea, ccompArea);

  // No hierarchy: every contour alone, its orientation kept.
  const std::vector<ContourGroup> alone = groupContours(contours, cv::noArray());
  ASSERT_EQ(alone.size(), contours.size());
  for (std::size_t i = 0; i < alone.size(); ++i) {
    EXPECT_EQ(alone[i].index, int(i));
    EXPECT_EQ(alone[i].rings, Paths{fromContour(contours[i])});
  }
}

TEST(GroupContours, HandMadeHierarchyMayListAHoleFirst) {
  const std::vector<std::vector<cv::Point>> contours = {{{5, 5}, {5, 10}, {10, 10}, {10, 5}},
                                                        {{0, 0}, {0, 20}, {20, 20}, {20, 0}}};
  const std::vector<cv::Vec4i> hierarchy = {{-1, -1, -1, 1}, {-1, -1, 0, -1}};
  const std::vector<ContourGroup> groups = groupContours(contours, hierarchy);
  ASSERT_EQ(groups.size(), 1u);
  EXPECT_EQ(groups[0].index, 1);
  ASSERT_EQ(groups[0].rings.size(), 2u);
  EXPECT_DOUBLE_EQ(signedArea(groups[0].rings[0]), -400);
  EXPECT_DOUBLE_EQ(signedArea(groups[0].rings[1]), 25);
  EXPECT_THROW(groupContours(contours, std::vector<cv::Vec4i>{{-1, -1, -1, 1}, {-1, -1, -1, 0}}),
               InvalidInputError);
}

// Two squares wound the same way overlapping in [10, 20] x [0, 20], and a third wound the other
// way: winding 1 and 2 inside the first two, -1 inside the third.
const Paths kWound = {{{0, 0}, {20, 0}, {20, 20}, {0, 20}},
                      {{10, 0}, {30, 0}, {30, 20}, {10, 20}},
                      {{40, 0}, {40, 20}, {55, 20}, {55, 0}}};

TEST(FillPaths, EvenOddIsOneFillPolyCallOfThePaths) {
  cv::Mat got(30, 64, CV_8UC1, cv::Scalar(0)), want = got.clone();
  fillPaths(got, kWound, FillRule::EvenOdd, cv::Scalar(255));
  const FixedPointContours c = toFixedPointContours(kWound);
  cv::fillPoly(want, c.contours.contours, cv::Scalar(255), cv::LINE_8, c.shift);
  EXPECT_EQ(cv::countNonZero(got != want), 0);
  EXPECT_EQ(got.at<std::uint8_t>(10, 15), 0);    // winding 2
  EXPECT_EQ(got.at<std::uint8_t>(10, 5), 255);   // winding 1
  EXPECT_EQ(got.at<std::uint8_t>(10, 45), 255);  // winding -1
}

TEST(FillPaths, OtherRulesFillTheExactRegionOfTheRule) {
  struct Case {
    FillRule rule;
    bool w2, w1, wMinus1;
  };
  for (const Case& k :
       {Case{FillRule::NonZero, true, true, true}, Case{FillRule::Positive, true, true, false},
        Case{FillRule::Negative, false, false, true}}) {
    cv::Mat got(30, 64, CV_8UC3, cv::Scalar::all(0)), want = got.clone();
    fillPaths(got, kWound, k.rule, cv::Scalar(0, 200, 0));
    fillPolygonSet(want, simplify(kWound, k.rule), cv::Scalar(0, 200, 0));
    EXPECT_EQ(cv::norm(got, want, cv::NORM_INF), 0) << toString(k.rule);
    EXPECT_EQ(got.at<cv::Vec3b>(10, 15)[1] == 200, k.w2) << toString(k.rule);
    EXPECT_EQ(got.at<cv::Vec3b>(10, 5)[1] == 200, k.w1) << toString(k.rule);
    EXPECT_EQ(got.at<cv::Vec3b>(10, 45)[1] == 200, k.wMinus1) << toString(k.rule);
  }
  // On random self-intersecting paths every rule's fill is the exact region off OpenCV's band.
  std::mt19937 rng(16);
  std::uniform_real_distribution<double> coord(2, 78);
  for (int trial = 0; trial < 20; ++trial) {
    Paths paths(2);
    for (Path& p : paths) {
      for (int i = 0; i < 9; ++i) p.emplace_back(coord(rng), coord(rng));
    }
    for (FillRule rule :
         {FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive, FillRule::Negative}) {
      cv::Mat filled(80, 80, CV_8UC1, cv::Scalar(0));
      fillPaths(filled, paths, rule, cv::Scalar(255));
      const cv::Mat exact = rasterize(paths, rule, filled.size());
      const MaskComparison c = compareMasks(exact, filled, kOpenCvBand, paths);
      EXPECT_TRUE(c.agreesOffBand()) << toString(rule) << " trial " << trial << ": " << c;
    }
  }
}

TEST(DrawPaths, ClosedOrOpen) {
  const Paths corner = {{{2, 2}, {20, 2}, {20, 20}}};
  cv::Mat closed(24, 24, CV_8UC1, cv::Scalar(0)), open = closed.clone();
  drawPaths(closed, corner, cv::Scalar(255));
  drawPaths(open, corner, cv::Scalar(255), 1, cv::LINE_8, false);
  EXPECT_EQ(closed.at<std::uint8_t>(11, 11), 255);  // on the closing diagonal
  EXPECT_EQ(open.at<std::uint8_t>(11, 11), 0);
  EXPECT_EQ(open.at<std::uint8_t>(2, 11), 255);
  EXPECT_EQ(open.at<std::uint8_t>(11, 20), 255);
  // drawPolygonSet draws the set's rings closed.
  cv::Mat rings(24, 24, CV_8UC1, cv::Scalar(0));
  drawPolygonSet(rings, simplify(corner, FillRule::NonZero), cv::Scalar(255));
  EXPECT_EQ(cv::countNonZero(rings != closed), 0);
  drawPaths(open, Paths{Path{}}, cv::Scalar(255));  // empty paths draw nothing
}

}  // namespace
}  // namespace roiclip::opencv
