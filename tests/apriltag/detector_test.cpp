// SPDX-License-Identifier: MIT
// Detector wrapper: corner order, pixel convention, buffer handling, ownership, threads, errors.
#include <roiclip/apriltag/detector.hpp>

#include <array>
#include <cmath>
#include <cstring>
#include <thread>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#ifdef ROICLIP_TEST_ARUCO
#include <opencv2/aruco.hpp>
#endif

// Only to demonstrate the in-place blur trap on the raw library (never in public headers).
extern "C" {
#include <apriltag/apriltag.h>
#include <apriltag/tag36h11.h>
}

namespace ra = roiclip::apriltag;
using ra::Corner;

namespace {

constexpr int kCell = 12;  // pixels per tag cell in the synthetic images

// A white canvas with tag `id` drawn axis-aligned, one cell = kCell pixels, its rendered image's
// top-left pixel at (ox, oy). Returns the canvas; `border` gets the black border offset in cells.
cv::Mat canvasWithTag(int id, int ox, int oy, int rotateCode = -1, const char* family = "tag36h11",
                      int* totalCells = nullptr, int* borderCells = nullptr) {
  int border = 0;
  cv::Mat tag = ra::renderTag(family, id, &border);
  if (rotateCode >= 0) cv::rotate(tag, tag, rotateCode);
  cv::Mat big;
  cv::resize(tag, big, cv::Size(), kCell, kCell, cv::INTER_NEAREST);
  cv::Mat canvas(360, 400, CV_8UC1, cv::Scalar(255));
  big.copyTo(canvas(cv::Rect(ox, oy, big.cols, big.rows)));
  // A symmetric blur keeps every edge where it was but gives the detector a gradient to fit;
  // on a perfect step edge sub-pixel localisation is ambiguous by up to ~0.15 px.
  cv::GaussianBlur(canvas, canvas, cv::Size(0, 0), 1.0);
  if (totalCells) *totalCells = tag.cols;
  if (borderCells) *borderCells = border;
  return canvas;
}

double dist(glm::dvec2 a, glm::dvec2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

// refine_edges moves corners of an axis-aligned tag ~0.1 px outwards (see RefineEdgesBias);
// without it the quad fit is exact here, so the convention tests can be tight.
ra::DetectorOptions unrefined() {
  ra::DetectorOptions options;
  options.refineEdges = false;
  return options;
}

// Pixel-centre coordinates of the black border's corners for canvasWithTag(ox, oy): the border
// starts `offset` cells in and spans `border` cells. A pixel's left edge is at x - 0.5.
struct Box {
  double left, top, right, bottom;
};
Box borderBox(int ox, int oy, int total, int border) {
  const int offset = (total - border) / 2;
  return {ox + offset * kCell - 0.5, oy + offset * kCell - 0.5,
          ox + (offset + border) * kCell - 0.5, oy + (offset + border) * kCell - 0.5};
}

TEST(AprilTagDetector, CornerOrderOfAnUprightTagIsBottomLeftBottomRightTopRightTopLeft) {
  int total = 0, border = 0;
  const cv::Mat image = canvasWithTag(7, 40, 30, -1, "tag36h11", &total, &border);
  const std::vector<ra::Detection> found = ra::Detector(unrefined()).detect(image);
  ASSERT_EQ(found.size(), 1u);
  const ra::Detection& d = found[0];
  EXPECT_EQ(d.id, 7);
  EXPECT_EQ(d.family, "tag36h11");
  EXPECT_EQ(d.hamming, 0);
  const Box b = borderBox(40, 30, total, border);
  EXPECT_LT(dist(d.corner(Corner::BottomLeft), {b.left, b.bottom}), 0.05);
  EXPECT_LT(dist(d.corner(Corner::BottomRight), {b.right, b.bottom}), 0.05);
  EXPECT_LT(dist(d.corner(Corner::TopRight), {b.right, b.top}), 0.05);
  EXPECT_LT(dist(d.corner(Corner::TopLeft), {b.left, b.top}), 0.05);
  // Counter-clockwise on screen (y down) means a negative shoelace sum.
  double shoelace = 0;
  for (int k = 0; k < 4; ++k) {
    const glm::dvec2 p = d.corners[k], q = d.corners[(k + 1) % 4];
    shoelace += p.x * q.y - q.x * p.y;
  }
  EXPECT_LT(shoelace, 0);
}

TEST(AprilTagDetector, CornersFollowTheTagWhenItIsRotated) {
  int total = 0, border = 0;
  // Rotated 90 degrees clockwise: the tag's top-left corner is now at the top right of the box.
  const cv::Mat image =
      canvasWithTag(7, 40, 30, cv::ROTATE_90_CLOCKWISE, "tag36h11", &total, &border);
  const std::vector<ra::Detection> found = ra::Detector(unrefined()).detect(image);
  ASSERT_EQ(found.size(), 1u);
  const ra::Detection& d = found[0];
  EXPECT_EQ(d.id, 7);
  const Box b = borderBox(40, 30, total, border);
  EXPECT_LT(dist(d.corner(Corner::TopLeft), {b.right, b.top}), 0.05);
  EXPECT_LT(dist(d.corner(Corner::TopRight), {b.right, b.bottom}), 0.05);
  EXPECT_LT(dist(d.corner(Corner::BottomRight), {b.left, b.bottom}), 0.05);
  EXPECT_LT(dist(d.corner(Corner::BottomLeft), {b.left, b.top}), 0.05);
}

TEST(ArucoOrder, ArucoCornersStartTopLeftAndRunClockwise) {
  int total = 0, border = 0;
  const cv::Mat upright = canvasWithTag(7, 40, 30, -1, "tag36h11", &total, &border);
  const std::vector<ra::Detection> found = ra::Detector(unrefined()).detect(upright);
  ASSERT_EQ(found.size(), 1u);
  const Box b = borderBox(40, 30, total, border);
  const std::array<glm::dvec2, 4> aruco = ra::arucoCorners(found[0]);
  EXPECT_LT(dist(aruco[0], {b.left, b.top}), 0.05);
  EXPECT_LT(dist(aruco[1], {b.right, b.top}), 0.05);
  EXPECT_LT(dist(aruco[2], {b.right, b.bottom}), 0.05);
  EXPECT_LT(dist(aruco[3], {b.left, b.bottom}), 0.05);
  // Clockwise on screen (y down) is a positive shoelace sum: the reverse of libapriltag's order.
  double shoelace = 0;
  for (int k = 0; k < 4; ++k) {
    shoelace += aruco[k].x * aruco[(k + 1) % 4].y - aruco[(k + 1) % 4].x * aruco[k].y;
    EXPECT_EQ(aruco[k], found[0].corners[3 - k]) << k;
  }
  EXPECT_GT(shoelace, 0);

  // Rotated 90 degrees clockwise: the tag's own top-left corner is now at the top right of the
  // box, and cv::aruco's order follows the tag, not the screen.
  const cv::Mat rotated = canvasWithTag(7, 40, 30, cv::ROTATE_90_CLOCKWISE);
  const std::vector<ra::Detection> turned = ra::Detector(unrefined()).detect(rotated);
  ASSERT_EQ(turned.size(), 1u);
  const std::array<glm::dvec2, 4> r = ra::arucoCorners(turned[0]);
  EXPECT_LT(dist(r[0], {b.right, b.top}), 0.05);
  EXPECT_LT(dist(r[1], {b.right, b.bottom}), 0.05);
  EXPECT_LT(dist(r[2], {b.left, b.bottom}), 0.05);
  EXPECT_LT(dist(r[3], {b.left, b.top}), 0.05);
}

TEST(ArucoOrder, DetectionFromArucoCornersRoundTrips) {
  const cv::Mat image = canvasWithTag(11, 60, 40, cv::ROTATE_180);
  const std::vector<ra::Detection> found = ra::Detector().detect(image);
  ASSERT_EQ(found.size(), 1u);
  const ra::Detection& d = found[0];
  const ra::Detection back = ra::detectionFromArucoCorners(d.id, ra::arucoCorners(d), d.family);
  EXPECT_EQ(back.id, 11);
  EXPECT_EQ(back.family, "tag36h11");
  EXPECT_EQ(back.corners, d.corners);
  EXPECT_EQ(ra::arucoCorners(back), ra::arucoCorners(d));
  // The other origin is the same list turned by two places, and round-trips the same way.
  const auto fromBottomRight = ra::arucoCorners(d, ra::ArucoFirstCorner::BottomRight);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(fromBottomRight[k], ra::arucoCorners(d)[(k + 2) % 4]);
  EXPECT_EQ(ra::detectionFromArucoCorners(d.id, fromBottomRight, d.family,
                                          ra::ArucoFirstCorner::BottomRight)
                .corners,
            d.corners);
  for (const glm::dvec2 q : {glm::dvec2{0, 0}, glm::dvec2{0.3, -0.2}, glm::dvec2{-0.5, 0.5}}) {
    EXPECT_LT(dist(back.tagToImage(q), d.tagToImage(q)), 1e-9);
  }
  EXPECT_LT(dist(back.centre, d.centre), 0.05);  // libapriltag's own centre vs the fitted one
  EXPECT_LT(dist(back.centre, d.tagToImage({0, 0})), 1e-9);

  // cv::aruco's type for one marker: std::vector<cv::Point2f>.
  std::vector<cv::Point2f> points;
  for (const glm::dvec2 p : ra::arucoCorners(d)) points.emplace_back(float(p.x), float(p.y));
  const ra::Detection fromFloats = ra::detectionFromArucoCorners(d.id, points, d.family);
  for (int k = 0; k < 4; ++k) EXPECT_LT(dist(fromFloats.corners[k], d.corners[k]), 1e-4);

  // libapriltag's order (counter-clockwise on screen) is refused, as are bad shapes and values.
  EXPECT_THROW(ra::detectionFromArucoCorners(d.id, d.corners), roiclip::InvalidInputError);
  EXPECT_THROW(ra::detectionFromArucoCorners(0, std::vector<cv::Point2f>(3)),
               roiclip::InvalidInputError);
  EXPECT_THROW(ra::detectionFromArucoCorners(0, std::vector<cv::Point>(4)),
               roiclip::InvalidInputError);
  std::array<glm::dvec2, 4> bad = ra::arucoCorners(d);
  bad[2].x = std::nan("");
  EXPECT_THROW(ra::detectionFromArucoCorners(0, bad), roiclip::InvalidInputError);
  const std::array<glm::dvec2, 4> collinear = {glm::dvec2{0, 0}, glm::dvec2{10, 0},
                                               glm::dvec2{20, 0}, glm::dvec2{10, 10}};
  EXPECT_THROW(ra::detectionFromArucoCorners(0, collinear), roiclip::InvalidInputError);
}

#ifdef ROICLIP_TEST_ARUCO
TEST(ArucoOrder, MatchesCvArucoOnRenderedTags) {
  // cv::aruco's own detector on the same images, with its AprilTag dictionaries. It reports the
  // libapriltag tag's bottom-right corner first (then clockwise): ArucoFirstCorner::BottomRight.
  // Without corner refinement it returns the centres of the outermost border pixels, about
  // 0.6 px inside libapriltag's corners per axis; a wrong order is a tag side (96 px) off.
  const std::pair<const char*, int> families[] = {{"tag16h5", cv::aruco::DICT_APRILTAG_16h5},
                                                  {"tag25h9", cv::aruco::DICT_APRILTAG_25h9},
                                                  {"tag36h10", cv::aruco::DICT_APRILTAG_36h10},
                                                  {"tag36h11", cv::aruco::DICT_APRILTAG_36h11}};
  for (const auto& [family, dictionary] : families) {
    for (int rotation : {-1, int(cv::ROTATE_90_CLOCKWISE)}) {
      ra::DetectorOptions options;
      options.family = family;
      const cv::Mat image = canvasWithTag(7, 40, 30, rotation, family);
      const std::vector<ra::Detection> found = ra::Detector(options).detect(image);
      ASSERT_EQ(found.size(), 1u) << family;
      std::vector<std::vector<cv::Point2f>> markers;
      std::vector<int> ids;
      cv::aruco::detectMarkers(image, cv::aruco::getPredefinedDictionary(dictionary), markers, ids);
      ASSERT_EQ(ids, std::vector<int>{7}) << family;
      const auto ours = ra::arucoCorners(found[0], ra::ArucoFirstCorner::BottomRight);
      const auto topLeft = ra::arucoCorners(found[0]);
      for (int k = 0; k < 4; ++k) {
        const glm::dvec2 theirs{markers[0][k].x, markers[0][k].y};
        EXPECT_LT(dist(ours[k], theirs), 1.0) << family << " corner " << k;
        EXPECT_GT(dist(topLeft[k], theirs), 90) << family << " corner " << k;
      }
      // Handed back, cv::aruco's corners give the Detection libapriltag made.
      const ra::Detection back = ra::detectionFromArucoCorners(ids[0], markers[0], family,
                                                               ra::ArucoFirstCorner::BottomRight);
      for (int k = 0; k < 4; ++k) {
        EXPECT_LT(dist(back.corners[k], found[0].corners[k]), 1.0) << family << " corner " << k;
      }
    }
  }
}
#endif

TEST(AprilTagDetector, CoordinatesArePixelCentred) {
  // The black border covers pixels [x0, x1] inclusive; in OpenCV's convention its outer edge is at
  // x0 - 0.5 and its centre at (x0 + x1) / 2. libapriltag alone would report both 0.5 px larger.
  int total = 0, border = 0;
  const cv::Mat image = canvasWithTag(3, 52, 44, -1, "tag36h11", &total, &border);
  const std::vector<ra::Detection> found = ra::Detector(unrefined()).detect(image);
  ASSERT_EQ(found.size(), 1u);
  const int offset = (total - border) / 2;
  const double x0 = 52 + offset * kCell, x1 = x0 + border * kCell - 1;
  const double y0 = 44 + offset * kCell, y1 = y0 + border * kCell - 1;
  EXPECT_NEAR(found[0].centre.x, (x0 + x1) / 2, 0.05);
  EXPECT_NEAR(found[0].centre.y, (y0 + y1) / 2, 0.05);
  EXPECT_NEAR(found[0].corner(Corner::TopLeft).x, x0 - 0.5, 0.05);
  EXPECT_NEAR(found[0].corner(Corner::TopLeft).y, y0 - 0.5, 0.05);
}

TEST(AprilTagDetector, RefineEdgesBiasIsSmall) {
  // libapriltag's edge refinement (on by default) places the corners of this blurred, axis-aligned
  // tag about 0.11 px outside the true border. Measured, not a wrapper offset: a 0.5 px convention
  // error would fail this.
  int total = 0, border = 0;
  const cv::Mat image = canvasWithTag(7, 40, 30, -1, "tag36h11", &total, &border);
  const std::vector<ra::Detection> found = ra::Detector().detect(image);
  ASSERT_EQ(found.size(), 1u);
  const Box b = borderBox(40, 30, total, border);
  const ra::Detection& d = found[0];
  EXPECT_LT(dist(d.corner(Corner::TopLeft), {b.left, b.top}), 0.2);
  EXPECT_LT(dist(d.corner(Corner::BottomRight), {b.right, b.bottom}), 0.2);
  EXPECT_LT(d.corner(Corner::TopLeft).x, b.left);  // outwards
  EXPECT_GT(d.corner(Corner::BottomRight).x, b.right);
}

TEST(AprilTagDetector, HomographyMapsTheTagFrame) {
  const cv::Mat image = canvasWithTag(11, 60, 20, cv::ROTATE_180);
  const std::vector<ra::Detection> found = ra::Detector().detect(image);
  ASSERT_EQ(found.size(), 1u);
  const ra::Detection& d = found[0];
  EXPECT_LT(dist(d.tagToImage({-0.5, -0.5}), d.corner(Corner::TopLeft)), 1e-6);
  EXPECT_LT(dist(d.tagToImage({0.5, -0.5}), d.corner(Corner::TopRight)), 1e-6);
  EXPECT_LT(dist(d.tagToImage({0.5, 0.5}), d.corner(Corner::BottomRight)), 1e-6);
  EXPECT_LT(dist(d.tagToImage({-0.5, 0.5}), d.corner(Corner::BottomLeft)), 1e-6);
  EXPECT_LT(dist(d.tagToImage({0, 0}), d.centre), 1e-6);
  // Upside down: the tag's "right" (+x) points left in the image.
  EXPECT_LT(d.tagToImage({1, 0}).x, d.centre.x);
}

TEST(AprilTagDetector, LibapriltagBlursTheCallersBufferInPlace) {
  // The trap the wrapper guards against: with quad_sigma != 0 and no decimation, the raw library
  // writes its blur into the image it was given.
  cv::Mat image = canvasWithTag(5, 40, 40);
  const cv::Mat before = image.clone();
  apriltag_family_t* family = tag36h11_create();
  apriltag_detector_t* td = apriltag_detector_create();
  apriltag_detector_add_family(td, family);
  td->quad_decimate = 1.0f;
  td->quad_sigma = 0.8f;
  td->nthreads = 1;
  image_u8_t wrapped{image.cols, image.rows, static_cast<int32_t>(image.step[0]), image.data};
  apriltag_detections_destroy(apriltag_detector_detect(td, &wrapped));
  apriltag_detector_destroy(td);
  tag36h11_destroy(family);
  EXPECT_GT(cv::norm(image, before, cv::NORM_INF), 0.0);
}

TEST(AprilTagDetector, NeverModifiesTheInput) {
  for (float sigma : {0.8f, -0.8f, 0.0f}) {
    for (float decimate : {1.0f, 2.0f}) {
      cv::Mat image = canvasWithTag(5, 40, 40);
      const cv::Mat before = image.clone();
      ra::DetectorOptions options;
      options.quadSigma = sigma;
      options.quadDecimate = decimate;
      const std::vector<ra::Detection> found = ra::Detector(options).detect(image);
      EXPECT_EQ(cv::norm(image, before, cv::NORM_INF), 0.0) << sigma << " " << decimate;
      ASSERT_EQ(found.size(), 1u) << sigma << " " << decimate;
      EXPECT_EQ(found[0].id, 5);
    }
  }
}

// libapriltag itself crashes on images under 3 rows after decimation; detect() answers
// "no tags" for them (found with a 1x1 PNG through `roiclip run`).
TEST(AprilTagDetector, TinyImagesHaveNoTagsAndDoNotCrash) {
  for (const float decimate : {1.0f, 2.0f, 4.0f}) {
    ra::DetectorOptions options;
    options.quadDecimate = decimate;
    const ra::Detector detector(options);
    for (const cv::Size size : {cv::Size(1, 1), cv::Size(2, 2), cv::Size(100, 1), cv::Size(100, 2),
                                cv::Size(100, 4), cv::Size(100, 8), cv::Size(1, 100)}) {
      EXPECT_TRUE(detector.detect(cv::Mat(size, CV_8UC1, cv::Scalar(128))).empty())
          << size << " at decimate " << decimate;
    }
  }
}

TEST(AprilTagDetector, RespectsTheRowStepOfAView) {
  const cv::Mat big = canvasWithTag(9, 120, 100);
  const cv::Mat view = big(cv::Rect(101, 83, 180, 170));  // not continuous: step > cols
  ASSERT_FALSE(view.isContinuous());
  const ra::Detector detector;
  const std::vector<ra::Detection> fromView = detector.detect(view);
  const std::vector<ra::Detection> fromCopy = detector.detect(view.clone());
  ASSERT_EQ(fromView.size(), 1u);
  ASSERT_EQ(fromCopy.size(), 1u);
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(fromView[0].corners[k], fromCopy[0].corners[k]);
  }
  // And the view's coordinates are relative to the view.
  const std::vector<ra::Detection> fromBig = detector.detect(big);
  ASSERT_EQ(fromBig.size(), 1u);
  EXPECT_LT(dist(fromView[0].centre + glm::dvec2{101, 83}, fromBig[0].centre), 0.05);
}

TEST(AprilTagDetector, ColourInputGivesTheSameResultAsGray) {
  const cv::Mat gray = canvasWithTag(21, 30, 50);
  cv::Mat bgr, bgra;
  cv::cvtColor(gray, bgr, cv::COLOR_GRAY2BGR);
  cv::cvtColor(gray, bgra, cv::COLOR_GRAY2BGRA);
  const ra::Detector detector;
  const auto a = detector.detect(gray), b = detector.detect(bgr), c = detector.detect(bgra);
  ASSERT_EQ(a.size(), 1u);
  ASSERT_EQ(b.size(), 1u);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(a[0].corners, b[0].corners);
  EXPECT_EQ(a[0].corners, c[0].corners);
}

TEST(AprilTagDetector, TwoDetectorsOfOneFamilyOwnTheirFamilies) {
  // With a shared libapriltag family both detectors would free its decode table (double free)
  // and the second destroy would read freed memory. Each Detector owns its family, so creating,
  // using and destroying them in any order is safe.
  const cv::Mat image = canvasWithTag(2, 40, 40);
  for (int round = 0; round < 3; ++round) {
    auto first = std::make_unique<ra::Detector>();
    auto second = std::make_unique<ra::Detector>();
    ASSERT_EQ(first->detect(image).size(), 1u);
    ASSERT_EQ(second->detect(image).size(), 1u);
    if (round % 2 == 0) {
      first.reset();
      ASSERT_EQ(second->detect(image).size(), 1u);
    } else {
      second.reset();
      ASSERT_EQ(first->detect(image).size(), 1u);
    }
  }
}

TEST(AprilTagDetector, ConcurrentCallsOnOneDetectorAreSerialised) {
  std::vector<cv::Mat> images;
  for (int id = 0; id < 4; ++id) images.push_back(canvasWithTag(id * 10, 20 + 8 * id, 30 + 4 * id));
  ra::DetectorOptions options;
  options.threads = 2;
  const ra::Detector detector(options);
  std::vector<std::vector<ra::Detection>> serial;
  for (const cv::Mat& image : images) serial.push_back(detector.detect(image));
  std::vector<std::vector<std::vector<ra::Detection>>> results(4);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      for (int repeat = 0; repeat < 3; ++repeat) {
        for (const cv::Mat& image : images) results[t].push_back(detector.detect(image));
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (int t = 0; t < 4; ++t) {
    ASSERT_EQ(results[t].size(), 12u);
    for (std::size_t i = 0; i < results[t].size(); ++i) {
      const auto& expected = serial[i % 4];
      ASSERT_EQ(results[t][i].size(), expected.size());
      ASSERT_EQ(results[t][i].size(), 1u);
      EXPECT_EQ(results[t][i][0].id, expected[0].id);
      EXPECT_EQ(results[t][i][0].corners, expected[0].corners);
    }
  }
}

TEST(AprilTagDetector, EveryFamilyRoundTrips) {
  for (const std::string& family : ra::availableFamilies()) {
    const int id = ra::familySize(family) / 2;
    const cv::Mat image = canvasWithTag(id, 40, 40, -1, family.c_str());
    ra::DetectorOptions options;
    options.family = family;
    options.maxBitsCorrected = 0;  // keeps the big families' decode tables small
    const std::vector<ra::Detection> found = ra::Detector(options).detect(image);
    ASSERT_EQ(found.size(), 1u) << family;
    EXPECT_EQ(found[0].id, id) << family;
    EXPECT_EQ(found[0].family, family);
  }
}

TEST(AprilTagDetector, RenderTagCopiesRowsWithTheirStride) {
  // apriltag_to_image pads rows to a 96-byte stride; a stride-blind copy would shear the tag.
  int border = 0;
  const cv::Mat tag = ra::renderTag("tag36h11", 0, &border);
  ASSERT_EQ(tag.type(), CV_8UC1);
  ASSERT_EQ(tag.rows, 10);
  ASSERT_EQ(tag.cols, 10);
  EXPECT_EQ(border, 8);
  for (int i = 0; i < 10; ++i) {
    // Outer ring white, next ring black, on every row and column.
    EXPECT_EQ(tag.at<unsigned char>(i, 0), 255) << i;
    EXPECT_EQ(tag.at<unsigned char>(0, i), 255) << i;
    EXPECT_EQ(tag.at<unsigned char>(i, 9), 255) << i;
    EXPECT_EQ(tag.at<unsigned char>(9, i), 255) << i;
    if (i >= 1 && i <= 8) {
      EXPECT_EQ(tag.at<unsigned char>(i, 1), 0) << i;
      EXPECT_EQ(tag.at<unsigned char>(1, i), 0) << i;
      EXPECT_EQ(tag.at<unsigned char>(i, 8), 0) << i;
      EXPECT_EQ(tag.at<unsigned char>(8, i), 0) << i;
    }
  }
  // Different ids give different payloads.
  EXPECT_GT(cv::norm(tag, ra::renderTag("tag36h11", 1), cv::NORM_L1), 0.0);
}

TEST(AprilTagDetector, FindsNothingInABlankImage) {
  const cv::Mat blank(120, 160, CV_8UC1, cv::Scalar(200));
  EXPECT_TRUE(ra::Detector().detect(blank).empty());
}

TEST(AprilTagDetectorErrors, EmptyImage) {
  try {
    (void)ra::Detector().detect(cv::Mat());
    FAIL() << "no exception";
  } catch (const roiclip::InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("empty"), std::string::npos) << e.what();
  }
}

TEST(AprilTagDetectorErrors, NonEightBitImages) {
  const ra::Detector detector;
  for (int type : {CV_16UC1, CV_32FC1, CV_64FC3, CV_8SC1}) {
    const cv::Mat image(40, 40, type, cv::Scalar(0));
    EXPECT_THROW((void)detector.detect(image), roiclip::InvalidInputError) << type;
  }
  try {
    (void)detector.detect(cv::Mat(40, 40, CV_16UC1, cv::Scalar(0)));
    FAIL() << "no exception";
  } catch (const roiclip::InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("CV_16UC1"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)detector.detect(cv::Mat(40, 40, CV_8UC2, cv::Scalar(0))),
               roiclip::InvalidInputError);
}

TEST(AprilTagDetectorErrors, UnknownFamily) {
  ra::DetectorOptions options;
  options.family = "tag99h99";
  try {
    ra::Detector detector(options);
    FAIL() << "no exception";
  } catch (const roiclip::InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("tag99h99"), std::string::npos) << e.what();
  }
  EXPECT_THROW(ra::familySize("nope"), roiclip::InvalidInputError);
  EXPECT_THROW(ra::renderTag("tag36h11", 100000), roiclip::InvalidInputError);
}

