// SPDX-License-Identifier: MIT
// processImage() on the bundled scenes (against the generator's exact ground truth) and on
// every per-image failure path.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <roiclip/batch/process.hpp>
#include <roiclip/opencv/rasterize.hpp>

#include "detail/image_file.hpp"
#include "detail/process.hpp"
#include "detail/result_json.hpp"

namespace rb = roiclip::batch;
using Json = nlohmann::json;

namespace {

const std::string kImages = ROICLIP_IMAGES;
const rb::RunOptions kDefaults;

Json loadJson(const std::string& file) {
  std::ifstream in(file);
  EXPECT_TRUE(in.good()) << file;
  return Json::parse(in);
}

roiclip::Paths pathsFrom(const Json& j) {
  roiclip::Paths paths;
  for (const auto& p : j) {
    roiclip::Path path;
    for (const auto& v : p) path.emplace_back(v[0].get<double>(), v[1].get<double>());
    paths.push_back(path);
  }
  return paths;
}

double perimeter(const roiclip::PolygonSet& set) {
  double total = 0;
  for (const auto& ring : set.toPaths()) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const auto d = ring[(i + 1) % ring.size()] - ring[i];
      total += std::hypot(d.x, d.y);
    }
  }
  return total;
}

struct Truth {
  roiclip::Paths shapes;  // all shapes; they do not overlap, so even-odd over all is their union
  Json scene;
};

Truth loadTruth(const std::string& scene) {
  Truth t;
  t.scene = loadJson(kImages + "/" + scene + ".json");
  for (const auto& s : t.scene["shapes"]) {
    const roiclip::Paths p = pathsFrom(s["paths"]);
    t.shapes.insert(t.shapes.end(), p.begin(), p.end());
  }
  return t;
}

roiclip::Paths truthRoi(const Truth& t, const std::string& name) {
  for (const auto& r : t.scene["rois"]) {
    if (r["name"] == name) return pathsFrom(r["paths"]);
  }
  ADD_FAILURE() << "no ROI " << name;
  return {};
}

void expectOrientedRings(const roiclip::PolygonSet& set) {
  for (const auto& poly : set.polygons) {
    EXPECT_LT(roiclip::signedArea(poly.outer), 0.0);
    for (const auto& hole : poly.holes) EXPECT_GT(roiclip::signedArea(hole), 0.0);
  }
}

class BatchScene : public ::testing::TestWithParam<std::string> {};

// The stated tolerance. cv::findContours traces the centres of the boundary pixels of the
// thresholded image, so the contour polygon lies about half a pixel inside the true boundary
// (a 1-px line has zero contour area): the measured area is short by about 0.5 px times the
// boundary length inside the ROI. Allowed: |measured - truth| <= 0.5 px * perimeter of the true
// clipped region (which includes the ROI cut edges, where the clip is exact) + 1% of the truth.
// Measured on the eight scenes: the measured area is 0.14 to 0.30 px * perimeter short.
constexpr double kPerimeterTolerance = 0.5;
constexpr double kRelativeTolerance = 0.01;
constexpr double kTruthBand = 1.0;

