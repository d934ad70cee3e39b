// SPDX-License-Identifier: MIT
// Vector-vs-raster proof: clip results rasterised exactly must match the raster route (our
// rasteriser and OpenCV's fillPoly) off a thin band around the operands' edges.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <roiclip/opencv/opencv.hpp>

#include "scenes.hpp"

namespace roiclip::opencv {
namespace {

using testing::drawScene;
using testing::makeRois;
using testing::SceneKind;

constexpr FillRule kRules[] = {FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive,
                               FillRule::Negative};

// The core's clip of the operands, checked against the raster routes.
MaskCheck clipAndCheck(const Paths& subject, const Paths& roi, FillRule subjectRule,
                       FillRule roiRule, cv::Size size, const MaskCheckOptions& options = {}) {
  const PolygonSet result = clip(options.op, subject, roi, subjectRule, roiRule, options.grid);
  return checkRoiClip(subject, roi, result, subjectRule, roiRule, size, options);
}

TEST(CompareMasks, CountsAndIou) {
  cv::Mat e(10, 10, CV_8UC1, cv::Scalar(0)), a(10, 10, CV_8UC1, cv::Scalar(0));
  e(cv::Rect(0, 0, 4, 5)).setTo(255);  // 20 px
  a(cv::Rect(2, 0, 4, 5)).setTo(7);    // 20 px, 10 shared; any non-zero value is on
  const MaskComparison c = compareMasks(e, a, 0.0, Paths{});
  EXPECT_EQ(c.onlyExpected, 10);
  EXPECT_EQ(c.onlyActual, 10);
  EXPECT_EQ(c.both, 10);
  EXPECT_DOUBLE_EQ(c.iou, 10.0 / 30);
  EXPECT_EQ(c.bandPixels, 0);
  EXPECT_FALSE(c.agreesOffBand());
  // A band of 1 px around the segment x = 3 (from y = -1 to 10) covers columns 2..4, which
  // holds every mismatching pixel except columns 0..1 and 5.
  const MaskComparison banded = compareMasks(e, a, 1.0, Paths{{{3, -1}, {3, 10}}});
  EXPECT_EQ(banded.bandPixels, 30);
  EXPECT_EQ(banded.offBandOnlyExpected, 10);
  EXPECT_EQ(banded.offBandOnlyActual, 5);
  std::ostringstream os;
  os << banded;
  EXPECT_NE(os.str().find("only expected 10, only actual 5"), std::string::npos) << os.str();
  EXPECT_NE(os.str().find("30 band pixels ignored"), std::string::npos) << os.str();
  EXPECT_DOUBLE_EQ(compareMasks(a, a, 0.0, {}).iou, 1.0);
  EXPECT_TRUE(compareMasks(cv::Mat::zeros(3, 3, CV_8U), cv::Mat::zeros(3, 3, CV_8U), 0.0, {})
                  .agreesOffBand());
  EXPECT_THROW(compareMasks(e, a(cv::Rect(0, 0, 9, 9)), 0.0, {}), InvalidInputError);
  EXPECT_THROW(compareMasks(e, cv::Mat(10, 10, CV_32F), 0.0, {}), InvalidInputError);
  EXPECT_THROW(compareMasks(e, a, -1.0, {}), InvalidInputError);
}

TEST(BoundaryBand, MatchesPerPixelDistance) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(-3, 23);
  const cv::Size size(20, 16);
  for (int iter = 0; iter < 200; ++iter) {
    const Paths paths = {
        {{coord(rng), coord(rng)}, {coord(rng), coord(rng)}, {coord(rng), coord(rng)}}};
    const double band = std::uniform_real_distribution<double>(0, 3)(rng);
    const cv::Mat mask = boundaryBandMask(paths, band, size);
    for (int r = 0; r < size.height; ++r) {
      for (int c = 0; c < size.width; ++c) {
        // Brute-force distance to the closed segments.
        double best = INFINITY;
        for (int i = 0; i < 3; ++i) {
          const cv::Point2d a(paths[0][i].x, paths[0][i].y);
          const cv::Point2d b(paths[0][(i + 1) % 3].x, paths[0][(i + 1) % 3].y);
          const cv::Point2d d = b - a, p(c, r);
          const double t = std::clamp((p - a).dot(d) / d.dot(d), 0.0, 1.0);
          best = std::min(best, cv::norm(a + t * d - p));
        }
        if (std::fabs(best - band) < 1e-9) continue;  // too close to call in floating point
        EXPECT_EQ(mask.at<std::uint8_t>(r, c) != 0, best <= band)
            << "pixel " << c << "," << r << " distance " << best << " band " << band;
      }
    }
  }
}

struct Contoured {
  std::vector<std::vector<cv::Point>> contours;
  std::vector<cv::Vec4i> hierarchy;
};

Contoured findAll(const cv::Mat& mask, int method = cv::CHAIN_APPROX_SIMPLE) {
  Contoured c;
  cv::findContours(mask, c.contours, c.hierarchy, cv::RETR_CCOMP, method);
  return c;
}

/// Subject variants of one scene: raw contours (both chain methods, with and without
/// hierarchy orientation) and approxPolyDP at several epsilons, which makes crossings.
std::vector<std::pair<std::string, Paths>> subjectVariants(const cv::Mat& mask) {
  std::vector<std::pair<std::string, Paths>> out;
  const Contoured simple = findAll(mask);
  out.emplace_back("contours", fromContours(simple.contours));
  out.emplace_back("contours+hierarchy", fromContours(simple.contours, simple.hierarchy));
  out.emplace_back("chain-none", fromContours(findAll(mask, cv::CHAIN_APPROX_NONE).contours));
  for (double eps : {0.7, 2.0, 5.0, 12.0}) {
    std::vector<std::vector<cv::Point>> approx(simple.contours.size());
    for (std::size_t i = 0; i < approx.size(); ++i) {
      cv::approxPolyDP(simple.contours[i], approx[i], eps, true);
    }
    out.emplace_back("approx" + std::to_string(eps).substr(0, 4), fromContours(approx));
  }
  return out;
}

/// Number of pairs of non-adjacent edges that properly cross, in all paths together (a cheap
/// witness that the approxPolyDP variants do self-intersect).
int countCrossings(const Paths& paths) {
  std::vector<std::pair<Point, Point>> edges;
  for (const Path& p : paths) {
    for (std::size_t i = 0; i < p.size(); ++i) edges.emplace_back(p[i], p[(i + 1) % p.size()]);
  }
  auto orient = [](Point a, Point b, Point c) {
    const double v = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    return (v > 0) - (v < 0);
  };
  int n = 0;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const auto [a, b] = edges[i];
      const auto [c, d] = edges[j];
      if (orient(a, b, c) * orient(a, b, d) < 0 && orient(c, d, a) * orient(c, d, b) < 0) ++n;
    }
  }
  return n;
}

