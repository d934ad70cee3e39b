// SPDX-License-Identifier: MIT
// Board files and the projective helpers: parsing, every error path, exact fits.
#include <roiclip/apriltag/projective.hpp>
#include <roiclip/apriltag/roi.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include <opencv2/core.hpp>

#include <gtest/gtest.h>

namespace ra = roiclip::apriltag;
using ra::Corner;

namespace {

const std::string kData = std::string(ROICLIP_TEST_DATA) + "/apriltag/";

// Expect `fn` to throw InvalidInputError whose message contains every string in `parts`.
template <class Fn>
void expectInvalid(Fn fn, std::initializer_list<const char*> parts) {
  try {
    fn();
    ADD_FAILURE() << "no exception";
  } catch (const roiclip::InvalidInputError& e) {
    for (const char* part : parts) {
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what() << " / " << part;
    }
  }
}

TEST(AprilTagBoard, LoadsCornersAndTheCentreSizeShorthand) {
  const ra::Board board = ra::Board::load(kData + "shorthand.json");
  EXPECT_EQ(board.family, "tag36h11");
  ASSERT_EQ(board.tags.size(), 2u);
  const auto& zero = board.tags.at(0);
  EXPECT_EQ(zero[static_cast<int>(Corner::TopLeft)], glm::dvec2(18, 18));
  EXPECT_EQ(zero[static_cast<int>(Corner::TopRight)], glm::dvec2(82, 18));
  EXPECT_EQ(zero[static_cast<int>(Corner::BottomRight)], glm::dvec2(82, 82));
  EXPECT_EQ(zero[static_cast<int>(Corner::BottomLeft)], glm::dvec2(18, 82));
  const auto& one = board.tags.at(1);
  EXPECT_EQ(one[static_cast<int>(Corner::TopLeft)], glm::dvec2(318, 18));
  EXPECT_EQ(one[static_cast<int>(Corner::BottomLeft)], glm::dvec2(318, 82));
  ASSERT_EQ(board.rois.size(), 2u);
  EXPECT_EQ(board.roi("two_rings").paths.size(), 2u);
  EXPECT_EQ(board.roi("strip").paths[0][2], glm::dvec2(300, 80));
}

TEST(AprilTagBoard, BundledBoardLoads) {
  const ra::Board board = ra::Board::load(std::string(ROICLIP_IMAGES) + "/board.json");
  EXPECT_EQ(board.tags.size(), 4u);
  EXPECT_NO_THROW((void)board.roi("inspection"));
  EXPECT_NO_THROW((void)board.roi("window"));
}

// toJson() is what roiclip-make-scenes writes images/board.json with: it must give the bundled
// file byte for byte, and read back to an equal board.
TEST(AprilTagBoard, ToJsonWritesTheBundledFileAndReadsBack) {
  const std::string file = std::string(ROICLIP_IMAGES) + "/board.json";
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  const ra::Board board = ra::Board::fromJson(text.str(), file);
  EXPECT_EQ(board.units, "mm");
  ASSERT_TRUE(board.size.has_value());
  EXPECT_EQ(*board.size, glm::dvec2(400, 300));
  EXPECT_EQ(board.toJson(1), text.str());

  const ra::Board again = ra::Board::fromJson(board.toJson(-1));
  EXPECT_EQ(again.family, board.family);
  EXPECT_EQ(again.tags, board.tags);
  ASSERT_EQ(again.rois.size(), board.rois.size());
  for (std::size_t i = 0; i < board.rois.size(); ++i) {
    EXPECT_EQ(again.rois[i].name, board.rois[i].name);
    EXPECT_EQ(again.rois[i].paths, board.rois[i].paths);
  }
  ra::Board bare;  // no units, no size: neither is written
  bare.tags[7] = board.tags.begin()->second;
  EXPECT_EQ(bare.toJson(-1).find("units"), std::string::npos);
  EXPECT_EQ(ra::Board::fromJson(bare.toJson(-1)).tags, bare.tags);
}

TEST(AprilTagBoardErrors, MalformedJson) {
  expectInvalid([] { (void)ra::Board::load(kData + "malformed.json"); },
                {"malformed.json", "malformed JSON"});
  expectInvalid([] { (void)ra::Board::fromJson("[1, 2]", "inline"); }, {"inline", "object"});
  // Found by tests/fuzz/fuzz_board: a number too large for a double is nlohmann's
  // out_of_range.406, which escaped as a non-roiclip exception.
  expectInvalid([] { (void)ra::Board::fromJson(R"({"tags": [1e999]})", "inline"); },
                {"inline", "malformed JSON", "1e999"});
}

TEST(AprilTagBoardErrors, UnknownTagId) {
  expectInvalid([] { (void)ra::Board::load(kData + "unknown_id.json"); },
                {"unknown_id.json", "tags[1]", "unknown tag id 587", "0..586"});
  expectInvalid(
      [] { (void)ra::Board::fromJson(R"({"tags":[{"id":-1,"centre":[0,0],"size":1}]})"); },
      {"unknown tag id -1"});
}

TEST(AprilTagBoardErrors, UnknownFamily) {
  expectInvalid([] { (void)ra::Board::load(kData + "unknown_family.json"); },
                {"unknown_family.json", "tag37h12"});
}

TEST(AprilTagBoardErrors, MissingFieldsAndWrongTypes) {
  expectInvalid([] { (void)ra::Board::load(kData + "missing_corner.json"); },
                {"tags[0]", "bottom_left"});
  expectInvalid([] { (void)ra::Board::fromJson(R"({"family":"tag36h11"})"); }, {"tags"});
  expectInvalid(
      [] { (void)ra::Board::fromJson(R"({"tags":[{"id":"zero","centre":[0,0],"size":1}]})"); },
      {"integer"});
  expectInvalid(
      [] { (void)ra::Board::fromJson(R"({"tags":[{"id":0,"centre":[0,"x"],"size":1}]})"); },
      {"centre"});
  expectInvalid(
      [] { (void)ra::Board::fromJson(R"({"tags":[{"id":0,"centre":[0,0],"size":-3}]})"); },
      {"size"});
  expectInvalid(
      [] {
        (void)ra::Board::fromJson(
            R"({"tags":[{"id":0,"centre":[0,0],"size":1},{"id":0,"centre":[5,0],"size":1}]})");
      },
      {"listed twice"});
  expectInvalid(
      [] {
        (void)ra::Board::fromJson(
            R"({"tags":[{"id":0,"centre":[0,0],"size":1}],"rois":[{"name":"a","paths":[[[0,0],[1]]]}]})");
      },
      {"rois[0]", "paths[0][1]"});
  expectInvalid([] { (void)ra::Board::load(kData + "does_not_exist.json"); },
                {"does_not_exist.json"});
  const ra::Board board = ra::Board::load(kData + "shorthand.json");
  expectInvalid([&] { (void)board.roi("nope"); }, {"nope", "strip", "two_rings"});
}

TEST(AprilTagProjective, ApplyAndMapPaths) {
  // x' = (2x + 1) / (0.001 x + 1), y' = (3y - 2) / (0.001 x + 1); GLM is column-major.
  const glm::dmat3 h(2, 0, 0.001, 0, 3, 0, 1, -2, 1);
  const glm::dvec2 p = ra::applyHomography(h, {10, 20});
  EXPECT_DOUBLE_EQ(p.x, 21 / 1.01);
  EXPECT_DOUBLE_EQ(p.y, 58 / 1.01);
  const roiclip::Paths mapped = ra::mapPaths(h, {{{0, 0}, {10, 0}, {10, 10}}});
  ASSERT_EQ(mapped.size(), 1u);
  EXPECT_EQ(mapped[0][0], glm::dvec2(1, -2));
  // A polygon straddling the line x = -1000 (w = 0) has no bounded image.
  expectInvalid(
      [&] {
        (void)ra::mapPaths(h, {{{0, 0}, {-2000, 0}, {-2000, 10}}});
      },
      {"path 0 vertex 1", "infinity"});
  EXPECT_THROW((void)ra::applyHomography(h, {-1000, 5}), roiclip::Error);
}

TEST(AprilTagProjective, FitBoardFromOneSyntheticTagIsExact) {
  ra::Board board = ra::Board::load(kData + "shorthand.json");
  // A known homography; fake a detection of tag 0 by mapping its board corners.
  const glm::dmat3 h(1.5, 0.2, 0.0004, -0.1, 1.4, 0.0002, 30, 40, 1);
  ra::Detection d;
  d.id = 0;
  d.family = "tag36h11";
  for (int k = 0; k < 4; ++k) d.corners[k] = ra::applyHomography(h, board.tags.at(0)[k]);
  const ra::RoiResult roi = ra::boardRoi(board, {d}, "strip");
  ASSERT_TRUE(roi.ok());
  for (std::size_t k = 0; k < 4; ++k) {
    const glm::dvec2 expected = ra::applyHomography(h, board.roi("strip").paths[0][k]);
    EXPECT_NEAR(roi.value()[0][k].x, expected.x, 1e-6);
    EXPECT_NEAR(roi.value()[0][k].y, expected.y, 1e-6);
  }
  // A detection of another family is not a board tag.
  d.family = "tag25h9";
  EXPECT_FALSE(ra::boardRoi(board, {d}).ok());
}

TEST(AprilTagProjective, FitBoardRansacRejectsAnOutlierTag) {
  ra::Board board;
  for (int id = 0; id < 4; ++id) {
    const glm::dvec2 c{50.0 + 100 * id, 50.0 + 30 * (id % 2)};
    for (int k = 0; k < 4; ++k) {
      static const double kOffsets[4][2] = {{-1, 1}, {1, 1}, {1, -1}, {-1, -1}};
      board.tags[id][k] = c + 20.0 * glm::dvec2{kOffsets[k][0], kOffsets[k][1]};
    }
  }
  board.rois.push_back({"box", {{{0, 0}, {400, 0}, {400, 150}, {0, 150}}}});
  const glm::dmat3 h(1.2, 0.1, 0.0003, -0.05, 1.3, 0.0001, 20, 30, 1);
  std::vector<ra::Detection> detections;
  for (const auto& [id, corners] : board.tags) {
    ra::Detection d;
    d.id = id;
    d.family = board.family;
    for (int k = 0; k < 4; ++k) d.corners[k] = ra::applyHomography(h, corners[k]);
    detections.push_back(d);
  }
  for (glm::dvec2& c : detections[2].corners) c += glm::dvec2{40, -25};  // a misplaced tag
  const ra::TagResult<ra::BoardFit> fit = ra::fitBoard(board, detections);
  ASSERT_TRUE(fit.ok());
  EXPECT_EQ(fit.value().inliers, 12);
  EXPECT_LT(fit.value().rmsError, 1e-3);  // findHomography works in float
  const ra::RoiResult roi = ra::boardRoi(board, detections, "box");
  for (std::size_t k = 0; k < 4; ++k) {
    const glm::dvec2 expected = ra::applyHomography(h, board.roi("box").paths[0][k]);
    EXPECT_NEAR(roi.value()[0][k].x, expected.x, 1e-3);
    EXPECT_NEAR(roi.value()[0][k].y, expected.y, 1e-3);
  }
}

TEST(AprilTagProjective, RandomViewsWithNoisyCornersAndAnOutlier) {
  // 40 random views (fixed seed) of the bundled board's layout: corners with 0.2 px Gaussian
  // noise plus a fifth tag detected 15 px off. The fit must drop that tag and map the ROI to
  // within 1 px.
  ra::Board board = ra::Board::load(std::string(ROICLIP_IMAGES) + "/board.json");
  board.tags[4] = board.tags.at(0);
  for (auto& c : board.tags[4]) c += glm::dvec2{150, 100};
  cv::RNG rng(20261122);
  double worst = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const double angle = rng.uniform(-3.1, 3.1), scale = rng.uniform(1.0, 2.5);
    const double c = std::cos(angle) * scale, n = std::sin(angle) * scale;
    const glm::dmat3 perspective(1, 0, rng.uniform(-0.001, 0.001), 0, 1, rng.uniform(-0.001, 0.001),
                                 -200, -150, 1);
    const glm::dmat3 similarity(c, n, 0, -n, c, 0, 400, 300, 1);
    const glm::dmat3 h = similarity * perspective;
    std::vector<ra::Detection> detections;
    for (const auto& [id, corners] : board.tags) {
      ra::Detection d;
      d.id = id;
      d.family = board.family;
      for (int k = 0; k < 4; ++k) {
        d.corners[k] = ra::applyHomography(h, corners[k]) +
                       glm::dvec2{rng.gaussian(0.2), rng.gaussian(0.2)} +
                       (id == 4 ? glm::dvec2{15, -10} : glm::dvec2{0, 0});
      }
      detections.push_back(d);
    }
    const ra::TagResult<ra::BoardFit> fit = ra::fitBoard(board, detections);
    ASSERT_TRUE(fit.ok());
    EXPECT_EQ(fit.value().tagsUsed.size(), 5u);
    EXPECT_EQ(fit.value().inliers, 16) << "trial " << trial;
    const roiclip::Paths roi = ra::boardRoi(board, detections, "inspection").value();
    const roiclip::Path& truth = board.roi("inspection").paths[0];
    for (std::size_t k = 0; k < truth.size(); ++k) {
      const glm::dvec2 e = roi[0][k] - ra::applyHomography(h, truth[k]);
      worst = std::max(worst, std::hypot(e.x, e.y));
    }
  }
  EXPECT_LT(worst, 1.0);
  std::printf("random views: board ROI max vertex error %.3f px\n", worst);
}

