// SPDX-License-Identifier: MIT
// NAME.json written and read back (the resume path), and the option/outcome texts both ways.
#include <algorithm>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <roiclip/batch/options.hpp>
#include <roiclip/batch/process.hpp>

#include "detail/result_json.hpp"
#include "temp_dir.hpp"

namespace rb = roiclip::batch;
using Json = nlohmann::json;

namespace {

constexpr rb::Status kStatuses[] = {rb::Status::Ok, rb::Status::NoRoi, rb::Status::Failed,
                                    rb::Status::MaskMismatch};
constexpr rb::FailureKind kFailures[] = {
    rb::FailureKind::None,     rb::FailureKind::Unreadable,  rb::FailureKind::TooLarge,
    rb::FailureKind::NoTags,   rb::FailureKind::MissingTags, rb::FailureKind::InvalidInput,
    rb::FailureKind::Internal, rb::FailureKind::Mismatch};

void expectSameRecord(const rb::ImageRecord& a, const rb::ImageRecord& b) {
  EXPECT_EQ(a.image, b.image);
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.failure, b.failure);
  EXPECT_EQ(a.reason, b.reason);
  EXPECT_EQ(a.skipped, b.skipped);
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  EXPECT_EQ(a.tagsFound, b.tagsFound);
  EXPECT_EQ(a.roiArea, b.roiArea);
  EXPECT_EQ(a.contoursIn, b.contoursIn);
  EXPECT_EQ(a.contoursOut, b.contoursOut);
  EXPECT_EQ(a.clippedArea, b.clippedArea);
  EXPECT_EQ(a.tagsRejected, b.tagsRejected);
  ASSERT_EQ(a.rois.size(), b.rois.size());
  for (std::size_t i = 0; i < a.rois.size(); ++i) {
    EXPECT_EQ(a.rois[i].name, b.rois[i].name);
    EXPECT_EQ(a.rois[i].roiArea, b.rois[i].roiArea);
    EXPECT_EQ(a.rois[i].contoursOut, b.rois[i].contoursOut);
    EXPECT_EQ(a.rois[i].clippedArea, b.rois[i].clippedArea);
  }
  EXPECT_EQ(a.iou, b.iou);
  EXPECT_EQ(a.offBandMismatches, b.offBandMismatches);
  EXPECT_EQ(a.seconds, b.seconds);
  for (const auto& [name, member] : rb::detail::kStageTimes) {
    EXPECT_EQ(a.stageSeconds.*member, b.stageSeconds.*member) << name;
  }
}

bool checked(rb::Status s) { return s == rb::Status::Ok || s == rb::Status::MaskMismatch; }

rb::ImageResult sampleResult(rb::Status status, rb::FailureKind failure, int salt) {
  rb::ImageResult r;
  r.status = status;
  r.failure = failure;
  r.reason = failure == rb::FailureKind::None ? "" : "why \"" + std::to_string(salt) + "\"\n";
  r.width = 640 + salt;
  r.height = 480;
  r.tags.resize(static_cast<std::size_t>(salt % 5));
  r.rejectedTags.resize(static_cast<std::size_t>(salt % 3));
  r.rois.push_back({"hull", {}, {}, 100.25 + salt, 2, 0.3 + salt});
  if (salt % 2 == 0) r.rois.push_back({"board:window", {}, {}, 7.125, 1, 0.7});
  r.roi = {{{1.5, 2.25}, {600.125, 3}, {590, 470.75}}};
  r.roiArea = 12345.678901234567 + salt;
  r.contoursIn = 7 + salt;
  r.contoursOut = 3;
  r.clippedArea = 0.1 + salt;  // not exact in binary: the text must round-trip it exactly
  r.vectorVsRaster.iou = 0.987654321012345;
  r.vectorVsRaster.offBandOnlyExpected = salt;
  r.vectorVsOpenCv.emplace();
  r.vectorVsOpenCv->offBandOnlyActual = 2;
  double t = 0.001 * salt;
  for (const auto& stage : rb::detail::kStageTimes) {
    r.seconds.*stage.second = t;
    t += 0.0123456789;
  }
  return r;
}