struct Summary {
  int checks = 0;
  int openCvChecks = 0;
  double minIou = 1.0;
  double minOpenCvIou = 1.0;
  std::int64_t clippedPixels = 0;    // pixels set in both (a) and (b), over all checks
  std::int64_t differingPixels = 0;  // pixels set in only one of (a) and (b), over all checks
  void add(const MaskCheck& check) {
    ++checks;
    minIou = std::min(minIou, check.vectorVsRaster.iou);
    clippedPixels += check.vectorVsRaster.both;
    differingPixels += check.vectorVsRaster.onlyExpected + check.vectorVsRaster.onlyActual;
    if (check.vectorVsOpenCv) {
      ++openCvChecks;
      minOpenCvIou = std::min(minOpenCvIou, check.vectorVsOpenCv->iou);
    }
  }
  [[nodiscard]] double overallIou() const {
    return clippedPixels == 0 ? 1.0
                              : double(clippedPixels) / double(clippedPixels + differingPixels);
  }
};

void checkScene(const std::string& name, const cv::Mat& mask, Summary& summary) {
  const cv::Size size = mask.size();
  for (const auto& [variant, subject] : subjectVariants(mask)) {
    for (const auto& roi : makeRois(size)) {
      for (FillRule rule : kRules) {
        const MaskCheck check = clipAndCheck(subject, roi.paths, rule, rule, size);
        summary.add(check);
        EXPECT_TRUE(check.vectorVsRaster.agreesOffBand())
            << name << " " << variant << " roi " << roi.name << " rule " << toString(rule) << ": "
            << check.vectorVsRaster;
        if (check.vectorVsOpenCv) {
          EXPECT_TRUE(check.vectorVsOpenCv->agreesOffBand())
              << name << " " << variant << " roi " << roi.name
              << " vs OpenCV: " << *check.vectorVsOpenCv;
        }
      }
    }
  }
}

