// SPDX-License-Identifier: MIT
// Detection and every ROI builder on the bundled scenes (images/), against their ground truth.
#include <roiclip/apriltag/detector.hpp>
#include <roiclip/apriltag/roi.hpp>
#include <roiclip/opencv/rasterize.hpp>
#include <roiclip/roiclip.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace ra = roiclip::apriltag;
using roiclip::Path;
using roiclip::Paths;

namespace {

const std::string kImages = ROICLIP_IMAGES;

struct Truth {
  std::vector<Paths> shapes;                         // each read with even-odd
  std::map<int, std::array<glm::dvec2, 4>> corners;  // Corner order
  std::map<int, glm::dvec2> centres;
  std::map<std::string, Paths> rois;
  glm::dmat3 imageFromBoard{1.0};
};

glm::dvec2 point(const nlohmann::json& j) { return {j[0].get<double>(), j[1].get<double>()}; }

Paths paths(const nlohmann::json& j) {
  Paths out;
  for (const auto& path : j) {
    Path p;
    for (const auto& q : path) p.push_back(point(q));
    out.push_back(p);
  }
  return out;
}

Truth loadTruth(const std::string& stem) {
  std::ifstream in(kImages + "/" + stem + ".json");
  EXPECT_TRUE(in.good()) << stem;
  const nlohmann::json j = nlohmann::json::parse(in);
  Truth t;
  for (const auto& tag : j.at("tags")) {
    const int id = tag.at("id").get<int>();
    for (int k = 0; k < 4; ++k) t.corners[id][k] = point(tag.at("corners")[k]);
    t.centres[id] = point(tag.at("centre"));
  }
  for (const auto& shape : j.at("shapes")) {
    EXPECT_EQ(shape.at("fill_rule").get<std::string>(), "evenodd");
    t.shapes.push_back(paths(shape.at("paths")));
  }
  for (const auto& roi : j.at("rois"))
    t.rois[roi.at("name").get<std::string>()] = paths(roi.at("paths"));
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c)
      t.imageFromBoard[c][r] = j.at("image_from_board")[r][c].get<double>();
  }
  return t;
}

double dist(glm::dvec2 a, glm::dvec2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

// Largest vertex distance between two path sets of the same shape.
double maxVertexError(const Paths& a, const Paths& b) {
  EXPECT_EQ(a.size(), b.size());
  double worst = 0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    EXPECT_EQ(a[i].size(), b[i].size());
    for (std::size_t k = 0; k < std::min(a[i].size(), b[i].size()); ++k) {
      worst = std::max(worst, dist(a[i][k], b[i][k]));
    }
  }
  return worst;
}

class AprilTagScene : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    image_ = cv::imread(kImages + "/" + GetParam() + ".png", cv::IMREAD_GRAYSCALE);
    ASSERT_FALSE(image_.empty()) << GetParam();
    truth_ = loadTruth(GetParam());
    board_ = ra::Board::load(kImages + "/board.json");
    detections_ = detector().detect(image_);
  }
  static const ra::Detector& detector() {
    static const ra::Detector instance;  // thread-safe by construction; built once
    return instance;
  }
  // One check per builder; grouped into a few tests below so that CTest (one process per test)
  // does not pay the process and detector start-up dozens of times per scene.
  void checkEveryTagFoundWithCornersWithinHalfAPixel();
  void checkDecimationAndThreadsKeepTheResult();
  void checkBoardRoiWithinOnePixel();
  void checkBoardRoiFromOneTagUsesAnExactFit();
  void checkPolygonThroughTagCentresAndCorners();
  void checkOutOfOrderTagsGiveASelfIntersectingRoi();
  void checkConvexHullOfTagCorners();
  void checkTagFrameRoiMatchesTheBoardGeometry();
  void checkMissingTagsAreReportedNotEmpty();
  void checkDuplicatedIdsAreAmbiguous();

  cv::Mat image_;
  Truth truth_;
  ra::Board board_;
  std::vector<ra::Detection> detections_;
};