TEST(AprilTagDetectorErrors, BadOptions) {
  ra::DetectorOptions decimate;
  decimate.quadDecimate = 0.5f;
  EXPECT_THROW(ra::Detector{decimate}, roiclip::InvalidInputError);
  ra::DetectorOptions threads;
  threads.threads = 0;
  EXPECT_THROW(ra::Detector{threads}, roiclip::InvalidInputError);
  ra::DetectorOptions bits;
  bits.maxBitsCorrected = 4;
  EXPECT_THROW(ra::Detector{bits}, roiclip::InvalidInputError);
  ra::DetectorOptions hamming;
  hamming.maxHamming = 4;
  EXPECT_THROW(ra::Detector{hamming}, roiclip::InvalidInputError);
  ra::DetectorOptions margin;
  margin.minDecisionMargin = -1;
  EXPECT_THROW(ra::Detector{margin}, roiclip::InvalidInputError);
}

TEST(AprilTagDetector, AutomaticDecimationFollowsTheImageSize) {
  EXPECT_EQ(ra::autoQuadDecimate(320, 240), 1.0f);
  EXPECT_EQ(ra::autoQuadDecimate(640, 480), 1.5f);
  EXPECT_EQ(ra::autoQuadDecimate(800, 600), 2.0f);
  EXPECT_EQ(ra::autoQuadDecimate(1280, 960), 3.0f);
  EXPECT_EQ(ra::autoQuadDecimate(1920, 1080), 4.0f);
  EXPECT_EQ(ra::autoQuadDecimate(3840, 2160), 8.0f);
  EXPECT_EQ(ra::autoQuadDecimate(8000, 6000), 16.0f);
  EXPECT_EQ(ra::autoQuadDecimate(0, 0), 1.0f);
  // The factor used is reported; a per-call factor overrides the options.
  const cv::Mat image = canvasWithTag(3, 40, 40);
  const ra::Detector detector;
  const ra::DetectionReport automatic = detector.detectReport(image);
  EXPECT_EQ(automatic.quadDecimate, 1.0f);  // 400 x 360: no decimation
  EXPECT_EQ(automatic.passes, 1);
  const ra::DetectionReport forced = detector.detectReport(image, 2.0f);
  EXPECT_EQ(forced.quadDecimate, 2.0f);
  ASSERT_EQ(forced.tags.size(), 1u);
  EXPECT_EQ(forced.tags[0].id, 3);
  EXPECT_THROW((void)detector.detectReport(image, 0.5f), roiclip::InvalidInputError);
}