TEST_P(BatchScene, BoardRoiAreasMatchGroundTruth) {
  const std::string scene = GetParam();
  const Truth truth = loadTruth(scene);
  const cv::Mat image = cv::imread(kImages + "/" + scene + ".png", cv::IMREAD_UNCHANGED);
  ASSERT_FALSE(image.empty());
  rb::RunOptions options;
  options.boardFile = kImages + "/board.json";
  for (const std::string roiName : {"inspection", "window"}) {
    options.rois = {"board:" + roiName};
    const rb::ImageResult r = rb::processImage(image, options);
    ASSERT_EQ(r.status, rb::Status::Ok) << scene << " " << roiName << ": " << r.reason;
    EXPECT_EQ(r.offBandMismatches(), 0);
    ASSERT_TRUE(r.vectorVsOpenCv.has_value());  // even-odd both: the cv::fillPoly route too
    EXPECT_EQ(r.width, image.cols);
    EXPECT_EQ(r.height, image.rows);
    EXPECT_EQ(r.tags.size(), 4u);
    expectOrientedRings(r.clipped);
    // Contours never overlap, so the per-contour clips add up to the clip of all of them.
    EXPECT_NEAR(r.contourClippedAreaSum, r.clippedArea, 1e-6 * (1 + r.clippedArea));

    const roiclip::PolygonSet expected =
        roiclip::intersect(truth.shapes, truthRoi(truth, roiName), roiclip::FillRule::EvenOdd);
    const double tolerance =
        kPerimeterTolerance * perimeter(expected) + kRelativeTolerance * expected.area();
    EXPECT_NEAR(r.clippedArea, expected.area(), tolerance) << scene << " " << roiName;
    EXPECT_LT(r.clippedArea, expected.area()) << "contours run through boundary pixel centres";
    std::cout << "[ figures  ] " << scene << " " << roiName << ": clipped " << r.clippedArea
              << " px2, truth " << expected.area() << " px2, diff "
              << r.clippedArea - expected.area() << ", tolerance " << tolerance << ", perimeter "
              << perimeter(expected) << "\n";
    // Pixel by pixel: the clipped region agrees with the true one everywhere farther than
    // kTruthBand px from a true shape edge, a true ROI edge or the fitted ROI's edge (blur,
    // threshold and tracing through pixel centres move boundaries by up to about a pixel).
    roiclip::Paths edges = truth.shapes;
    const roiclip::Paths trueRoi = truthRoi(truth, roiName);
    edges.insert(edges.end(), trueRoi.begin(), trueRoi.end());
    edges.insert(edges.end(), r.roi.begin(), r.roi.end());
    const cv::Size size(image.cols, image.rows);
    const roiclip::opencv::MaskComparison vsTruth = roiclip::opencv::compareMasks(
        roiclip::opencv::rasterize(expected, size), rb::renderMask(r), kTruthBand, edges);
    EXPECT_TRUE(vsTruth.agreesOffBand()) << scene << " " << roiName << ": " << vsTruth;
    std::cout << "[ figures  ] " << scene << " " << roiName << " vs truth: " << vsTruth << "\n";
    const roiclip::PolygonSet roiTruth =
        roiclip::simplify(truthRoi(truth, roiName), roiclip::FillRule::EvenOdd);
    // Fitted board ROI within 0.17 px of the truth (images/README.md): area within 0.5 px * P.
    EXPECT_NEAR(r.roiArea, roiTruth.area(), 0.5 * perimeter(roiTruth));
  }
}