void report(const std::string& what, const Summary& s) {
  std::cout << what << ": " << s.checks << " checks (" << s.openCvChecks
            << " also vs cv::fillPoly), " << s.clippedPixels
            << " clipped pixels; IoU vs exact raster: overall " << s.overallIou() << ", worst "
            << s.minIou << ", worst IoU vs cv::fillPoly " << s.minOpenCvIou << "\n";
}

class SyntheticScenes : public ::testing::TestWithParam<SceneKind> {};

TEST_P(SyntheticScenes, ClipMatchesRasterMasksOffBand) {
  Summary summary;
  for (unsigned seed : {1u, 2u}) {
    const cv::Mat mask = drawScene(GetParam(), {240, 180}, seed);
    ASSERT_GT(cv::countNonZero(mask), 100);
    checkScene(std::string(testing::sceneName(GetParam())) + " seed " + std::to_string(seed), mask,
               summary);
  }
  report(testing::sceneName(GetParam()), summary);
  EXPECT_GT(summary.clippedPixels, 1000);  // the checks compared real content
  // Exact route: the only differences are pixel centres within 0.05 px of an edge. Contour
  // edges run through pixel centres, so there are some, but few overall (a single tiny clipped
  // piece can still have a low IoU of its own).
  EXPECT_GT(summary.overallIou(), 0.95);
}

INSTANTIATE_TEST_SUITE_P(Scenes, SyntheticScenes,
                         ::testing::Values(SceneKind::Blobs, SceneKind::Text, SceneKind::ThinLines,
                                           SceneKind::SelfTouching),
                         [](const auto& param) { return testing::sceneName(param.param); });

TEST(SyntheticScene, ApproxPolyDpVariantsSelfIntersect) {
  // The approxPolyDP subjects must actually contain crossings, or the checks above would not
  // exercise the core's self-intersection handling.
  int crossings = 0;
  for (SceneKind kind : {SceneKind::Blobs, SceneKind::Text, SceneKind::SelfTouching}) {
    for (const auto& [variant, subject] : subjectVariants(drawScene(kind, {240, 180}, 1))) {
      if (variant.rfind("approx", 0) == 0) crossings += countCrossings(subject);
    }
  }
  EXPECT_GT(crossings, 10);
}

/// A binary image to check, with ROIs of its own (from its JSON description) if any.
struct SceneImage {
  std::string name;
  cv::Mat mask;
  std::vector<testing::NamedRoi> rois;
};

/// ROIs listed in the scene generator's JSON ("rois": [{"name", "paths"}]) and the quad through
/// the tag centres ("tags": [{"centre"}]), as the AprilTag layer would build it.
std::vector<testing::NamedRoi> roisFromJson(const std::filesystem::path& file) {
  std::vector<testing::NamedRoi> rois;
  std::ifstream in(file);
  if (!in) return rois;
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) return rois;
  for (const auto& roi : j.value("rois", nlohmann::json::array())) {
    testing::NamedRoi named{"json:" + roi.value("name", std::string("?")), {}};
    for (const auto& path : roi.at("paths")) {
      named.paths.emplace_back();
      for (const auto& p : path)
        named.paths.back().push_back({p.at(0).get<double>(), p.at(1).get<double>()});
    }
    rois.push_back(named);
  }
  Path centres;
  for (const auto& tag : j.value("tags", nlohmann::json::array())) {
    if (tag.contains("centre"))
      centres.push_back({tag["centre"][0].get<double>(), tag["centre"][1].get<double>()});
  }
  if (centres.size() >= 3) rois.push_back({"tag-centres", {centres}});
  return rois;
}