// A 1920 x 1080 frame with tag `id` drawn with a black square of `side` pixels, turned by
// `degrees` about (cx, cy), lightly blurred.
void drawTag(cv::Mat& frame, int id, double side, double degrees, cv::Point2d centre) {
  int border = 0;
  const cv::Mat tag = ra::renderTag("tag36h11", id, &border);
  const double cell = side / (tag.cols - 2);  // the rendered tag has one white cell each side
  cv::Mat big;
  cv::resize(tag, big, cv::Size(), cell, cell, cv::INTER_NEAREST);
  cv::Mat m = cv::getRotationMatrix2D(cv::Point2f(float(big.cols) / 2.0f, float(big.rows) / 2.0f),
                                      degrees, 1.0);
  m.at<double>(0, 2) += centre.x - big.cols / 2.0;
  m.at<double>(1, 2) += centre.y - big.rows / 2.0;
  cv::Mat warped, mask;
  cv::warpAffine(big, warped, m, frame.size(), cv::INTER_LINEAR);
  cv::warpAffine(cv::Mat(big.size(), CV_8UC1, cv::Scalar(255)), mask, m, frame.size(),
                 cv::INTER_LINEAR);
  warped.copyTo(frame, mask > 128);
}

std::vector<int> idsOf(const ra::DetectionReport& r) {
  std::vector<int> ids;
  for (const ra::Detection& d : r.tags) ids.push_back(d.id);
  return ids;
}

