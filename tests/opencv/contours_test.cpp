// SPDX-License-Identifier: MIT
// roiclip::opencv contour detection, image conversion and edge tracing (moved here from the
// batch pipeline, whose tests still run them end to end).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <roiclip/opencv/contours.hpp>
#include <roiclip/opencv/edges.hpp>

namespace roiclip::opencv {
namespace {

TEST(ToGray8, EveryImageTypeAndItsErrors) {
  cv::Mat gray(40, 50, CV_8UC1);
  cv::randu(gray, 0, 256);
  cv::Mat bgr, bgra, gray16, grayF;
  cv::cvtColor(gray, bgr, cv::COLOR_GRAY2BGR);
  cv::cvtColor(gray, bgra, cv::COLOR_GRAY2BGRA);
  gray.convertTo(gray16, CV_16U, 257.0);  // 255 * 257 = 65535: exact round trip
  gray.convertTo(grayF, CV_32F, 1.0 / 255.0);
  for (const cv::Mat& m : {gray, bgr, bgra, gray16, grayF}) {
    const cv::Mat g = toGray8(m, "x");
    ASSERT_EQ(g.type(), CV_8UC1);
    EXPECT_EQ(cv::countNonZero(g != gray), 0) << m.type();
  }
  EXPECT_EQ(toGray8(gray).data, gray.data);  // 8-bit gray: no copy
  EXPECT_THROW(toGray8(cv::Mat(), "x"), InvalidInputError);
  // Two channels are gray + alpha: the gray channel is used.
  cv::Mat grayAlpha;
  cv::merge(std::vector<cv::Mat>{gray, cv::Mat(gray.size(), CV_8UC1, cv::Scalar(255))}, grayAlpha);
  EXPECT_EQ(cv::countNonZero(toGray8(grayAlpha, "x") != gray), 0);
  EXPECT_THROW(toGray8(cv::Mat(4, 4, CV_8UC(5)), "x"), InvalidInputError);
  EXPECT_THROW(toGray8(cv::Mat(4, 4, CV_32SC1), "x"), InvalidInputError);
  try {
    toGray8(cv::Mat(), "scene.png");
    FAIL();
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("scene.png"), std::string::npos) << e.what();
  }
}

TEST(ToBgr8, GrayAlphaAndColour) {
  cv::Mat gray(8, 9, CV_8UC1);
  cv::randu(gray, 0, 256);
  cv::Mat expected, grayAlpha, bgra;
  cv::cvtColor(gray, expected, cv::COLOR_GRAY2BGR);
  cv::merge(std::vector<cv::Mat>{gray, cv::Mat(gray.size(), CV_8UC1, cv::Scalar(7))}, grayAlpha);
  cv::cvtColor(expected, bgra, cv::COLOR_BGR2BGRA);
  for (const cv::Mat& m : {gray, grayAlpha, expected, bgra}) {
    const cv::Mat bgr = toBgr8(m);
    ASSERT_EQ(bgr.type(), CV_8UC3);
    EXPECT_EQ(cv::norm(bgr, expected, cv::NORM_INF), 0.0) << m.channels();
  }
  EXPECT_NE(toBgr8(expected).data, expected.data);  // always a new image
  EXPECT_THROW(toBgr8(cv::Mat()), InvalidInputError);
}

TEST(DetectContours, GroupsOuterContoursWithTheirHolesOriented) {
  // A dark square with a hole, an island in the hole, and a small dot.
  cv::Mat image(120, 120, CV_8UC1, cv::Scalar(255));
  cv::rectangle(image, cv::Rect(10, 10, 80, 80), cv::Scalar(0), cv::FILLED);
  cv::rectangle(image, cv::Rect(30, 30, 40, 40), cv::Scalar(255), cv::FILLED);
  cv::rectangle(image, cv::Rect(45, 45, 10, 10), cv::Scalar(0), cv::FILLED);
  cv::rectangle(image, cv::Rect(100, 100, 3, 3), cv::Scalar(0), cv::FILLED);
  ContourOptions options;
  const std::vector<ContourGroup> groups = detectContours(image, options);
  ASSERT_EQ(groups.size(), 3u);
  std::size_t rings = 0;
  for (const ContourGroup& g : groups) {
    ASSERT_FALSE(g.rings.empty());
    EXPECT_GE(g.index, 0);
    EXPECT_LT(signedArea(g.rings[0]), 0.0);  // outer: negative, as roiclip outputs
    for (std::size_t h = 1; h < g.rings.size(); ++h) EXPECT_GT(signedArea(g.rings[h]), 0.0);
    rings += g.rings.size();
  }
  EXPECT_EQ(rings, 4u);  // one hole
  // Light polarity finds the background and the hole instead.
  options.polarity = Polarity::Light;
  EXPECT_FALSE(detectContours(image, options).empty());
  // minArea drops the dot (3 x 3 pixels: contour area 4).
  options.polarity = Polarity::Dark;
  options.minArea = 5.0;
  EXPECT_EQ(detectContours(image, options).size(), 2u);
  // approxPolyDP keeps the rectangles' corners.
  options.minArea = 0.0;
  options.approxEpsilon = 1.0;
  for (const ContourGroup& g : detectContours(image, options)) {
    for (const Path& ring : g.rings) EXPECT_LE(ring.size(), 4u);
  }
  options.method = ContourMethod::Adaptive;
  options.adaptiveBlock = 4;
  EXPECT_THROW(detectContours(image, options), InvalidInputError);
  EXPECT_THROW(detectContours(cv::Mat(4, 4, CV_8UC3), ContourOptions{}), InvalidInputError);
  EXPECT_THROW(detectContours(cv::Mat(), ContourOptions{}), InvalidInputError);
}

TEST(Edges, TraceEdgesFollowsChainsAndLoops) {
  cv::Mat edges = cv::Mat::zeros(60, 80, CV_8U);
  cv::line(edges, {5, 5}, {40, 20}, 255, 1, cv::LINE_8);  // an open chain
  cv::circle(edges, {60, 40}, 10, 255, 1, cv::LINE_8);    // a closed loop
  edges.at<uchar>(55, 5) = 255;                           // a single pixel
  const Paths lines = traceEdges(edges);
  ASSERT_EQ(lines.size(), 3u);
  std::size_t pixels = 0;
  for (const auto& l : lines) pixels += l.size();
  // Every edge pixel once, plus the loop's closing point.
  EXPECT_EQ(pixels, static_cast<std::size_t>(cv::countNonZero(edges)) + 1);
  const auto& chain = lines[0];
  EXPECT_EQ(chain.front(), Point(5, 5));
  EXPECT_EQ(chain.back(), Point(40, 20));
  for (std::size_t i = 1; i < chain.size(); ++i) {  // 8-connected steps
    EXPECT_LE(std::abs(chain[i].x - chain[i - 1].x), 1.0);
    EXPECT_LE(std::abs(chain[i].y - chain[i - 1].y), 1.0);
  }
  EXPECT_EQ(lines[1].front(), lines[1].back());  // the loop is closed
  EXPECT_NEAR(polylineLength({lines[1]}), 2 * CV_PI * 10, 0.15 * 2 * CV_PI * 10);
}

TEST(Edges, ApproximatePolylinesKeepsEndsAndCorners) {
  Paths lines = {{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}}, {{5, 5}}};
  approximatePolylines(lines, 0.5);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], (Path{{0, 0}, {3, 0}, {3, 2}}));
  EXPECT_EQ(lines[1].size(), 1u);
  EXPECT_DOUBLE_EQ(polylineLength(lines), 5.0);
}

}  // namespace
}  // namespace roiclip::opencv