/// Images in images/ (written by the scene generator; there may be none yet), thresholded both
/// ways (dark shapes as foreground, and the bright board with the shapes as holes), plus large
/// synthetic scenes so that the test checks real content either way.
std::vector<SceneImage> sceneImages() {
  std::vector<SceneImage> out;
  std::error_code ec;
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(ROICLIP_IMAGES, ec)) {
    const std::string ext = entry.path().extension().string();
    if (ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".pgm") {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  for (std::size_t i = 0; i < files.size() && i < 8; ++i) {  // keep the suite fast
    const cv::Mat gray = cv::imread(files[i].string(), cv::IMREAD_GRAYSCALE);
    if (gray.empty() || gray.cols > 2000) continue;
    std::filesystem::path json = files[i];
    json.replace_extension(".json");
    const std::vector<testing::NamedRoi> rois = roisFromJson(json);
    for (int polarity : {cv::THRESH_BINARY_INV, cv::THRESH_BINARY}) {
      cv::Mat mask;
      cv::threshold(gray, mask, 0, 255, polarity | cv::THRESH_OTSU);
      out.push_back(
          {files[i].filename().string() + (polarity == cv::THRESH_BINARY ? " (bright)" : " (dark)"),
           mask, rois});
    }
  }
  out.push_back({"synthetic blobs 640x480", drawScene(SceneKind::Blobs, {640, 480}, 11), {}});
  out.push_back({"synthetic text 640x480", drawScene(SceneKind::Text, {640, 480}, 12), {}});
  return out;
}

TEST(SceneImages, ClipMatchesRasterMasksOffBand) {
  int images = 0;
  for (const SceneImage& image : sceneImages()) {
    Summary summary;
    const Contoured c = findAll(image.mask);
    const Paths subject = fromContours(c.contours, c.hierarchy);
    std::vector<std::vector<cv::Point>> approx(c.contours.size());
    for (std::size_t i = 0; i < approx.size(); ++i) {
      cv::approxPolyDP(c.contours[i], approx[i], 3.0, true);
    }
    std::vector<testing::NamedRoi> rois = makeRois(image.mask.size());
    rois.insert(rois.end(), image.rois.begin(), image.rois.end());
    for (const Paths& s : {subject, fromContours(approx)}) {
      for (const auto& roi : rois) {
        for (FillRule rule : kRules) {
          const MaskCheck check = clipAndCheck(s, roi.paths, rule, rule, image.mask.size());
          summary.add(check);
          EXPECT_TRUE(check.ok()) << image.name << " roi " << roi.name << " rule " << toString(rule)
                                  << ": " << check.vectorVsRaster << " / OpenCV: "
                                  << (check.vectorVsOpenCv ? check.vectorVsOpenCv->iou : -1.0);
        }
      }
    }
    report(image.name + " (" + std::to_string(rois.size()) + " ROIs)", summary);
    EXPECT_GT(summary.clippedPixels, 0) << image.name;
    ++images;
  }
  EXPECT_GE(images, 2);
}

void checkRoundTrip(const std::string& name, const cv::Mat& mask, int method) {
  const Contoured c = findAll(mask, method);
  const Paths paths = fromContours(c.contours, c.hierarchy);
  for (FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
    const PolygonSet set = simplify(paths, rule);
    // Integer contours are exact here: findContours' vertices are pixel centres. Band 0: only
    // pixels whose centres lie exactly on a contour edge may differ (zero-area parts such as
    // 1-px lines vanish from the region, but their pixels are on the edges).
    const Contours<cv::Point> back = toContours(set);
    cv::Mat drawn(mask.size(), CV_8UC1, cv::Scalar(0));
    cv::drawContours(drawn, back.contours, -1, cv::Scalar(255), cv::FILLED, cv::LINE_8,
                     back.hierarchy);
    const MaskComparison cmp = compareMasks(mask, drawn, 0.0, paths);
    EXPECT_TRUE(cmp.agreesOffBand()) << name << " " << toString(rule) << ": " << cmp;
    // fillPoly at sub-pixel precision (the default drawing form) as well.
    cv::Mat filled(mask.size(), CV_8UC1, cv::Scalar(0));
    fillPolygonSet(filled, set, cv::Scalar(255));
    const MaskComparison sub = compareMasks(mask, filled, kOpenCvBand, paths);
    EXPECT_TRUE(sub.agreesOffBand()) << name << " " << toString(rule) << ": " << sub;
    // The exact region covers the mask minus the boundary pixels whose centres it does not
    // contain, and never more.
    const MaskComparison exact = compareMasks(mask, rasterize(set, mask.size()), 0.0, paths);
    EXPECT_TRUE(exact.agreesOffBand()) << name << " " << toString(rule) << ": " << exact;
    EXPECT_EQ(exact.onlyActual, 0) << name << ": the region never leaves the mask";
    EXPECT_GT(exact.both, 0) << name;
  }
}

TEST(RoundTrip, FindContoursToContoursFillPolyReproducesMask) {
  for (SceneKind kind :
       {SceneKind::Blobs, SceneKind::Text, SceneKind::ThinLines, SceneKind::SelfTouching}) {
    for (int method : {cv::CHAIN_APPROX_NONE, cv::CHAIN_APPROX_SIMPLE}) {
      checkRoundTrip(testing::sceneName(kind), drawScene(kind, {240, 180}, 3), method);
    }
  }
  for (const SceneImage& image : sceneImages()) {
    checkRoundTrip(image.name, image.mask, cv::CHAIN_APPROX_SIMPLE);
  }
}

}  // namespace
}  // namespace roiclip::opencv