// kAutoDecimatePixels rests on this: one pass finds a tag whose black square is 14 decimated
// pixels a side (56 px at decimate 4, the automatic factor at 1080p), turned, blurred and noisy.
TEST(AprilTagDetector, OnePassFindsTagsOfFourteenDecimatedPixels) {
  const ra::Detector detector;
  cv::RNG rng(7);
  for (const float decimate : {2.0f, 3.0f, 4.0f}) {
    cv::Mat frame(1080, 1920, CV_8UC1, cv::Scalar(110));
    std::vector<int> want;
    for (int i = 0; i < 12; ++i) {  // a 4 x 3 grid, each tag turned differently
      drawTag(frame, i, 14 * decimate, rng.uniform(-40.0, 40.0),
              {240.0 + 480 * (i % 4), 180.0 + 360 * (i / 4)});
      want.push_back(i);
    }
    cv::GaussianBlur(frame, frame, cv::Size(0, 0), 0.8);
    cv::Mat noise(frame.size(), CV_8UC1);
    rng.fill(noise, cv::RNG::NORMAL, 0, 4);
    frame += noise;
    EXPECT_EQ(idsOf(detector.detectReport(frame, decimate)), want) << "decimate " << decimate;
  }
}

// Automatic decimation runs coarse to fine: a finer pass follows when a pass finds no tag, a
// small tag, or misses an id the caller expects.
TEST(AprilTagDetector, AutomaticDecimationGoesFinerWhenAPassFallsShort) {
  const ra::Detector detector;
  cv::Mat frame(1080, 1920, CV_8UC1, cv::Scalar(110));
  drawTag(frame, 1, 240, 10, {500, 500});
  drawTag(frame, 2, 16, 0, {1400, 500});  // 4 decimated pixels at 4: lost by the first pass
  cv::GaussianBlur(frame, frame, cv::Size(0, 0), 0.8);
  // Only the large tag: nothing says the small one is missing (the documented limit).
  const ra::DetectionReport coarse = detector.detectReport(frame);
  EXPECT_EQ(coarse.quadDecimate, 4.0f);
  EXPECT_EQ(coarse.passes, 1);
  EXPECT_EQ(idsOf(coarse), std::vector<int>{1});
  // Expecting id 2 runs finer passes (2, then 1: at 2 the small tag is missing or, found, too
  // small), which find both.
  const ra::DetectionReport expected = detector.detectReport(frame, 0, {1, 2});
  EXPECT_EQ(expected.quadDecimate, 1.0f);
  EXPECT_EQ(expected.passes, 3);
  EXPECT_EQ(idsOf(expected), (std::vector<int>{1, 2}));
  // A small tag found alone asks for a finer pass too (14 decimated pixels at 4).
  cv::Mat small(1080, 1920, CV_8UC1, cv::Scalar(110));
  drawTag(small, 5, 56, 20, {900, 600});
  cv::GaussianBlur(small, small, cv::Size(0, 0), 0.8);
  const ra::DetectionReport finer = detector.detectReport(small);
  EXPECT_EQ(idsOf(finer), std::vector<int>{5});
  EXPECT_EQ(finer.passes, 2);
  EXPECT_EQ(finer.quadDecimate, 2.0f);
  // No tag at all: passes at 4, 2 and 1.
  const ra::DetectionReport none = detector.detectReport(cv::Mat(1080, 1920, CV_8UC1, 110));
  EXPECT_TRUE(none.tags.empty());
  EXPECT_EQ(none.passes, 3);
  EXPECT_EQ(none.quadDecimate, 1.0f);
  // A fixed factor is one pass, whatever it finds.
  EXPECT_EQ(detector.detectReport(frame, 4.0f, {1, 2}).passes, 1);
}