TEST_P(BatchScene, DefaultHullContainsEveryTagCorner) {
  const std::string scene = GetParam();
  const Truth truth = loadTruth(scene);
  const cv::Mat image = cv::imread(kImages + "/" + scene + ".png", cv::IMREAD_GRAYSCALE);
  const rb::ImageResult r = rb::processImage(image, kDefaults);
  ASSERT_EQ(r.status, rb::Status::Ok) << r.reason;
  EXPECT_EQ(r.offBandMismatches(), 0);
  roiclip::Paths corners;
  for (const auto& tag : truth.scene["tags"])
    corners.push_back(pathsFrom(Json::array({tag["corners"]}))[0]);
  // The hull of the true corners vs the ROI built from detected corners (0.23 px error).
  std::vector<cv::Point2f> pts;
  for (const auto& c : corners) {
    for (const auto& p : c) pts.emplace_back(static_cast<float>(p.x), static_cast<float>(p.y));
  }
  std::vector<cv::Point2f> hull;
  cv::convexHull(pts, hull);
  const double hullArea = cv::contourArea(hull);
  const double hullPerimeter = cv::arcLength(hull, true);
  // The region is the hull minus the tag quads (which lie inside it and do not overlap).
  double tagsArea = 0, tagsPerimeter = 0;
  for (const auto& c : corners) {
    std::vector<cv::Point2f> quad;
    for (const auto& p : c) quad.emplace_back(static_cast<float>(p.x), static_cast<float>(p.y));
    tagsArea += std::abs(cv::contourArea(quad));
    tagsPerimeter += cv::arcLength(quad, true);
  }
  EXPECT_NEAR(r.roiArea, hullArea - tagsArea, 0.25 * (hullPerimeter + tagsPerimeter));
  ASSERT_EQ(r.rois.size(), 1u);
  EXPECT_EQ(r.rois[0].name, "hull");
  EXPECT_EQ(r.rois[0].area, r.roiArea);
  EXPECT_EQ(r.excludedTags.size(), r.tags.size());
  // Every clipped vertex lies in the ROI's bounding box.
  const cv::Rect2f box = cv::boundingRect(hull);
  for (const auto& ring : r.clipped.toPaths()) {
    for (const auto& p : ring) {
      EXPECT_GE(p.x, box.x - 0.5);
      EXPECT_LE(p.x, box.x + box.width + 0.5);
      EXPECT_GE(p.y, box.y - 0.5);
      EXPECT_LE(p.y, box.y + box.height + 0.5);
    }
  }
  // The overlay is the image's width and taller by the caption band above it, in colour; the
  // mask is the clipped region.
  const cv::Mat overlay = rb::renderOverlay(image, r);
  EXPECT_EQ(overlay.cols, image.cols);
  ASSERT_GT(overlay.rows, image.rows);
  const int band = overlay.rows - image.rows;
  EXPECT_EQ(overlay.type(), CV_8UC3);
  // Outside the ROI the overlay is the image dimmed, from the first row on (the caption is in
  // its own band, not over the image).
  cv::Mat roiMask = cv::Mat::zeros(image.size(), CV_8U);
  std::vector<cv::Point> hullInt;
  for (const auto& p : hull) hullInt.emplace_back(cvRound(p.x), cvRound(p.y));
  cv::fillConvexPoly(roiMask, hullInt, 255);
  cv::Mat near;
  cv::dilate(roiMask, near, cv::Mat(), {-1, -1}, 4);
  // The ROI's name is written just above its top-left vertex.
  const auto topLeft = std::min_element(hullInt.begin(), hullInt.end(),
                                        [](auto a, auto b) { return a.x + a.y < b.x + b.y; });
  cv::rectangle(near, cv::Rect(topLeft->x - 10, topLeft->y - 40, 120, 40), 255, cv::FILLED);
  int dimmedChecked = 0;
  for (int y = 0; y < image.rows; y += 7) {
    for (int x = 0; x < image.cols; x += 7) {
      if (near.at<uchar>(y, x) != 0) continue;
      const int original = image.at<uchar>(y, x);
      EXPECT_NEAR(overlay.at<cv::Vec3b>(y + band, x)[1], 0.35 * original, 1.0) << x << "," << y;
      ++dimmedChecked;
    }
  }
  EXPECT_GT(dimmedChecked, 100);
  const cv::Mat mask = rb::renderMask(r);
  EXPECT_EQ(mask.size(), image.size());
  EXPECT_NEAR(cv::countNonZero(mask), r.clippedArea, 0.1 * r.clippedArea);
}

INSTANTIATE_TEST_SUITE_P(Bundled, BatchScene,
                         ::testing::Values("scene_01", "scene_02", "scene_03", "scene_04",
                                           "scene_05", "scene_06", "scene_07", "scene_08"));

// --- image types -----------------------------------------------------------------------------