namespace roiclip::opencv {
namespace {

// Random self-intersecting operands on coarse grids: many collinear overlaps, vertices on
// edges and shared vertices, which are exactly the cases an exact core must get right.
Paths randomCoarsePaths(std::mt19937& rng, int extent, double step) {
  std::uniform_int_distribution<int> count(1, 3), vertices(3, 8);
  std::uniform_int_distribution<int> coord(-2, int(extent / step) + 2);
  Paths paths(std::size_t(count(rng)));
  for (Path& p : paths) {
    const int n = vertices(rng);
    for (int i = 0; i < n; ++i) p.push_back({coord(rng) * step, coord(rng) * step});
  }
  return paths;
}

TEST(RandomOperands, ClipMatchesRasterMasksOffBandForEveryRulePairAndOperation) {
  std::mt19937 rng(4242);
  const cv::Size size(24, 24);
  int checks = 0;
  std::int64_t clipped = 0;
  for (int iter = 0; iter < 1200; ++iter) {
    const double step = iter % 3 == 0 ? 4.0 : (iter % 3 == 1 ? 1.0 : 0.5);
    const Paths subject = randomCoarsePaths(rng, 24, step);
    const Paths roi = randomCoarsePaths(rng, 24, step);
    MaskCheckOptions options;
    options.op = static_cast<ClipOp>(iter % 4);
    for (FillRule subjectRule : kRules) {
      for (FillRule roiRule : kRules) {
        const MaskCheck check = clipAndCheck(subject, roi, subjectRule, roiRule, size, options);
        ++checks;
        clipped += check.vectorVsRaster.both;
        ASSERT_TRUE(check.ok()) << "iteration " << iter << " " << toString(options.op) << " rules "
                                << toString(subjectRule) << "/" << toString(roiRule) << ": "
                                << check.vectorVsRaster;
      }
    }
  }
  EXPECT_GT(clipped, std::int64_t(checks) * 10);  // most results are not empty
}

}  // namespace
}  // namespace roiclip::opencv