// The tag of canvasWithTag() with one payload cell inverted: it decodes with one corrected bit.
cv::Mat canvasWithOneBitFlipped(int id) {
  cv::Mat tag = ra::renderTag("tag36h11", id);
  tag.at<unsigned char>(4, 4) = static_cast<unsigned char>(255 - tag.at<unsigned char>(4, 4));
  cv::Mat big;
  cv::resize(tag, big, cv::Size(), kCell, kCell, cv::INTER_NEAREST);
  cv::Mat canvas(360, 400, CV_8UC1, cv::Scalar(255));
  big.copyTo(canvas(cv::Rect(40, 40, big.cols, big.rows)));
  cv::GaussianBlur(canvas, canvas, cv::Size(0, 0), 1.0);
  return canvas;
}

TEST(AprilTagDetector, CorrectedDetectionsAreRejectedUnlessAllowed) {
  const cv::Mat image = canvasWithOneBitFlipped(5);
  const ra::DetectionReport strict = ra::Detector().detectReport(image);
  EXPECT_TRUE(strict.tags.empty());
  ASSERT_EQ(strict.rejected.size(), 1u);
  EXPECT_EQ(strict.rejected[0].id, 5);
  EXPECT_EQ(strict.rejected[0].hamming, 1);

  ra::DetectorOptions lenient;
  lenient.maxHamming = 1;
  const ra::DetectionReport accepted = ra::Detector(lenient).detectReport(image);
  ASSERT_EQ(accepted.tags.size(), 1u);
  EXPECT_EQ(accepted.tags[0].hamming, 1);
  EXPECT_TRUE(accepted.rejected.empty());
}