TEST(BatchImageTypes, SixteenBitAndColourGiveTheSameResultAsGray) {
  const cv::Mat gray = cv::imread(kImages + "/scene_02.png", cv::IMREAD_GRAYSCALE);
  ASSERT_EQ(gray.type(), CV_8UC1);
  cv::Mat bgr, bgra, gray16;
  cv::cvtColor(gray, bgr, cv::COLOR_GRAY2BGR);
  cv::cvtColor(gray, bgra, cv::COLOR_GRAY2BGRA);
  gray.convertTo(gray16, CV_16U, 257.0);  // 255 * 257 = 65535: exact round trip
  const rb::ImageResult ref = rb::processImage(gray, kDefaults);
  ASSERT_EQ(ref.status, rb::Status::Ok);
  for (const cv::Mat& m : {bgr, bgra, gray16}) {
    const rb::ImageResult r = rb::processImage(m, kDefaults);
    ASSERT_EQ(r.status, rb::Status::Ok) << r.reason;
    EXPECT_EQ(r.tags.size(), ref.tags.size());
    EXPECT_EQ(r.contoursIn, ref.contoursIn);
    EXPECT_DOUBLE_EQ(r.clippedArea, ref.clippedArea);
  }
}

// --- failure paths ---------------------------------------------------------------------------

TEST(BatchFailures, EmptyImageIsFailedInvalidInput) {
  const rb::ImageResult r = rb::processImage(cv::Mat(), kDefaults);
  EXPECT_EQ(r.status, rb::Status::Failed);
  EXPECT_EQ(r.failure, rb::FailureKind::InvalidInput);
  EXPECT_FALSE(r.reason.empty());
}

TEST(BatchFailures, ImageWithoutTagsIsNoRoi) {
  cv::Mat blank(240, 320, CV_8UC1, cv::Scalar(230));
  cv::circle(blank, {160, 120}, 40, cv::Scalar(30), cv::FILLED);  // contours, but no tags
  const rb::ImageResult r = rb::processImage(blank, kDefaults);
  EXPECT_EQ(r.status, rb::Status::NoRoi);
  EXPECT_EQ(r.failure, rb::FailureKind::NoTags);
  EXPECT_NE(r.reason.find("no tag36h11 tags"), std::string::npos) << r.reason;
  EXPECT_TRUE(r.clipped.empty());
  EXPECT_EQ(r.contoursIn, 0);
}

TEST(BatchFailures, MissingRequiredIdIsNoRoiNamingTheId) {
  const cv::Mat image = cv::imread(kImages + "/scene_03.png", cv::IMREAD_GRAYSCALE);
  rb::RunOptions options;
  options.rois = {"tags:0,1,2,9"};
  const rb::ImageResult r = rb::processImage(image, options);
  EXPECT_EQ(r.status, rb::Status::NoRoi);
  EXPECT_EQ(r.failure, rb::FailureKind::MissingTags);
  ASSERT_TRUE(r.missingTags.has_value());
  EXPECT_EQ(r.missingTags->missing, std::vector<int>{9});
  EXPECT_NE(r.reason.find("9"), std::string::npos) << r.reason;
  EXPECT_EQ(r.tags.size(), 4u);  // what was seen is still reported
}

TEST(BatchFailures, BadOptionsAreFailedInvalidInput) {
  const cv::Mat image = cv::imread(kImages + "/scene_03.png", cv::IMREAD_GRAYSCALE);
  rb::RunOptions badSpec;
  badSpec.rois = {"polygon:1,2"};
  EXPECT_EQ(rb::processImage(image, badSpec).failure, rb::FailureKind::InvalidInput);
  rb::RunOptions noBoard;
  noBoard.rois = {"board:inspection"};
  const rb::ImageResult r = rb::processImage(image, noBoard);
  EXPECT_EQ(r.status, rb::Status::Failed);
  EXPECT_NE(r.reason.find("--board"), std::string::npos) << r.reason;
  EXPECT_THROW(rb::Processor{noBoard}, roiclip::InvalidInputError);
}

