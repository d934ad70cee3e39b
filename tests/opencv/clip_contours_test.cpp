// SPDX-License-Identifier: MIT
// Clipping at the OpenCV boundary: contours + hierarchy in, RETR_CCOMP contours out; contour
// groups (outer contour + holes) clipped one by one, keeping their source index.
#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include <roiclip/opencv/opencv.hpp>

namespace roiclip::opencv {
namespace {

// Three dark blobs on white: a frame with two holes and an island in one hole, a disc, and a
// square that the ROI below misses.
cv::Mat blobs() {
  cv::Mat image(120, 160, CV_8UC1, cv::Scalar(0));
  cv::rectangle(image, cv::Rect(10, 10, 70, 90), cv::Scalar(255), cv::FILLED);
  cv::rectangle(image, cv::Rect(20, 20, 30, 30), cv::Scalar(0), cv::FILLED);
  cv::rectangle(image, cv::Rect(28, 28, 10, 10), cv::Scalar(255), cv::FILLED);
  cv::rectangle(image, cv::Rect(20, 60, 50, 25), cv::Scalar(0), cv::FILLED);
  cv::circle(image, cv::Point(110, 40), 20, cv::Scalar(255), cv::FILLED);
  cv::rectangle(image, cv::Rect(130, 95, 20, 20), cv::Scalar(255), cv::FILLED);
  return image;
}

// Area of contours in roiclip's orientation (outer rings negative, holes positive). Re-reading
// them with simplify() would snap the clip's crossing vertices to the grid again.
double areaOf(const std::vector<std::vector<cv::Point2d>>& contours) {
  double area = 0;
  for (const auto& c : contours) area -= signedArea(fromContour(c));
  return area;
}

struct Found {
  std::vector<std::vector<cv::Point>> contours;
  std::vector<cv::Vec4i> hierarchy;
};
Found findContoursOf(const cv::Mat& image, int mode = cv::RETR_CCOMP) {
  Found f;
  cv::findContours(image, f.contours, f.hierarchy, mode, cv::CHAIN_APPROX_SIMPLE);
  return f;
}

// A sub-pixel quad through the frame's holes and the disc, missing the square.
const Paths kRoi = {{{12.5, 14.25}, {125.75, 12.5}, {118.25, 82.5}, {12.125, 96.5}}};

TEST(ClipContours, IntersectIsTheCoreClipAsCcompContours) {
  const Found f = findContoursOf(blobs());
  ASSERT_GE(f.contours.size(), 6u);
  const PolygonSet expected = roiclip::intersect(fromContours(f.contours, f.hierarchy), kRoi);
  ASSERT_GT(expected.ringCount(), expected.polygons.size());  // holes survive the clip

  const Contours<cv::Point2d> exact = intersect<cv::Point2d>(f.contours, f.hierarchy, kRoi);
  const Contours<cv::Point2d> wanted = toContours2d(expected);
  EXPECT_EQ(exact.contours, wanted.contours);
  EXPECT_EQ(exact.hierarchy, wanted.hierarchy);
  const Contours<cv::Point2f> floats = intersect<cv::Point2f>(f.contours, f.hierarchy, kRoi);
  EXPECT_EQ(floats.contours, toContours2f(expected).contours);

  // The default point type is cv::Point, what cv::drawContours takes.
  static_assert(
      std::is_same_v<decltype(intersect(f.contours, f.hierarchy, kRoi)), Contours<cv::Point>>);
  const Contours<cv::Point> ints = intersect(f.contours, f.hierarchy, kRoi);
  EXPECT_EQ(ints.contours, toContours(expected).contours);
  EXPECT_EQ(ints.hierarchy, wanted.hierarchy);
  // Drawn filled with its hierarchy, it is the clipped region (off OpenCV's drawing band).
  cv::Mat drawn(120, 160, CV_8UC1, cv::Scalar(0));
  cv::drawContours(drawn, ints.contours, -1, cv::Scalar(255), cv::FILLED, cv::LINE_8,
                   ints.hierarchy);
  const Paths edges = [&] {
    Paths e = fromContours(f.contours);
    e.insert(e.end(), kRoi.begin(), kRoi.end());
    return e;
  }();
  const MaskComparison c =
      compareMasks(rasterize(expected, drawn.size()), drawn, kOpenCvBand, edges);
  EXPECT_TRUE(c.agreesOffBand()) << c;
  EXPECT_GT(c.both, 1000);
}

TEST(ClipContours, ClipTakesTheOperationAndRules) {
  const Found f = findContoursOf(blobs());
  const Paths subject = fromContours(f.contours, f.hierarchy);
  for (ClipOp op : {ClipOp::Intersection, ClipOp::Union, ClipOp::Difference, ClipOp::Xor}) {
    const Contours<cv::Point2d> got =
        clip<cv::Point2d>(op, f.contours, f.hierarchy, kRoi, FillRule::NonZero);
    const PolygonSet want = roiclip::clip(op, subject, kRoi, FillRule::NonZero, FillRule::EvenOdd);
    EXPECT_EQ(got.contours, toContours2d(want).contours) << toString(op);
  }
  const double withHierarchy = roiclip::intersect(subject, kRoi).area();
  // Without a hierarchy the contours keep their orientation. Give every contour the same
  // orientation: under non-zero the hierarchy then decides whether holes stay holes.
  std::vector<std::vector<cv::Point>> same = f.contours;
  for (auto& c : same) {
    if (cv::contourArea(c, true) > 0) std::reverse(c.begin(), c.end());
  }
  const Contours<cv::Point2d> oriented =
      intersect<cv::Point2d>(same, f.hierarchy, kRoi, FillRule::NonZero);
  EXPECT_NEAR(areaOf(oriented.contours), withHierarchy, 1e-9);
  const Contours<cv::Point2d> raw =
      intersect<cv::Point2d>(same, cv::noArray(), kRoi, FillRule::NonZero);
  EXPECT_EQ(raw.contours,
            toContours2d(roiclip::intersect(fromContours(same), kRoi, FillRule::NonZero)).contours);
  EXPECT_GT(areaOf(raw.contours), withHierarchy + 100);  // the holes are filled
  // The region's own rule is used: a doubled ROI is empty under even-odd.
  const Paths doubled = {kRoi[0], kRoi[0]};
  EXPECT_TRUE(intersect(f.contours, f.hierarchy, doubled).contours.empty());
  EXPECT_FALSE(intersect(f.contours, f.hierarchy, doubled, FillRule::EvenOdd, FillRule::NonZero)
                   .contours.empty());
  // The core's clip() and intersect() are still found unqualified in roiclip::opencv.
  EXPECT_NEAR(intersect(subject, kRoi).area(), withHierarchy, 0.0);
  EXPECT_NEAR(
      clip(ClipOp::Intersection, subject, kRoi, FillRule::EvenOdd, FillRule::EvenOdd).area(),
      withHierarchy, 0.0);
}

TEST(ClipGroups, EveryGroupClippedAloneKeepsItsSourceIndex) {
  const Found f = findContoursOf(blobs());
  const std::vector<ContourGroup> groups = groupContours(f.contours, f.hierarchy);
  const std::vector<ClippedGroup> clipped = clipGroups(ClipOp::Intersection, groups, kRoi);
  ASSERT_EQ(clipped.size(), groups.size());
  int empty = 0;
  double sum = 0;
  for (std::size_t i = 0; i < groups.size(); ++i) {
    EXPECT_EQ(clipped[i].index, groups[i].index);
    const PolygonSet want = roiclip::intersect(groups[i].rings, kRoi);
    EXPECT_EQ(clipped[i].polygons.toPaths(), want.toPaths()) << i;
    // The pieces lie inside the contour they came from.
    for (const Polygon& p : clipped[i].polygons.polygons) {
      const cv::Point2d q = cv::Point2d(p.outer[0].x, p.outer[0].y);
      EXPECT_GE(cv::pointPolygonTest(f.contours[std::size_t(groups[i].index)], q, false), 0);
    }
    empty += clipped[i].polygons.empty() ? 1 : 0;
    sum += clipped[i].polygons.area();
  }
  EXPECT_EQ(empty, 1);  // the square outside the ROI
  // The groups do not overlap here, so their pieces add up to the clip of all contours.
  EXPECT_NEAR(sum, roiclip::intersect(fromContours(f.contours, f.hierarchy), kRoi).area(), 1e-6);
  // Another operation and rule pass through.
  const std::vector<ClippedGroup> outside =
      clipGroups(ClipOp::Difference, groups, kRoi, FillRule::NonZero);
  EXPECT_EQ(outside[0].polygons.toPaths(),
            roiclip::subtract(groups[0].rings, kRoi, FillRule::NonZero).toPaths());
}

TEST(ClipGroups, ErrorsNameTheSourceContour) {
  std::vector<ContourGroup> groups = {{3, {{{0, 0}, {0, 10}, {10, 10}, {10, 0}}}},
                                      {7, {{{0, 0}, {0, 10}, {NAN, 10}}}}};  // NaN: any
  // finite coordinate fits the default, fitted grid
  try {
    (void)clipGroups(ClipOp::Intersection, groups, kRoi);
    FAIL() << "no InvalidInputError";
  } catch (const InvalidInputError& e) {
    EXPECT_EQ(e.location().source, "contour 7");
    EXPECT_EQ(e.location().operand, Operand::Subject);
    EXPECT_EQ(e.location().path, 0u);
    EXPECT_EQ(e.location().vertex, 2u);
  }
  // Errors in the region are the region's.
  groups.pop_back();
  const Paths badRoi = {{{0, 0}, {std::numeric_limits<double>::quiet_NaN(), 1}, {1, 1}}};
  try {
    (void)clipGroups(ClipOp::Intersection, groups, badRoi);
    FAIL() << "no InvalidInputError";
  } catch (const InvalidInputError& e) {
    EXPECT_EQ(e.location().source, "");
    EXPECT_EQ(e.location().operand, Operand::Clip);
  }
}

}  // namespace
}  // namespace roiclip::opencv