TEST(AprilTagDetector, LowDecisionMarginsAreRejected) {
  const cv::Mat image = canvasWithTag(9, 40, 40);
  const ra::DetectionReport plain = ra::Detector().detectReport(image);
  ASSERT_EQ(plain.tags.size(), 1u);
  ra::DetectorOptions picky;
  picky.minDecisionMargin = plain.tags[0].decisionMargin + 1;
  const ra::DetectionReport report = ra::Detector(picky).detectReport(image);
  EXPECT_TRUE(report.tags.empty());
  ASSERT_EQ(report.rejected.size(), 1u);
  EXPECT_EQ(report.rejected[0].id, 9);
}

TEST(AprilTagDetector, SeveralFamiliesAtOnce) {
  cv::Mat image = canvasWithTag(3, 20, 40);
  const cv::Mat other = canvasWithTag(4, 220, 40, -1, "tag25h9");
  other(cv::Rect(200, 0, 200, 360)).copyTo(image(cv::Rect(200, 0, 200, 360)));
  ra::DetectorOptions both;
  both.family = "tag36h11,tag25h9";
  const std::vector<ra::Detection> found = ra::Detector(both).detect(image);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].id, 3);
  EXPECT_EQ(found[0].family, "tag36h11");
  EXPECT_EQ(found[1].id, 4);
  EXPECT_EQ(found[1].family, "tag25h9");
  // One family alone sees only its own tag.
  EXPECT_EQ(ra::Detector().detect(image).size(), 1u);
  ra::DetectorOptions twice;
  twice.family = "tag36h11,tag36h11";
  EXPECT_THROW(ra::Detector{twice}, roiclip::InvalidInputError);
  ra::DetectorOptions unknown;
  unknown.family = "tag36h11,tag99h1";
  EXPECT_THROW(ra::Detector{unknown}, roiclip::InvalidInputError);
}

TEST(AprilTagDetectorErrors, MovedFromDetectorThrows) {
  ra::Detector a;
  ra::Detector b(std::move(a));
  const cv::Mat image = canvasWithTag(1, 40, 40);
  EXPECT_EQ(b.detect(image).size(), 1u);
  EXPECT_THROW((void)a.detect(image), roiclip::Error);  // NOLINT(bugprone-use-after-move)
}

}  // namespace
