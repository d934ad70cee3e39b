// SPDX-License-Identifier: MIT
// The region `roiclip run` clips against: the tags are not objects, board ROIs are separate
// regions whose union is the image's region, repeated ROIs are reported by name, and bad specs
// are refused before any image is read.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include <roiclip/batch/process.hpp>
#include <roiclip/batch/run.hpp>
#include <roiclip/opencv/mask_check.hpp>
#include <roiclip/opencv/rasterize.hpp>

#include "detail/report.hpp"
#include "detail/result_json.hpp"

namespace rb = roiclip::batch;
using roiclip::FillRule;
using roiclip::Paths;

namespace {

const std::string kImages = ROICLIP_IMAGES;

cv::Mat scene(const std::string& name) {
  const cv::Mat image = cv::imread(kImages + "/" + name + ".png", cv::IMREAD_GRAYSCALE);
  EXPECT_FALSE(image.empty()) << name;
  return image;
}

// Area of what the clipped result shares with the tags' black-border quads.
double overlapWithTags(const rb::ImageResult& r) {
  Paths quads;
  for (const auto& tag : r.tags) quads.emplace_back(tag.corners.begin(), tag.corners.end());
  return roiclip::clip(roiclip::ClipOp::Intersection, r.clipped.toPaths(), quads, FillRule::EvenOdd,
                       FillRule::NonZero)
      .area();
}

double perimeter(const Paths& rings) {
  double total = 0;
  for (const auto& ring : rings) {
    for (std::size_t i = 0; i < ring.size(); ++i)
      total += glm::length(ring[(i + 1) % ring.size()] - ring[i]);
  }
  return total;
}

// Results are rounded to double and snapped again to the 1/256 px grid when clipped further, so
// a boundary shared with the tags may move by up to half a grid step: slivers of at most
// (length of that boundary) x 1/512 px.
double roundingBound(const rb::ImageResult& r) {
  Paths quads;
  for (const auto& tag : r.tags) quads.emplace_back(tag.corners.begin(), tag.corners.end());
  return perimeter(quads) / 512;
}

class BatchRoiScene : public ::testing::TestWithParam<std::string> {};

TEST_P(BatchRoiScene, NoClippedPolygonOverlapsATagByDefault) {
  const cv::Mat image = scene(GetParam());
  const rb::ImageResult r = rb::processImage(image, {});
  ASSERT_EQ(r.status, rb::Status::Ok) << r.reason;
  ASSERT_EQ(r.tags.size(), 4u);
  EXPECT_EQ(r.excludedTags.size(), 4u);
  EXPECT_LE(overlapWithTags(r), roundingBound(r));
  Paths quads;
  for (const auto& tag : r.tags) quads.emplace_back(tag.corners.begin(), tag.corners.end());
  double perContour = 0;
  for (const auto& c : r.contours) {
    perContour += roiclip::intersect(c.clipped.toPaths(), quads, FillRule::NonZero).area();
  }
  EXPECT_LE(perContour, roundingBound(r));
  // The tags' black borders are dark contours: kept, they are a large part of the result.
  rb::RunOptions keep;
  keep.keepTags = true;
  const rb::ImageResult kept = rb::processImage(image, keep);
  ASSERT_EQ(kept.status, rb::Status::Ok) << kept.reason;
  EXPECT_TRUE(kept.excludedTags.empty());
  EXPECT_GT(overlapWithTags(kept), 1000.0);
  EXPECT_NEAR(kept.clippedArea, r.clippedArea + overlapWithTags(kept), 2 * roundingBound(r));
}

INSTANTIATE_TEST_SUITE_P(Bundled, BatchRoiScene,
                         ::testing::Values("scene_01", "scene_02", "scene_03", "scene_04",
                                           "scene_05", "scene_06", "scene_07", "scene_08"));

// Distance from point p to the line through a and b.
double lineDistance(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
  const glm::dvec2 d = b - a;
  return std::abs(d.x * (p.y - a.y) - d.y * (p.x - a.x)) / glm::length(d);
}

TEST(BatchRoi, TagMarginMovesEveryQuadEdgeOutwards) {
  const cv::Mat image = scene("scene_03");
  rb::RunOptions options;
  options.tagMargin = 4.0;
  const rb::ImageResult r = rb::processImage(image, options);
  ASSERT_EQ(r.status, rb::Status::Ok) << r.reason;
  const rb::ImageResult plain = rb::processImage(image, {});
  ASSERT_EQ(r.excludedTags.size(), r.tags.size());
  for (std::size_t t = 0; t < r.tags.size(); ++t) {
    const roiclip::Path& grown = r.excludedTags[t];
    ASSERT_EQ(grown.size(), 4u);
    // Each grown edge is parallel to a tag edge, 4 px out: both ends of every tag edge are
    // 4 px from one grown edge's line.
    for (int k = 0; k < 4; ++k) {
      const glm::dvec2 a = r.tags[t].corners[k];
      const glm::dvec2 b = r.tags[t].corners[(k + 1) % 4];
      bool found = false;
      for (int g = 0; g < 4; ++g) {
        const glm::dvec2 p = grown[g];
        const glm::dvec2 q = grown[(g + 1) % 4];
        if (std::abs(lineDistance(a, p, q) - 4.0) < 1e-9 &&
            std::abs(lineDistance(b, p, q) - 4.0) < 1e-9) {
          found = true;
        }
      }
      EXPECT_TRUE(found) << "tag " << r.tags[t].id << " edge " << k;
    }
    EXPECT_GT(std::abs(roiclip::signedArea(grown)),
              std::abs(roiclip::signedArea(
                  roiclip::Path(r.tags[t].corners.begin(), r.tags[t].corners.end()))));
  }
  EXPECT_LT(r.roiArea, plain.roiArea);
  EXPECT_LE(r.clippedArea, plain.clippedArea);
  rb::RunOptions negative;
  negative.tagMargin = -1;
  EXPECT_THROW(rb::Processor{negative}, roiclip::InvalidInputError);
}

TEST(BatchRoi, BoardRoisAreSeparateAndTheirUnionIsTheRegion) {
  const cv::Mat image = scene("scene_01");
  rb::RunOptions options;
  options.rois = {"board"};
  options.boardFile = kImages + "/board.json";
  options.keepTags = true;  // the board's ROIs as they are
  const rb::ImageResult r = rb::processImage(image, options);
  ASSERT_EQ(r.status, rb::Status::Ok) << r.reason;
  ASSERT_EQ(r.rois.size(), 2u);
  EXPECT_EQ(r.rois[0].name, "inspection");
  EXPECT_EQ(r.rois[1].name, "window");
  const rb::RoiRegion& inspection = r.rois[0];
  const rb::RoiRegion& window = r.rois[1];
  // The window lies inside the inspection area: the union is the inspection area, not the
  // even-odd XOR of both (which has the window as a hole).
  const double xorArea = roiclip::symmetricDifference(inspection.paths, window.paths).area();
  EXPECT_NEAR(r.roiArea, inspection.area, 1e-6 * inspection.area);
  EXPECT_GT(r.roiArea, xorArea + 0.9 * window.area);
  // Independently, by raster: the region's mask is the OR of the two ROI masks off a band.
  const cv::Size size(r.width, r.height);
  const cv::Mat either = roiclip::opencv::rasterize(inspection.paths, FillRule::EvenOdd, size) |
                         roiclip::opencv::rasterize(window.paths, FillRule::EvenOdd, size);
  Paths edges = inspection.paths;
  edges.insert(edges.end(), window.paths.begin(), window.paths.end());
  const auto cmp = roiclip::opencv::compareMasks(
      either, roiclip::opencv::rasterize(r.roi, FillRule::EvenOdd, size), 0.05, edges);
  EXPECT_TRUE(cmp.agreesOffBand()) << cmp;
  // Per-ROI figures: the window's contours are a part of the inspection area's.
  EXPECT_GT(window.clippedArea, 0.0);
  EXPECT_LE(window.clippedArea, inspection.clippedArea);
  EXPECT_NEAR(inspection.clippedArea, r.clippedArea, perimeter(r.clipped.toPaths()) / 512);
  EXPECT_LE(window.contoursOut, inspection.contoursOut);
  // One summary row per image and ROI.
  rb::RunSummary summary;
  rb::ImageRecord record = rb::detail::recordOf(r);
  record.image = "scene_01.png";
  summary.images.push_back(record);
  summary.total = 1;
  const std::string csv = rb::detail::summaryCsv(summary);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3);
  EXPECT_NE(csv.find(",inspection,0,0\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",window,0,0\n"), std::string::npos) << csv;
  // NAME.json carries them and reads back.
  const auto back = rb::detail::parseRecord(rb::resultToJson(r, "scene_01.png"));
  ASSERT_TRUE(back.has_value());
  ASSERT_EQ(back->rois.size(), 2u);
  EXPECT_EQ(back->rois[1].name, "window");
  EXPECT_EQ(back->rois[1].clippedArea, window.clippedArea);
}

TEST(BatchRoi, RepeatedRoisAreReportedUnderTheirNames) {
  const cv::Mat image = scene("scene_02");
  rb::RunOptions options;
  options.rois = {"hull", "board:window"};
  options.boardFile = kImages + "/board.json";
  const rb::ImageResult r = rb::processImage(image, options);
  ASSERT_EQ(r.status, rb::Status::Ok) << r.reason;
  ASSERT_EQ(r.rois.size(), 2u);
  EXPECT_EQ(r.rois[0].name, "hull");
  EXPECT_EQ(r.rois[1].name, "window");
  // The window is inside the hull: the union is the hull region.
  EXPECT_NEAR(r.roiArea, r.rois[0].area, 1e-6 * r.roiArea);
  const rb::ImageResult hullOnly = rb::processImage(image, {});
  EXPECT_NEAR(r.clippedArea, hullOnly.clippedArea, perimeter(r.clipped.toPaths()) / 512);
}

TEST(BatchRoi, BadSpecsAreRefusedBeforeAnyImage) {
  const auto refused = [](std::vector<std::string> rois, const std::string& words) {
    rb::RunOptions options;
    options.rois = std::move(rois);
    options.boardFile = kImages + "/board.json";
    try {
      rb::Processor processor(options);
      ADD_FAILURE() << "accepted: " << words;
    } catch (const roiclip::InvalidInputError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  refused({"tags:0,0,0"}, "listed twice");
  refused({"hull:0,1,1"}, "listed twice");
  refused({"tags:0,1,999"}, "tag id 999 does not exist in tag36h11");
  refused({"hull", "hull"}, "'hull' is given twice");
  refused({"board", "board:window"}, "'window' is given twice");
  refused({"board:nope"}, "no ROI named 'nope'");
  refused({}, "no ROI given");
}

}  // namespace