TEST(AprilTagAnchor, Parses) {
  EXPECT_EQ(ra::parseTagAnchor("centre"), ra::TagAnchor::Centre);
  EXPECT_EQ(ra::parseTagAnchor("Center"), ra::TagAnchor::Centre);
  EXPECT_EQ(ra::parseTagAnchor("top_left"), ra::TagAnchor::TopLeft);
  EXPECT_EQ(ra::parseTagAnchor("bottom-right"), ra::TagAnchor::BottomRight);
  expectInvalid([] { (void)ra::parseTagAnchor("middle"); }, {"middle"});
}

TEST(AprilTagPolygon, RejectsBadIdLists) {
  expectInvalid([] { (void)ra::polygonThroughTags({}, {1, 2}); }, {"at least 3"});
  expectInvalid([] { (void)ra::polygonThroughTags({}, {1, 2, 1}); }, {"twice"});
}

TEST(AprilTagRoiSpec, ParsesEveryKind) {
  const ra::RoiSpec tags = ra::parseRoiSpec("tags:0,2,1,3");
  EXPECT_EQ(tags.kind, ra::RoiSpec::Kind::Tags);
  EXPECT_EQ(tags.ids, (std::vector<int>{0, 2, 1, 3}));
  using A = ra::TagAnchor;
  EXPECT_EQ(tags.anchors, std::vector<A>(4, A::Centre));
  // One anchor after the last id applies to every tag; otherwise each id has its own.
  EXPECT_EQ(ra::parseRoiSpec("tags:4,5,6@top-left").anchors, std::vector<A>(3, A::TopLeft));
  EXPECT_EQ(
      ra::parseRoiSpec("tags:22@top-left,24@top-right,25@bottom-right,23@bottom-left").anchors,
      (std::vector<A>{A::TopLeft, A::TopRight, A::BottomRight, A::BottomLeft}));
  EXPECT_EQ(ra::parseRoiSpec("tags:4@top-left,5,6").anchors,
            (std::vector<A>{A::TopLeft, A::Centre, A::Centre}));
  const ra::RoiSpec hull = ra::parseRoiSpec("hull");
  EXPECT_EQ(hull.kind, ra::RoiSpec::Kind::Hull);
  EXPECT_TRUE(hull.ids.empty());
  EXPECT_EQ(ra::parseRoiSpec("hull:7,9").ids, (std::vector<int>{7, 9}));
  const ra::RoiSpec board = ra::parseRoiSpec("board:inspection");
  EXPECT_EQ(board.kind, ra::RoiSpec::Kind::Board);
  EXPECT_EQ(board.roiName, "inspection");
  EXPECT_EQ(ra::parseRoiSpec("board").roiName, "");
  const ra::RoiSpec tag = ra::parseRoiSpec("tag:5:0.5,-0.5;2.5,-0.5;2.5,0.5|0,0;1,0;1,1");
  EXPECT_EQ(tag.kind, ra::RoiSpec::Kind::TagFrame);
  EXPECT_EQ(tag.ids, std::vector<int>{5});
  ASSERT_EQ(tag.tagFramePaths.size(), 2u);
  EXPECT_EQ(tag.tagFramePaths[0][1], glm::dvec2(2.5, -0.5));
  EXPECT_EQ(tag.tagFramePaths[1].size(), 3u);
}