namespace roiclip::opencv {
namespace {

double distanceToEdges(const Paths& paths, cv::Point2d p) {
  double best = INFINITY;
  for (const Path& path : paths) {
    for (std::size_t i = 0; i < path.size(); ++i) {
      const cv::Point2d a(path[i].x, path[i].y);
      const cv::Point2d b(path[(i + 1) % path.size()].x, path[(i + 1) % path.size()].y);
      const cv::Point2d d = b - a;
      const double len2 = d.dot(d);
      const double t = len2 > 0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
      best = std::min(best, cv::norm(a + t * d - p));
    }
  }
  return best;
}

TEST(OpenCvBand, FillPolyDiffersFromExactRasterOnlyWithinTheBand) {
  // The evidence for kOpenCvBand: random self-intersecting polygons, integer and sub-pixel.
  std::mt19937 rng(99);
  const cv::Size size(32, 32);
  double farthestOpenCvOnly = 0, farthestExactOnly = 0;
  for (int iter = 0; iter < 4000; ++iter) {
    const double step = iter % 2 == 0 ? 1.0 : 1.0 / 64;
    std::uniform_int_distribution<int> coord(int(-2 / step), int(34 / step)), count(3, 8);
    Paths paths(1);
    for (int i = count(rng); i > 0; --i) paths[0].push_back({coord(rng) * step, coord(rng) * step});
    const FixedPointContours fixed = toFixedPointContours(paths, iter % 2 == 0 ? 0 : kDefaultShift);
    cv::Mat drawn(size, CV_8UC1, cv::Scalar(0));
    cv::fillPoly(drawn, fixed.contours.contours, cv::Scalar(255), cv::LINE_8, fixed.shift);
    const cv::Mat exact = rasterize(paths, FillRule::EvenOdd, size);
    for (int r = 0; r < size.height; ++r) {
      for (int c = 0; c < size.width; ++c) {
        const bool o = drawn.at<std::uint8_t>(r, c) != 0, e = exact.at<std::uint8_t>(r, c) != 0;
        if (o == e) continue;
        double& farthest = o ? farthestOpenCvOnly : farthestExactOnly;
        farthest = std::max(farthest, distanceToEdges(paths, cv::Point2d(c, r)));
      }
    }
  }
  std::cout << "cv::fillPoly vs rasterize: pixels only in fillPoly up to " << farthestOpenCvOnly
            << " px from an edge, only in rasterize up to " << farthestExactOnly << " px\n";
  EXPECT_LT(farthestOpenCvOnly, kOpenCvBand);
  EXPECT_LT(farthestExactOnly, kOpenCvBand);
  EXPECT_GT(farthestOpenCvOnly, 0.5);  // fillPoly's edge lines do reach outside
}

}  // namespace
}  // namespace roiclip::opencv

namespace roiclip::opencv {
namespace {

TEST(MaskCheck, DetectsAWrongResult) {
  // The check is not vacuous: a result that lost one hole, or moved by a pixel, fails off the
  // band against both raster routes.
  const cv::Size size(120, 100);
  const Paths subject = {{{10, 10}, {110, 10}, {110, 90}, {10, 90}},
                         {{30, 30}, {30, 70}, {80, 70}, {80, 30}}};
  const Paths roi = {{{20.5, 5}, {100, 20}, {95.25, 95}, {5, 80}}};
  const PolygonSet clipped =
      clip(ClipOp::Intersection, subject, roi, FillRule::EvenOdd, FillRule::EvenOdd);
  ASSERT_TRUE(checkRoiClip(subject, roi, clipped, FillRule::EvenOdd, FillRule::EvenOdd, size).ok());
  ASSERT_EQ(clipped.polygons.size(), 1u);
  ASSERT_EQ(clipped.polygons[0].holes.size(), 1u);
  Paths edges = subject;
  edges.insert(edges.end(), roi.begin(), roi.end());
  const cv::Mat right = rasterize(clipped, size);

  PolygonSet noHole = clipped;
  noHole.polygons[0].holes.clear();
  const MaskComparison lost = compareMasks(right, rasterize(noHole, size), kOpenCvBand, edges);
  EXPECT_FALSE(lost.agreesOffBand()) << lost;
  EXPECT_GT(lost.offBandOnlyActual, 1000);

  PolygonSet moved = clipped;
  for (Point& p : moved.polygons[0].outer) p.x += 1.0;
  for (Point& p : moved.polygons[0].holes[0]) p.x += 1.0;
  const MaskComparison shifted = compareMasks(right, rasterize(moved, size), kExactBand, edges);
  EXPECT_FALSE(shifted.agreesOffBand()) << shifted;

  // checkRoiClip() judges the result it is given: each wrong one fails it. The exact route sees
  // both; the 1 px shift lies inside the cv::fillPoly route's 2 px band, the lost hole does not.
  for (const PolygonSet* wrong : {&noHole, &moved}) {
    const MaskCheck check =
        checkRoiClip(subject, roi, *wrong, FillRule::EvenOdd, FillRule::EvenOdd, size);
    EXPECT_FALSE(check.ok());
    EXPECT_FALSE(check.vectorVsRaster.agreesOffBand()) << check.vectorVsRaster;
    ASSERT_TRUE(check.vectorVsOpenCv.has_value());
    EXPECT_EQ(check.vectorVsOpenCv->agreesOffBand(), wrong == &moved) << *check.vectorVsOpenCv;
  }
  // An empty result for a non-empty clip, and the result of another operation, fail too.
  EXPECT_FALSE(
      checkRoiClip(subject, roi, PolygonSet{}, FillRule::EvenOdd, FillRule::EvenOdd, size).ok());
  const PolygonSet united = clip(ClipOp::Union, subject, roi, FillRule::EvenOdd, FillRule::EvenOdd);
  EXPECT_FALSE(checkRoiClip(subject, roi, united, FillRule::EvenOdd, FillRule::EvenOdd, size).ok());
}

}  // namespace
}  // namespace roiclip::opencv