TEST(ResultJson, EveryStatusAndFailureKindRoundTrips) {
  int salt = 0;
  for (rb::Status status : kStatuses) {
    for (rb::FailureKind failure : kFailures) {
      SCOPED_TRACE(std::string(rb::toString(status)) + " / " + rb::toString(failure));
      const rb::ImageResult r = sampleResult(status, failure, ++salt);
      const std::string text = rb::resultToJson(r, "sub/img.png", "key");
      const std::optional<rb::ImageRecord> back = rb::detail::parseRecord(text);
      ASSERT_TRUE(back.has_value());
      rb::ImageRecord expected = rb::detail::recordOf(r);
      expected.image = "sub/img.png";
      expectSameRecord(*back, expected);
      // IoU only where the mask check ran; null in the file otherwise.
      EXPECT_EQ(back->iou.has_value(), checked(status));
      const Json j = Json::parse(text);
      EXPECT_EQ(j["schema_version"], rb::kSchemaVersion);
      EXPECT_EQ(j["roiclip_version"], rb::roiclipVersion());
      EXPECT_EQ(j["mask_check"].is_null(), !checked(status));
      for (const auto& [name, member] : rb::detail::kStageTimes) {
        EXPECT_EQ(j["seconds"][name], r.seconds.*member) << name;
      }
    }
  }
}

TEST(ResultJson, OtherSchemaVersionsAreNotRead) {
  const rb::ImageResult r = sampleResult(rb::Status::Ok, rb::FailureKind::None, 2);
  Json j = Json::parse(rb::resultToJson(r, "x.png", "key"));
  ASSERT_TRUE(rb::detail::parseRecord(j.dump()).has_value());
  j.erase("schema_version");  // the layout of roiclip 0.1
  EXPECT_FALSE(rb::detail::parseRecord(j.dump()).has_value());
  for (const Json& version : {Json(1), Json(3), Json("2"), Json(nullptr)}) {
    j["schema_version"] = version;
    EXPECT_FALSE(rb::detail::parseRecord(j.dump()).has_value()) << version;
  }
}

TEST(ResultJson, ClippedPolygonsAreGeoJsonFeaturesThatReadBack) {
  // Two contours inside two ROIs: one square with a hole, in both; one triangle, in the second.
  rb::ImageResult r = sampleResult(rb::Status::Ok, rb::FailureKind::None, 2);
  const roiclip::Path square = {{0, 0}, {0, 10}, {10, 10}, {10, 0}};  // negative shoelace sum
  const roiclip::Path hole = {{2, 2}, {8, 2}, {8, 8}, {2, 8}};
  const roiclip::Path triangle = {{20, 0}, {20, 5}, {25, 0}};
  rb::ContourResult a;
  a.contourIndex = 4;
  a.clipped.polygons.push_back({square, {hole}, -1, -1});
  a.rois = {0, 1};
  rb::ContourResult b;
  b.contourIndex = 9;
  b.clipped.polygons.push_back({triangle, {}, -1, -1});
  b.rois = {1};
  r.contours = {a, b};
  r.clipped.polygons = {b.clipped.polygons[0], a.clipped.polygons[0]};
  std::rotate(r.clipped.polygons[1].outer.begin(), r.clipped.polygons[1].outer.begin() + 2,
              r.clipped.polygons[1].outer.end());  // the one clip may start a ring elsewhere
  const roiclip::testing::TempDir tmp("result_json_clipped");
  const auto file = tmp.path() / "x.json";
  const std::string text = rb::resultToJson(r, "x.png");
  std::ofstream(file, std::ios::trunc) << text;

  const Json j = Json::parse(text);
  EXPECT_EQ(j["coordinates"], rb::detail::kPixelCoordinates);
  const Json& features = j["clipped"]["features"];
  ASSERT_EQ(features.size(), 2u);
  const Json& ring = features[1]["geometry"]["coordinates"][0];
  ASSERT_EQ(ring.size(), 5u);
  EXPECT_EQ(ring.front(), ring.back());  // closed, as GeoJSON requires
  EXPECT_EQ(features[1]["properties"]["holes"], 1);
  EXPECT_EQ(features[1]["properties"]["parent"], nullptr);
  EXPECT_EQ(j["contours"][0]["features"], Json::array({1}));
  EXPECT_EQ(j["contours"][1]["features"], Json::array({0}));

  const auto back = rb::detail::readClipped(file);
  ASSERT_TRUE(back.has_value());
  ASSERT_EQ(back->size(), 2u);
  EXPECT_EQ((*back)[0].contourIndex, 9);
  EXPECT_EQ((*back)[0].rois, std::vector<std::string>({"board:window"}));
  EXPECT_EQ((*back)[0].area, 12.5);
  EXPECT_EQ((*back)[0].polygon.outer, triangle);
  EXPECT_EQ((*back)[1].contourIndex, 4);
  EXPECT_EQ((*back)[1].rois, std::vector<std::string>({"hull", "board:window"}));
  EXPECT_EQ((*back)[1].area, 100.0 - 36.0);
  ASSERT_EQ((*back)[1].polygon.holes.size(), 1u);
  EXPECT_EQ((*back)[1].polygon.holes[0], hole);

  // A polygon no contour's clip has (touching contours joined) has a null source.
  r.clipped.polygons.push_back({{{40, 0}, {40, 5}, {45, 0}}, {}, -1, -1});
  std::ofstream(file, std::ios::trunc) << rb::resultToJson(r, "x.png");
  const auto joined = rb::detail::readClipped(file);
  ASSERT_TRUE(joined.has_value());
  ASSERT_EQ(joined->size(), 3u);
  EXPECT_EQ((*joined)[2].contourIndex, -1);
  EXPECT_TRUE((*joined)[2].rois.empty());
  std::ofstream(file, std::ios::trunc) << "{}";
  EXPECT_FALSE(rb::detail::readClipped(file).has_value());
}