TEST(BatchFailures, UnreadableFileThrowsNamingIt) {
  const std::string file = std::string(ROICLIP_TEST_DATA) + "/batch/corrupt.png";
  try {
    (void)rb::readImage(file);
    FAIL() << "no exception";
  } catch (const roiclip::InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("corrupt.png"), std::string::npos);
  }
}

// --- options parsing -------------------------------------------------------------------------

TEST(BatchOptions, ContourMethodAndPolarity) {
  rb::ContourOptions o;
  rb::parseContourMethod("threshold:90", o);
  EXPECT_EQ(o.method, rb::ContourMethod::Threshold);
  EXPECT_EQ(o.threshold, 90);
  rb::parseContourMethod("adaptive", o);
  EXPECT_EQ(o.method, rb::ContourMethod::Adaptive);
  for (const char* bad : {"threshold:", "threshold:300", "threshold:9x", "sobel", ""}) {
    EXPECT_THROW(rb::parseContourMethod(bad, o), roiclip::InvalidInputError) << bad;
  }
  EXPECT_EQ(rb::parsePolarity("light"), rb::Polarity::Light);
  EXPECT_THROW(rb::parsePolarity("bright"), roiclip::InvalidInputError);
}

TEST(BatchOptions, EveryContourMethodRunsAndPassesTheMaskCheck) {
  const cv::Mat image = cv::imread(kImages + "/scene_04.png", cv::IMREAD_GRAYSCALE);
  for (const char* method : {"otsu", "adaptive", "canny", "threshold:120"}) {
    rb::RunOptions options;
    rb::parseContourMethod(method, options.contours);
    options.contours.approxEpsilon = 1.5;  // self-intersecting contours are allowed
    const rb::ImageResult r = rb::processImage(image, options);
    EXPECT_EQ(r.status, rb::Status::Ok) << method << ": " << r.reason;
    EXPECT_GT(r.contoursOut, 0) << method;
    EXPECT_EQ(r.offBandMismatches(), 0) << method;
  }
}

TEST(BatchOptions, MinAreaDropsSmallContours) {
  const cv::Mat image = cv::imread(kImages + "/scene_06.png", cv::IMREAD_GRAYSCALE);
  rb::RunOptions all;
  rb::RunOptions big;
  big.contours.minArea = 200.0;
  const rb::ImageResult a = rb::processImage(image, all);
  const rb::ImageResult b = rb::processImage(image, big);
  EXPECT_LT(b.contoursIn, a.contoursIn);
  for (const auto& c : b.contours) EXPECT_GE(c.inputArea, 200.0 - 1e-9);
}

// A lone pixel or a 1 px wide line is a contour without an area: counted, not kept as an object.
// --min-area 0.25 drops exactly those (findContours areas are multiples of 0.5), so both runs keep
// the same objects and clip the same area.
TEST(BatchOptions, ContoursWithoutAreaAreCountedNotKept) {
  const cv::Mat image = cv::imread(kImages + "/scene_01.png", cv::IMREAD_GRAYSCALE);
  rb::RunOptions all;
  all.contours.method = roiclip::opencv::ContourMethod::Adaptive;
  rb::RunOptions positive = all;
  positive.contours.minArea = 0.25;
  const rb::ImageResult a = rb::processImage(image, all);
  const rb::ImageResult b = rb::processImage(image, positive);
  ASSERT_EQ(a.status, rb::Status::Ok) << a.reason;
  ASSERT_EQ(b.status, rb::Status::Ok) << b.reason;
  EXPECT_GT(a.contoursDegenerate, 50);
  EXPECT_EQ(b.contoursDegenerate, 0);
  EXPECT_EQ(a.contoursIn, b.contoursIn);
  EXPECT_EQ(a.contours.size(), std::size_t(a.contoursIn));
  for (const auto& c : a.contours) EXPECT_GT(c.inputArea, 0.0) << c.contourIndex;
  EXPECT_EQ(a.clippedArea, b.clippedArea);
  EXPECT_EQ(a.contoursOut, b.contoursOut);
  const Json j = Json::parse(rb::resultToJson(a));
  EXPECT_EQ(j["contours_degenerate"], a.contoursDegenerate);
}