void AprilTagScene::checkEveryTagFoundWithCornersWithinHalfAPixel() {
  std::vector<int> ids;
  for (const ra::Detection& d : detections_) ids.push_back(d.id);
  EXPECT_EQ(ids, (std::vector<int>{0, 1, 2, 3}));
  double worst = 0;
  for (const ra::Detection& d : detections_) {
    ASSERT_TRUE(truth_.corners.count(d.id)) << d.id;
    EXPECT_EQ(d.family, "tag36h11");
    EXPECT_EQ(d.hamming, 0);
    for (int k = 0; k < 4; ++k) {
      const double e = dist(d.corners[k], truth_.corners[d.id][k]);
      EXPECT_LT(e, 0.5) << "tag " << d.id << " corner " << k;
      worst = std::max(worst, e);
    }
  }
  RecordProperty("max_corner_error_px", std::to_string(worst));
  std::printf("[ %s ] max corner error %.3f px\n", GetParam().c_str(), worst);
}

void AprilTagScene::checkDecimationAndThreadsKeepTheResult() {
  // quad_decimate 2 finds quads on a half-size image; refine_edges then snaps the edges back to
  // full-resolution gradients. Several worker threads must not change anything.
  ra::DetectorOptions options;
  options.quadDecimate = 2.0f;
  options.threads = 2;
  const std::vector<ra::Detection> found = ra::Detector(options).detect(image_);
  ASSERT_EQ(found.size(), 4u);
  double worst = 0;
  for (const ra::Detection& d : found) {
    for (int k = 0; k < 4; ++k)
      worst = std::max(worst, dist(d.corners[k], truth_.corners.at(d.id)[k]));
  }
  EXPECT_LT(worst, 0.5);
  ra::DetectorOptions single = options;
  single.threads = 1;
  const std::vector<ra::Detection> serial = ra::Detector(single).detect(image_);
  // Against libapriltag before 3.4.3 one worker runs (its pool can crash with more).
  EXPECT_EQ(ra::Detector(options).detectReport(image_).threads,
            ROICLIP_TEST_APRILTAG_ONE_WORKER ? 1 : 2);
  ASSERT_EQ(serial.size(), found.size());
  for (std::size_t i = 0; i < found.size(); ++i) EXPECT_EQ(serial[i].corners, found[i].corners);
  std::printf("[ %s ] decimate 2: max corner error %.3f px\n", GetParam().c_str(), worst);
}