// pixelContourArea() stands in for a simplify per contour in roiclip run: on findContours
// output it must be the area under every fill rule. Checked on the bundled scenes and on
// random masks full of pinches, one-pixel lines and diagonal touches (fixed seed).
TEST(PixelContourArea, IsTheAreaUnderEveryFillRuleOfFindContoursOutput) {
  std::vector<cv::Mat> images;
  for (int i = 1; i <= 8; ++i) {
    images.push_back(
        cv::imread(std::string(ROICLIP_IMAGES) + "/scene_0" + std::to_string(i) + ".png",
                   cv::IMREAD_GRAYSCALE));
    ASSERT_FALSE(images.back().empty());
  }
  cv::RNG rng(11);
  for (int k = 0; k < 12; ++k) {
    cv::Mat noise(180, 240, CV_8UC1);
    rng.fill(noise, cv::RNG::UNIFORM, 0, 256);
    if (k % 3 != 0) cv::GaussianBlur(noise, noise, cv::Size(0, 0), 0.6 * (k % 3));
    images.push_back(noise);
  }
  int groups = 0;
  for (const cv::Mat& image : images) {
    roiclip::opencv::ContourOptions options;
    for (const roiclip::opencv::ContourGroup& g : roiclip::opencv::detectContours(image, options)) {
      const double area = roiclip::opencv::pixelContourArea(g);
      for (const roiclip::FillRule rule :
           {roiclip::FillRule::EvenOdd, roiclip::FillRule::NonZero}) {
        const double exact = roiclip::simplify(g.rings, rule).area();
        ASSERT_NEAR(area, exact, 1e-9 * std::max(1.0, exact)) << "group " << g.index;
      }
      ++groups;
    }
  }
  EXPECT_GT(groups, 2000);  // the random masks give thousands of groups
  // A ring that crosses itself is outside the contract: the shoelace sum of a bow-tie cancels.
  roiclip::opencv::ContourGroup bowTie;
  bowTie.rings = {{{0, 0}, {10, 10}, {10, 0}, {0, 10}}};
  EXPECT_EQ(roiclip::opencv::pixelContourArea(bowTie), 0.0);
  EXPECT_EQ(roiclip::simplify(bowTie.rings, roiclip::FillRule::EvenOdd).area(), 50.0);
}