TEST(BatchJson, ResultJsonHasEveryFigure) {
  const cv::Mat image = cv::imread(kImages + "/scene_07.png", cv::IMREAD_GRAYSCALE);
  const rb::ImageResult r = rb::processImage(image, kDefaults);
  const Json j = Json::parse(rb::resultToJson(r, "scene_07.png"));
  EXPECT_EQ(j["image"], "scene_07.png");
  EXPECT_EQ(j["status"], "ok");
  EXPECT_EQ(j["tags"].size(), 4u);
  EXPECT_EQ(j["contours_in"], r.contoursIn);
  EXPECT_DOUBLE_EQ(j["clipped_area"].get<double>(), r.clippedArea);
  EXPECT_EQ(j["mask_check"]["off_band_mismatches"], 0);
  ASSERT_TRUE(j["mask_check"].contains("opencv"));
  EXPECT_EQ(j["schema_version"], rb::kSchemaVersion);
  EXPECT_EQ(j["roiclip_version"], rb::roiclipVersion());
  // The GeoJSON features give back the clipped area: closed rings, outer ring first.
  ASSERT_EQ(j["clipped"]["type"], "FeatureCollection");
  const Json& features = j["clipped"]["features"];
  ASSERT_EQ(features.size(), r.clipped.polygons.size());
  roiclip::PolygonSet back;
  std::set<int> contours;
  for (const auto& f : features) {
    EXPECT_EQ(f["type"], "Feature");
    EXPECT_EQ(f["geometry"]["type"], "Polygon");
    roiclip::Paths rings = pathsFrom(f["geometry"]["coordinates"]);
    for (roiclip::Path& ring : rings) {
      ASSERT_GE(ring.size(), 4u);
      EXPECT_EQ(ring.front(), ring.back());
      ring.pop_back();
    }
    roiclip::Polygon poly;
    poly.outer = rings[0];
    poly.holes.assign(rings.begin() + 1, rings.end());
    EXPECT_EQ(f["properties"]["holes"], poly.holes.size());
    roiclip::PolygonSet one;
    one.polygons.push_back(poly);
    EXPECT_NEAR(f["properties"]["area"].get<double>(), one.area(), 1e-9 * one.area());
    back.polygons.push_back(poly);
    // Every polygon is traced to its source contour (they do not touch in this scene).
    ASSERT_TRUE(f["properties"]["contour_index"].is_number_integer()) << f["properties"];
    contours.insert(f["properties"]["contour_index"].get<int>());
    EXPECT_EQ(f["properties"]["rois"], Json::array({"hull"}));
  }
  EXPECT_NEAR(back.area(), r.clippedArea, 1e-6 * r.clippedArea);
  EXPECT_EQ(static_cast<int>(contours.size()), r.contoursOut);
  ASSERT_EQ(static_cast<int>(j["contours"].size()), r.contoursOut);
  std::size_t linked = 0;
  for (const auto& c : j["contours"]) {
    for (const auto& i : c["features"]) {
      EXPECT_EQ(features[i.get<std::size_t>()]["properties"]["contour_index"], c["contour_index"]);
      ++linked;
    }
  }
  EXPECT_EQ(linked, features.size());
}

}  // namespace

// --- open polylines (Canny edges) ------------------------------------------------------------