void AprilTagScene::checkBoardRoiWithinOnePixel() {
  double worst = 0;
  for (const ra::BoardRoi& roi : board_.rois) {
    const ra::RoiResult result = ra::boardRoi(board_, detections_, roi.name);
    ASSERT_TRUE(result.ok()) << result.missing().describe();
    const double e = maxVertexError(result.value(), truth_.rois.at(roi.name));
    EXPECT_LT(e, 1.0) << roi.name;
    worst = std::max(worst, e);
  }
  // All ROIs at once: the concatenation in board order.
  const ra::RoiResult all = ra::boardRoi(board_, detections_);
  ASSERT_TRUE(all.ok());
  EXPECT_EQ(all.value().size(), board_.rois.size());
  const ra::TagResult<ra::BoardFit> fit = ra::fitBoard(board_, detections_);
  ASSERT_TRUE(fit.ok());
  EXPECT_EQ(fit.value().tagsUsed, (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(fit.value().inliers, 16);
  EXPECT_LT(fit.value().rmsError, 0.5);
  std::printf("[ %s ] board ROI max vertex error %.3f px, fit rms %.3f px\n", GetParam().c_str(),
              worst, fit.value().rmsError);
}

void AprilTagScene::checkBoardRoiFromOneTagUsesAnExactFit() {
  // Only tag 1 visible: the homography comes from its 4 corners alone (no RANSAC), so the ROI far
  // from the tag is less accurate; still a result, not a failure.
  std::vector<ra::Detection> one;
  for (const ra::Detection& d : detections_) {
    if (d.id == 1) one.push_back(d);
  }
  const ra::TagResult<ra::BoardFit> fit = ra::fitBoard(board_, one);
  ASSERT_TRUE(fit.ok());
  EXPECT_EQ(fit.value().tagsUsed, std::vector<int>{1});
  EXPECT_LT(fit.value().rmsError, 1e-6);
  const ra::RoiResult roi = ra::boardRoi(board_, one, "inspection");
  ASSERT_TRUE(roi.ok());
  const double e = maxVertexError(roi.value(), truth_.rois.at("inspection"));
  EXPECT_LT(e, 8.0);
  std::printf("[ %s ] one-tag board ROI max vertex error %.3f px\n", GetParam().c_str(), e);
}

void AprilTagScene::checkPolygonThroughTagCentresAndCorners() {
  const ra::RoiResult centres = ra::polygonThroughTags(detections_, {0, 1, 2, 3});
  ASSERT_TRUE(centres.ok());
  ASSERT_EQ(centres.value().size(), 1u);
  const Path& path = centres.value()[0];
  ASSERT_EQ(path.size(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_LT(dist(path[i], truth_.centres.at(i)), 0.5) << i;

  const ra::RoiResult corners =
      ra::polygonThroughTags(detections_, {3, 2, 1, 0}, ra::TagAnchor::TopLeft);
  ASSERT_TRUE(corners.ok());
  const int order[] = {3, 2, 1, 0};
  for (int i = 0; i < 4; ++i) {
    EXPECT_LT(dist(corners.value()[0][i],
                   truth_.corners.at(order[i])[static_cast<int>(ra::Corner::TopLeft)]),
              0.5);
  }
  // Listing the ids in the given order keeps the orientation: reversed order, opposite sign.
  const ra::RoiResult reversed = ra::polygonThroughTags(detections_, {3, 2, 1, 0});
  EXPECT_LT(roiclip::signedArea(path) * roiclip::signedArea(reversed.value()[0]), 0);
}

void AprilTagScene::checkOutOfOrderTagsGiveASelfIntersectingRoi() {
  // 0,2,1,3 crosses itself between the tags: a bow-tie. Under even-odd it is two triangles.
  const ra::RoiResult bowTie = ra::polygonThroughTags(detections_, {0, 2, 1, 3});
  ASSERT_TRUE(bowTie.ok());
  const roiclip::PolygonSet region = roiclip::simplify(bowTie.value(), roiclip::FillRule::EvenOdd);
  EXPECT_EQ(region.polygons.size(), 2u);
  const roiclip::PolygonSet quad = roiclip::simplify(
      ra::polygonThroughTags(detections_, {0, 1, 2, 3}).value(), roiclip::FillRule::EvenOdd);
  EXPECT_EQ(quad.polygons.size(), 1u);
  EXPECT_LT(region.area(), quad.area());
}

void AprilTagScene::checkConvexHullOfTagCorners() {
  std::vector<cv::Point2f> truthPoints;
  for (const auto& [id, corners] : truth_.corners) {
    for (const glm::dvec2& c : corners) {
      truthPoints.emplace_back(static_cast<float>(c.x), static_cast<float>(c.y));
    }
  }
  std::vector<cv::Point2f> truthHull;
  cv::convexHull(truthPoints, truthHull);
  const double truthArea = cv::contourArea(truthHull);

  const ra::RoiResult all = ra::convexHullOfTags(detections_);
  ASSERT_TRUE(all.ok());
  ASSERT_EQ(all.value().size(), 1u);
  EXPECT_LT(roiclip::signedArea(all.value()[0]), 0);  // outer-contour orientation
  EXPECT_NEAR(-roiclip::signedArea(all.value()[0]), truthArea, 0.005 * truthArea);
  std::vector<cv::Point2f> hull;
  for (const glm::dvec2& p : all.value()[0]) {
    hull.emplace_back(static_cast<float>(p.x), static_cast<float>(p.y));
  }
  for (const cv::Point2f& p : truthPoints) {
    EXPECT_GT(cv::pointPolygonTest(hull, p, true), -0.5);  // every true corner inside (to 0.5 px)
  }

  // A chosen id set: tags 0 and 2 only; its hull contains both tags' true corners only.
  const ra::RoiResult two = ra::convexHullOfTags(detections_, {0, 2});
  ASSERT_TRUE(two.ok());
  std::vector<cv::Point2f> twoHull;
  for (const glm::dvec2& p : two.value()[0]) {
    twoHull.emplace_back(static_cast<float>(p.x), static_cast<float>(p.y));
  }
  for (int id : {0, 2}) {
    for (const glm::dvec2& c : truth_.corners.at(id)) {
      EXPECT_GT(cv::pointPolygonTest(
                    twoHull, cv::Point2f(static_cast<float>(c.x), static_cast<float>(c.y)), true),
                -0.5);
    }
  }
  EXPECT_LT(-roiclip::signedArea(two.value()[0]), truthArea);
}

void AprilTagScene::checkTagFrameRoiMatchesTheBoardGeometry() {
  // On the board, tag 0 is upright with its centre at (50, 50) mm and a 64 mm black border, so
  // tag-frame (u, v) is board (50 + 64 u, 50 + 64 v). The area 2 tag-widths to its right:
  const Paths tagFrame = {{{0.5, -0.5}, {2.5, -0.5}, {2.5, 0.5}, {0.5, 0.5}}};
  const ra::RoiResult roi = ra::tagFrameRoi(detections_, 0, tagFrame);
  ASSERT_TRUE(roi.ok());
  Paths expected = {{}};
  for (const glm::dvec2& p : tagFrame[0]) {
    expected[0].push_back(
        ra::applyHomography(truth_.imageFromBoard, glm::dvec2{50, 50} + 64.0 * p));
  }
  const double e = maxVertexError(roi.value(), expected);
  // Extrapolating 2.5 tag widths from one tag's corners magnifies their error.
  EXPECT_LT(e, 2.5);
  // Orientation kept: tag frame is y down like the image and the map does not mirror.
  EXPECT_GT(roiclip::signedArea(tagFrame[0]) * roiclip::signedArea(roi.value()[0]), 0);
  std::printf("[ %s ] tag-frame ROI max vertex error %.3f px\n", GetParam().c_str(), e);
}

void AprilTagScene::checkMissingTagsAreReportedNotEmpty() {
  std::vector<ra::Detection> withoutTwo;
  for (const ra::Detection& d : detections_) {
    if (d.id != 2) withoutTwo.push_back(d);
  }
  const ra::RoiResult polygon = ra::polygonThroughTags(withoutTwo, {0, 1, 2, 3});
  ASSERT_FALSE(polygon.ok());
  EXPECT_EQ(polygon.missing().needed, (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(polygon.missing().seen, (std::vector<int>{0, 1, 3}));
  EXPECT_EQ(polygon.missing().missing, std::vector<int>{2});
  EXPECT_EQ(polygon.missing().describe(), "needed tags [0 1 2 3], seen [0 1 3]: missing [2]");
  EXPECT_THROW((void)polygon.value(), ra::MissingTagsError);
  try {
    (void)polygon.value();
  } catch (const roiclip::Error& e) {
    EXPECT_NE(std::string(e.what()).find("missing [2]"), std::string::npos) << e.what();
  }

  EXPECT_FALSE(ra::convexHullOfTags(withoutTwo, {1, 2}).ok());
  EXPECT_FALSE(ra::tagFrameRoi(withoutTwo, 2, {{{0, 0}, {1, 0}, {1, 1}}}).ok());
  EXPECT_TRUE(ra::boardRoi(board_, withoutTwo).ok());  // three board tags are plenty

  const ra::RoiResult none = ra::boardRoi(board_, {});
  ASSERT_FALSE(none.ok());
  EXPECT_EQ(none.missing().minimumNeeded, 1);
  EXPECT_EQ(none.missing().missing, (std::vector<int>{0, 1, 2, 3}));
  const ra::RoiResult nothing = ra::convexHullOfTags({});
  ASSERT_FALSE(nothing.ok());
  EXPECT_EQ(nothing.missing().describe(), "needed at least 1 detected tag, seen []");
}

void AprilTagScene::checkDuplicatedIdsAreAmbiguous() {
  std::vector<ra::Detection> doubled = detections_;
  ra::Detection copy = detections_.front();
  for (glm::dvec2& c : copy.corners) c += glm::dvec2{5, 5};
  doubled.push_back(copy);
  const ra::RoiResult polygon = ra::polygonThroughTags(doubled, {0, 1, 2});
  ASSERT_FALSE(polygon.ok());
  EXPECT_EQ(polygon.missing().duplicated, std::vector<int>{copy.id});
  EXPECT_FALSE(ra::boardRoi(board_, doubled).ok());
}

// Even-odd raster of a path set, 1/256 px vertex precision, 255 inside.
cv::Mat fillMask(cv::Size size, const Paths& region) {
  std::vector<std::vector<cv::Point>> contours;
  for (const Path& path : region) {
    std::vector<cv::Point> c;
    for (const glm::dvec2& p : path) {
      c.emplace_back(static_cast<int>(std::lround(p.x * 256)),
                     static_cast<int>(std::lround(p.y * 256)));
    }
    contours.push_back(c);
  }
  cv::Mat mask(size, CV_8UC1, cv::Scalar(0));
  cv::fillPoly(mask, contours, cv::Scalar(255), cv::LINE_8, 8);
  return mask;
}

TEST_P(AprilTagScene, ShapeGroundTruthMatchesThePixels) {
  // The truth the batch app will be judged against: dark exactly where the shapes are.
  const cv::Mat kernel = cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(7, 7));
  ASSERT_EQ(truth_.shapes.size(), 9u);
  cv::Mat all(image_.size(), CV_8UC1, cv::Scalar(0));
  for (std::size_t i = 0; i < truth_.shapes.size(); ++i) {
    const cv::Mat mask = fillMask(image_.size(), truth_.shapes[i]);
    EXPECT_EQ(cv::countNonZero(mask & all), 0) << "shape " << i << " overlaps another shape";
    all |= mask;
    cv::Mat core;
    cv::erode(mask, core, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(5, 5)));
    if (cv::countNonZero(core) > 0) {
      EXPECT_LT(cv::mean(image_, core)[0], 110) << "shape " << i << " is not dark inside";
    }
  }
  // Tags with their white margin (10/8 of the black border) must not touch any shape.
  for (const auto& [id, c] : truth_.corners) {
    Path margin;
    const glm::dvec2 centre = truth_.centres.at(id);
    for (const glm::dvec2& p : c) margin.push_back(centre + (p - centre) * 1.25);
    EXPECT_EQ(cv::countNonZero(fillMask(image_.size(), {margin}) & all), 0) << "tag " << id;
  }
  // Board pixels well away from shapes and tags are bright.
  cv::Mat board = fillMask(image_.size(), {{ra::applyHomography(truth_.imageFromBoard, {5, 5}),
                                            ra::applyHomography(truth_.imageFromBoard, {395, 5}),
                                            ra::applyHomography(truth_.imageFromBoard, {395, 295}),
                                            ra::applyHomography(truth_.imageFromBoard, {5, 295})}});
  cv::Mat near;
  cv::dilate(all, near, kernel);
  board.setTo(0, near);
  for (const auto& [id, c] : truth_.corners) {
    Path margin;
    const glm::dvec2 centre = truth_.centres.at(id);
    for (const glm::dvec2& p : c) margin.push_back(centre + (p - centre) * 1.4);
    board.setTo(0, fillMask(image_.size(), {margin}));
  }
  cv::Mat darkOnBoard = (image_ < 150) & board;
  EXPECT_LT(cv::countNonZero(darkOnBoard), 20) << "dark pixels where no shape is";
}

TEST_P(AprilTagScene, Detection) {
  {
    SCOPED_TRACE("EveryTagFoundWithCornersWithinHalfAPixel");
    checkEveryTagFoundWithCornersWithinHalfAPixel();
  }
  {
    SCOPED_TRACE("DecimationAndThreadsKeepTheResult");
    checkDecimationAndThreadsKeepTheResult();
  }
}

// A camera-resolution photo: scene_01 (800 x 600) upscaled 10x to 8000 x 6000. With the default
// (automatic) decimation quads are searched on 500 x 375 pixels and refined at full resolution:
// every tag is found, with corners within half a pixel of the original scene's resolution.
TEST(AprilTagCameraResolution, FindsEveryTagAtTheDefaults) {
  const cv::Mat scene = cv::imread(kImages + "/scene_01.png", cv::IMREAD_GRAYSCALE);
  ASSERT_FALSE(scene.empty());
  constexpr double kScale = 10;
  cv::Mat photo;
  cv::resize(scene, photo, cv::Size(), kScale, kScale, cv::INTER_LINEAR);
  ASSERT_EQ(photo.size(), cv::Size(8000, 6000));
  const Truth truth = loadTruth("scene_01");
  const ra::DetectionReport report = ra::Detector().detectReport(photo);
  EXPECT_EQ(report.quadDecimate, 16.0f);
  EXPECT_EQ(report.passes, 1);
  std::vector<int> ids;
  double worst = 0;
  for (const ra::Detection& d : report.tags) {
    ids.push_back(d.id);
    for (int k = 0; k < 4; ++k) {
      // Pixel centres: x_photo + 0.5 = kScale * (x_scene + 0.5).
      const glm::dvec2 expected = (truth.corners.at(d.id)[k] + 0.5) * kScale - 0.5;
      worst = std::max(worst, dist(d.corners[k], expected) / kScale);
    }
  }
  EXPECT_EQ(ids, (std::vector<int>{0, 1, 2, 3}));
  EXPECT_LT(worst, 0.5);
  std::printf("8000 x 6000: decimate %.1f, max corner error %.3f px of the 800 x 600 scene\n",
              static_cast<double>(report.quadDecimate), worst);
}

// Small tags in a large image: scene_01 shrunk to 15% (tags about 18 px a side) in a 3840 x 2160
// frame. The automatic decimation (8) loses them; the finer passes (4, 2, 1) find them all.
TEST(AprilTagCameraResolution, SmallTagsInALargeImageAreFoundByTheSecondPass) {
  const cv::Mat scene = cv::imread(kImages + "/scene_01.png", cv::IMREAD_GRAYSCALE);
  ASSERT_FALSE(scene.empty());
  cv::Mat small;
  cv::resize(scene, small, cv::Size(), 0.15, 0.15, cv::INTER_AREA);
  cv::Mat frame(2160, 3840, CV_8UC1, cv::Scalar(95));
  small.copyTo(frame(cv::Rect(1600, 900, small.cols, small.rows)));
  const ra::Detector detector;
  EXPECT_TRUE(detector.detectReport(frame, 8.0f).tags.empty());  // what one pass would give
  const ra::DetectionReport report = detector.detectReport(frame);
  EXPECT_EQ(report.quadDecimate, 1.0f);
  std::vector<int> ids;
  for (const ra::Detection& d : report.tags) ids.push_back(d.id);
  EXPECT_EQ(ids, (std::vector<int>{0, 1, 2, 3}));
  // Large tags need no second pass.
  cv::Mat big;
  cv::resize(scene, big, cv::Size(), 2.7, 2.7, cv::INTER_LINEAR);
  frame(cv::Rect(0, 0, big.cols, big.rows)).setTo(95);
  big.copyTo(frame(cv::Rect(0, 0, big.cols, big.rows)));
  const ra::DetectionReport large = detector.detectReport(frame);
  EXPECT_EQ(large.quadDecimate, 8.0f);
  EXPECT_EQ(large.passes, 1);
}

TEST_P(AprilTagScene, BoardRoi) {
  {
    SCOPED_TRACE("BoardRoiWithinOnePixel");
    checkBoardRoiWithinOnePixel();
  }
  {
    SCOPED_TRACE("BoardRoiFromOneTagUsesAnExactFit");
    checkBoardRoiFromOneTagUsesAnExactFit();
  }
}

TEST_P(AprilTagScene, TagBuilders) {
  {
    SCOPED_TRACE("PolygonThroughTagCentresAndCorners");
    checkPolygonThroughTagCentresAndCorners();
  }
  {
    SCOPED_TRACE("OutOfOrderTagsGiveASelfIntersectingRoi");
    checkOutOfOrderTagsGiveASelfIntersectingRoi();
  }
  {
    SCOPED_TRACE("ConvexHullOfTagCorners");
    checkConvexHullOfTagCorners();
  }
  {
    SCOPED_TRACE("TagFrameRoiMatchesTheBoardGeometry");
    checkTagFrameRoiMatchesTheBoardGeometry();
  }
}

TEST_P(AprilTagScene, Failures) {
  {
    SCOPED_TRACE("MissingTagsAreReportedNotEmpty");
    checkMissingTagsAreReportedNotEmpty();
  }
  {
    SCOPED_TRACE("DuplicatedIdsAreAmbiguous");
    checkDuplicatedIdsAreAmbiguous();
  }
}

double perimeter(const roiclip::PolygonSet& set) {
  double total = 0;
  for (const Path& ring : set.toPaths()) {
    for (std::size_t i = 0; i < ring.size(); ++i)
      total += dist(ring[i], ring[(i + 1) % ring.size()]);
  }
  return total;
}

TEST_P(AprilTagScene, ClippingTheTrueShapesWithTheDetectedRoi) {
  // End to end on the core: each true shape clipped by the board ROI built from the detected tags
  // covers the same area as when clipped by the true ROI, and as a raster of shape AND ROI.
  for (const ra::BoardRoi& roi : board_.rois) {
    const Paths detected = ra::boardRoi(board_, detections_, roi.name).value();
    const Paths& truth = truth_.rois.at(roi.name);
    const cv::Mat roiMask =
        roiclip::opencv::rasterize(truth, roiclip::FillRule::EvenOdd, image_.size());
    for (std::size_t i = 0; i < truth_.shapes.size(); ++i) {
      SCOPED_TRACE(roi.name + " shape " + std::to_string(i));
      const Paths& shape = truth_.shapes[i];
      const roiclip::PolygonSet a =
          roiclip::clip(roiclip::ClipOp::Intersection, shape, detected, roiclip::FillRule::EvenOdd,
                        roiclip::FillRule::EvenOdd);
      const roiclip::PolygonSet b =
          roiclip::clip(roiclip::ClipOp::Intersection, shape, truth, roiclip::FillRule::EvenOdd,
                        roiclip::FillRule::EvenOdd);
      // The ROIs differ by < 0.2 px along their border (BoardRoi check).
      EXPECT_NEAR(a.area(), b.area(), 0.2 * perimeter(b) + 1e-9);
      // Pixel-centre rasters: (shape AND roi) must equal the raster of the clipped polygons, up
      // to centres lying within rounding distance of a crossing vertex.
      const cv::Mat expected =
          roiclip::opencv::rasterize(shape, roiclip::FillRule::EvenOdd, image_.size()) & roiMask;
      const cv::Mat actual = roiclip::opencv::rasterize(b, image_.size());
      EXPECT_LE(cv::countNonZero(expected ^ actual), 2);
      EXPECT_NEAR(b.area(), cv::countNonZero(actual), 0.5 * perimeter(b) + 2.0);
      for (const roiclip::Polygon& polygon : b.polygons) {
        EXPECT_LT(roiclip::signedArea(polygon.outer), 0);
        for (const Path& hole : polygon.holes) EXPECT_GT(roiclip::signedArea(hole), 0);
      }
    }
  }
}

TEST_P(AprilTagScene, ClippingWithASelfIntersectingTagRoi) {
  // tags:0,2,1,3 is a bow-tie through the tag centres; both fill rules must agree with a raster.
  const Paths bowTie = ra::polygonThroughTags(detections_, {0, 2, 1, 3}).value();
  std::map<roiclip::FillRule, double> total;
  for (roiclip::FillRule rule : {roiclip::FillRule::EvenOdd, roiclip::FillRule::NonZero,
                                 roiclip::FillRule::Positive, roiclip::FillRule::Negative}) {
    const cv::Mat roiMask = roiclip::opencv::rasterize(bowTie, rule, image_.size());
    for (std::size_t i = 0; i < truth_.shapes.size(); ++i) {
      SCOPED_TRACE(std::string(roiclip::toString(rule)) + " shape " + std::to_string(i));
      const roiclip::PolygonSet clipped =
          roiclip::clip(roiclip::ClipOp::Intersection, truth_.shapes[i], bowTie,
                        roiclip::FillRule::EvenOdd, rule);
      const cv::Mat expected =
          roiclip::opencv::rasterize(truth_.shapes[i], roiclip::FillRule::EvenOdd, image_.size()) &
          roiMask;
      EXPECT_LE(cv::countNonZero(expected ^ roiclip::opencv::rasterize(clipped, image_.size())), 2);
      total[rule] += clipped.area();
    }
  }
  // The bow-tie winds +1 in one lobe and -1 in the other.
  using roiclip::FillRule;
  EXPECT_GT(total[FillRule::Positive], 100.0);
  EXPECT_GT(total[FillRule::Negative], 100.0);
  EXPECT_NEAR(total[FillRule::Positive] + total[FillRule::Negative], total[FillRule::EvenOdd],
              1e-6 * total[FillRule::EvenOdd]);
  EXPECT_NEAR(total[FillRule::NonZero], total[FillRule::EvenOdd], 1e-6 * total[FillRule::EvenOdd]);
}

std::vector<std::string> sceneNames() {
  std::vector<std::string> names;
  for (int i = 1; i <= 8; ++i) {
    char name[24];  // room for any int: GCC warns on 16 (-Wformat-truncation)
    std::snprintf(name, sizeof name, "scene_%02d", i);
    names.emplace_back(name);
  }
  return names;
}

INSTANTIATE_TEST_SUITE_P(Bundled, AprilTagScene, ::testing::ValuesIn(sceneNames()));

}  // namespace