TEST(AprilTagRoiSpec, RejectsBadText) {
  expectInvalid([] { (void)ra::parseRoiSpec("tags:0,1"); }, {"tags:0,1", "at least 3"});
  expectInvalid([] { (void)ra::parseRoiSpec("tags:0,x,2"); }, {"'x' is not a tag id"});
  expectInvalid([] { (void)ra::parseRoiSpec("tags:0,1,2@middle"); }, {"middle"});
  expectInvalid([] { (void)ra::parseRoiSpec("tags"); }, {"expected tags:"});
  expectInvalid([] { (void)ra::parseRoiSpec("hull:1,,2"); }, {"'' is not a tag id"});
  expectInvalid([] { (void)ra::parseRoiSpec("tag:5:0,0;1,0"); }, {"at least 3"});
  expectInvalid([] { (void)ra::parseRoiSpec("tag:5:0,0;1;1,1"); }, {"'1' is not x,y"});
  expectInvalid([] { (void)ra::parseRoiSpec("tag:5"); }, {"expected tag:ID:"});
  expectInvalid([] { (void)ra::parseRoiSpec("circle:3"); }, {"unknown kind 'circle'"});
  expectInvalid([] { (void)ra::parseRoiSpec("tags:0,0,0"); }, {"tag id 0 is listed twice"});
  expectInvalid([] { (void)ra::parseRoiSpec("hull:0,3,0"); }, {"tag id 0 is listed twice"});
  expectInvalid([] { (void)ra::parseRoiSpec("tags:1@top-left,2@nowhere,3"); }, {"nowhere"});
  expectInvalid([] { (void)ra::buildRoi(ra::parseRoiSpec("board"), {}); }, {"board file"});
}