namespace {

TEST(BatchEdges, SceneEdgesAreClippedToTheRoi) {
  const cv::Mat image = cv::imread(kImages + "/scene_01.png", cv::IMREAD_GRAYSCALE);
  rb::RunOptions options;
  options.rois = {"board:window"};
  options.boardFile = kImages + "/board.json";
  options.contours.openEdges = true;
  const rb::ImageResult r = rb::processImage(image, options);
  ASSERT_EQ(r.status, rb::Status::Ok) << r.reason;
  EXPECT_GT(r.edgesIn, 0);
  ASSERT_FALSE(r.edges.empty());
  std::vector<cv::Point2f> roi;
  for (const auto& p : r.roi[0]) roi.emplace_back(static_cast<float>(p.x), static_cast<float>(p.y));
  for (const auto& line : r.edges) {
    for (const auto& p : line) {
      EXPECT_GE(cv::pointPolygonTest(
                    roi, cv::Point2f(static_cast<float>(p.x), static_cast<float>(p.y)), true),
                -1e-3);
    }
  }
  // The window holds the figure-eight stroke and the frame: their edges are most of the
  // clipped length, at least the window-clipped contour perimeter's order of magnitude.
  EXPECT_GT(r.edgeLength, 100.0);
  const Json j = Json::parse(rb::resultToJson(r, "scene_01.png"));
  EXPECT_DOUBLE_EQ(j["edges"]["length"].get<double>(), r.edgeLength);
}

TEST(BatchEdges, ApproxEpsilonAlsoSimplifiesTheEdges) {
  // cv::approxPolyDP takes no double points; the edges once failed every image with --approx.
  const cv::Mat image = cv::imread(kImages + "/scene_01.png", cv::IMREAD_GRAYSCALE);
  rb::RunOptions options;
  options.contours.openEdges = true;
  options.keepTags = true;  // the tags' dense edges, as when this was measured
  const rb::ImageResult exact = rb::processImage(image, options);
  options.contours.approxEpsilon = 1.5;
  const rb::ImageResult approx = rb::processImage(image, options);
  ASSERT_EQ(approx.status, rb::Status::Ok) << approx.reason;
  ASSERT_EQ(exact.status, rb::Status::Ok) << exact.reason;
  std::size_t exactPoints = 0, approxPoints = 0;
  for (const auto& l : exact.edges) exactPoints += l.size();
  for (const auto& l : approx.edges) approxPoints += l.size();
  EXPECT_LT(approxPoints, exactPoints / 2);
  EXPECT_NEAR(approx.edgeLength, exact.edgeLength, 0.2 * exact.edgeLength);
}

// --- core calls per image --------------------------------------------------------------------

TEST(BatchCoreCalls, OnePerContourPlusThreeAndTheMaskCheckDoesNotClip) {
  // One simplify of the ROI and one difference taking the tags out; per contour one clip (its
  // input area is the shoelace sum, opencv::pixelContourArea); one clip of all contours
  // together, which the mask check takes as it is: N + 3 for N contours, N + 2 with the tags
  // kept. With approxPolyDP each contour's input area takes one simplify more: 2N + 3.
  rb::RunOptions keep = kDefaults;
  keep.keepTags = true;
  rb::RunOptions approximate = kDefaults;
  approximate.contours.approxEpsilon = 1.5;
  for (const char* scene : {"scene_01", "scene_04", "scene_07"}) {
    const cv::Mat image = cv::imread(kImages + "/" + scene + ".png", cv::IMREAD_GRAYSCALE);
    rb::detail::CoreCalls calls;
    const rb::ImageResult r = rb::detail::processCountingCoreCalls(image, kDefaults, calls);
    ASSERT_EQ(r.status, rb::Status::Ok) << scene << ": " << r.reason;
    const int n = r.contoursIn;
    ASSERT_GT(n, 0) << scene;
    EXPECT_EQ(calls.simplify, 1) << scene;
    EXPECT_EQ(calls.clip, n + 2) << scene;
    EXPECT_EQ(calls.clipLines, 0) << scene;
    EXPECT_EQ(calls.total(), n + 3) << scene;
    rb::detail::CoreCalls kept;
    const rb::ImageResult k = rb::detail::processCountingCoreCalls(image, keep, kept);
    ASSERT_EQ(k.status, rb::Status::Ok) << scene << ": " << k.reason;
    EXPECT_EQ(kept.total(), k.contoursIn + 2) << scene;
    rb::detail::CoreCalls approx;
    const rb::ImageResult a = rb::detail::processCountingCoreCalls(image, approximate, approx);
    ASSERT_EQ(a.status, rb::Status::Ok) << scene << ": " << a.reason;
    // Every outer contour's area is a simplify; only those with an area are clipped.
    EXPECT_EQ(approx.total(), 2 * a.contoursIn + a.contoursDegenerate + 3) << scene;
    // The same result as the uncounted pipeline.
    const rb::ImageResult plain = rb::processImage(image, kDefaults);
    EXPECT_EQ(plain.clippedArea, r.clippedArea) << scene;
    EXPECT_EQ(plain.clipped.polygons.size(), r.clipped.polygons.size()) << scene;
  }
  // Open edges add one clipLines; no ROI means no core call at all.
  const cv::Mat image = cv::imread(kImages + "/scene_01.png", cv::IMREAD_GRAYSCALE);
  rb::RunOptions edges;
  edges.contours.openEdges = true;
  rb::detail::CoreCalls withEdges;
  const rb::ImageResult e = rb::detail::processCountingCoreCalls(image, edges, withEdges);
  ASSERT_EQ(e.status, rb::Status::Ok) << e.reason;
  EXPECT_EQ(withEdges.clipLines, 1);
  EXPECT_EQ(withEdges.total(), e.contoursIn + 4);
  rb::detail::CoreCalls none;
  const rb::ImageResult blank = rb::detail::processCountingCoreCalls(
      cv::Mat(64, 64, CV_8UC1, cv::Scalar(255)), kDefaults, none);
  EXPECT_EQ(blank.status, rb::Status::NoRoi);
  EXPECT_EQ(none.total(), 0);
}

TEST(BatchCoreCalls, ClippedHoldsEveryContoursPartWithParentsAcrossContours) {
  // ImageResult::clipped is all contours AND ROI in one clip: its area is the per-contour sum
  // (contours do not overlap), and an island inside another contour's hole is that hole's
  // child, which per-contour results alone cannot say (RETR_CCOMP makes the island a top-level
  // contour of its own).
  cv::Mat image = cv::imread(kImages + "/scene_07.png", cv::IMREAD_GRAYSCALE);
  cv::rectangle(image, cv::Rect(250, 220, 160, 160), cv::Scalar(255), cv::FILLED);
  cv::rectangle(image, cv::Rect(260, 230, 140, 140), cv::Scalar(0), cv::FILLED);
  cv::rectangle(image, cv::Rect(290, 260, 80, 80), cv::Scalar(255), cv::FILLED);  // hole
  cv::rectangle(image, cv::Rect(315, 285, 30, 30), cv::Scalar(0), cv::FILLED);    // island
  const rb::ImageResult r = rb::processImage(image, kDefaults);
  ASSERT_EQ(r.status, rb::Status::Ok) << r.reason;
  EXPECT_NEAR(r.clippedArea, r.contourClippedAreaSum, 1e-9 * r.clippedArea);
  int nested = 0;
  for (const roiclip::Polygon& p : r.clipped.polygons) {
    if (p.parent < 0) continue;
    ++nested;
    const roiclip::Polygon& outer = r.clipped.polygons[static_cast<std::size_t>(p.parent)];
    ASSERT_GE(p.parentHole, 0);
    EXPECT_LT(static_cast<std::size_t>(p.parentHole), outer.holes.size());
  }
  EXPECT_EQ(nested, 1);
  for (const rb::ContourResult& c : r.contours) {
    for (const roiclip::Polygon& p : c.clipped.polygons) EXPECT_EQ(p.parent, -1);
  }
}

}  // namespace