namespace roiclip::opencv {
namespace {

// An intersection is compared only in the ROI's (and the result's) bounding box: the counts
// equal those of whole-image masks, and a result that strays far outside the ROI still fails.
TEST(MaskCheck, IntersectionWindowGivesTheWholeImageCounts) {
  const cv::Size size(400, 300);
  const Paths subject = {{{10, 10}, {390, 15}, {380, 290}, {20, 280}},
                         {{150, 100}, {150, 200}, {260, 210}, {250, 90}}};
  const Paths roi = {{{120.5, 60}, {300, 80}, {290.25, 240}, {100, 220}}};
  const PolygonSet clipped =
      clip(ClipOp::Intersection, subject, roi, FillRule::EvenOdd, FillRule::EvenOdd);
  const MaskCheck check =
      checkRoiClip(subject, roi, clipped, FillRule::EvenOdd, FillRule::EvenOdd, size);
  ASSERT_TRUE(check.ok());
  Paths edges = subject;
  edges.insert(edges.end(), roi.begin(), roi.end());
  const cv::Mat expected =
      rasterize(subject, FillRule::EvenOdd, size) & rasterize(roi, FillRule::EvenOdd, size);
  const MaskComparison whole = compareMasks(expected, rasterize(clipped, size), kExactBand, edges);
  EXPECT_EQ(check.vectorVsRaster.both, whole.both);
  EXPECT_EQ(check.vectorVsRaster.onlyExpected, whole.onlyExpected);
  EXPECT_EQ(check.vectorVsRaster.onlyActual, whole.onlyActual);
  EXPECT_EQ(check.vectorVsRaster.offBandOnlyExpected, whole.offBandOnlyExpected);
  EXPECT_EQ(check.vectorVsRaster.offBandOnlyActual, whole.offBandOnlyActual);
  EXPECT_DOUBLE_EQ(check.vectorVsRaster.iou, whole.iou);
  EXPECT_LT(check.vectorVsRaster.bandPixels, whole.bandPixels);  // only the window's

  PolygonSet stray = clipped;
  Polygon far;
  far.outer = {{350, 250}, {350, 290}, {390, 290}, {390, 250}};
  if (signedArea(far.outer) > 0) std::reverse(far.outer.begin(), far.outer.end());
  stray.polygons.push_back(far);
  const MaskCheck wrong =
      checkRoiClip(subject, roi, stray, FillRule::EvenOdd, FillRule::EvenOdd, size);
  EXPECT_FALSE(wrong.ok());
  EXPECT_GT(wrong.vectorVsRaster.offBandOnlyActual, 1000);
}

}  // namespace
}  // namespace roiclip::opencv