TEST(ResultJson, ResumeReusesOnlyFinalStatusesMadeWithTheSameOptions) {
  const roiclip::testing::TempDir tmp("result_json");
  const auto file = tmp.path() / "x.json";
  for (rb::Status status : kStatuses) {
    for (rb::FailureKind failure : kFailures) {
      SCOPED_TRACE(std::string(rb::toString(status)) + " / " + rb::toString(failure));
      const rb::ImageResult r = sampleResult(status, failure, 3);
      std::ofstream(file, std::ios::trunc) << rb::resultToJson(r, "x.png", "key");
      const std::optional<rb::ImageRecord> rec = rb::detail::readRecord(file, "key");
      const bool final = status == rb::Status::Ok || status == rb::Status::NoRoi;
      ASSERT_EQ(rec.has_value(), final);
      EXPECT_FALSE(rb::detail::readRecord(file, "other key").has_value());
      if (!final) continue;
      rb::ImageRecord expected = rb::detail::recordOf(r);
      expected.image = "x.png";
      expected.skipped = true;
      expected.seconds = 0;  // nothing was processed
      expected.stageSeconds = {};
      expectSameRecord(*rec, expected);
    }
  }
  for (const char* bad : {"", "[]", "{}", "{\"status\": \"ok\"}", "not json"}) {
    std::ofstream(file, std::ios::trunc) << bad;
    EXPECT_FALSE(rb::detail::readRecord(file, "").has_value()) << bad;
    EXPECT_FALSE(rb::detail::parseRecord(bad).has_value()) << bad;
  }
  // An unknown status or failure text is no record (never mapped to a near one).
  std::string text =
      rb::resultToJson(sampleResult(rb::Status::Ok, rb::FailureKind::None, 1), "x.png");
  const std::string none = "\"failure\":\"none\"";
  ASSERT_NE(text.find(none), std::string::npos);
  text.replace(text.find(none), none.size(), "\"failure\":\"nothing\"");
  EXPECT_FALSE(rb::detail::parseRecord(text).has_value());
  EXPECT_FALSE(rb::detail::readRecord(tmp.path() / "missing.json", "").has_value());
}

TEST(OptionTexts, EveryEnumBothWays) {
  for (rb::Status s : kStatuses) EXPECT_EQ(rb::parseStatus(rb::toString(s)), s);
  for (rb::FailureKind f : kFailures) EXPECT_EQ(rb::parseFailureKind(rb::toString(f)), f);
  EXPECT_FALSE(rb::parseStatus("OK").has_value());
  EXPECT_FALSE(rb::parseFailureKind("").has_value());
  for (rb::ContourMethod m :
       {rb::ContourMethod::Otsu, rb::ContourMethod::Adaptive, rb::ContourMethod::Canny}) {
    rb::ContourOptions o;
    rb::parseContourMethod(rb::toString(m), o);
    EXPECT_EQ(o.method, m);
  }
  rb::ContourOptions o;
  rb::parseContourMethod(std::string(rb::toString(rb::ContourMethod::Threshold)) + ":7", o);
  EXPECT_EQ(o.method, rb::ContourMethod::Threshold);
  EXPECT_EQ(o.threshold, 7);
  for (rb::Polarity p : {rb::Polarity::Dark, rb::Polarity::Light}) {
    EXPECT_EQ(rb::parsePolarity(rb::toString(p)), p);
  }
}

}  // namespace