TEST(AprilTagRoiSpec, BuildsTheSameAsTheBuilders) {
  std::vector<ra::Detection> detections;
  for (int id = 0; id < 3; ++id) {
    ra::Detection d;
    d.id = id;
    d.family = "tag36h11";
    d.centre = {100.0 * id, 50.0 * (id % 2)};
    for (int k = 0; k < 4; ++k)
      d.corners[k] = d.centre + glm::dvec2{k % 2 ? 5 : -5, k < 2 ? 5 : -5};
    d.homography = glm::dmat3(10, 0, 0, 0, 10, 0, d.centre.x, d.centre.y, 1);
    detections.push_back(d);
  }
  EXPECT_EQ(ra::buildRoi(ra::parseRoiSpec("tags:2,0,1"), detections).value(),
            ra::polygonThroughTags(detections, {2, 0, 1}).value());
  EXPECT_EQ(ra::buildRoi(ra::parseRoiSpec("hull"), detections).value(),
            ra::convexHullOfTags(detections).value());
  const roiclip::Paths square = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  EXPECT_EQ(ra::buildRoi(ra::parseRoiSpec("tag:1:0,0;1,0;1,1;0,1"), detections).value(),
            ra::tagFrameRoi(detections, 1, square).value());
  EXPECT_FALSE(ra::buildRoi(ra::parseRoiSpec("tags:0,1,7"), detections).ok());
  // Per-tag corners: each vertex is that tag's own corner.
  const roiclip::Paths corners =
      ra::buildRoi(ra::parseRoiSpec("tags:0@top-left,1@bottom-right,2@top-right"), detections)
          .value();
  ASSERT_EQ(corners.size(), 1u);
  EXPECT_EQ(corners[0], (roiclip::Path{detections[0].corner(ra::Corner::TopLeft),
                                       detections[1].corner(ra::Corner::BottomRight),
                                       detections[2].corner(ra::Corner::TopRight)}));
  EXPECT_THROW((void)ra::polygonThroughTags(detections, {0, 1, 2},
                                            std::vector<ra::TagAnchor>{ra::TagAnchor::TopLeft}),
               roiclip::InvalidInputError);
}

}  // namespace
