// NAME.json written and read back (the resume path), and the option/outcome texts both ways.
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include <roiclip/batch/options.hpp>
#include <roiclip/batch/process.hpp>

#include "detail/result_json.hpp"
#include "temp_dir.hpp"

namespace rb = roiclip::batch;

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
  EXPECT_EQ(a.iou, b.iou);
  EXPECT_EQ(a.offBandMismatches, b.offBandMismatches);
  EXPECT_EQ(a.seconds, b.seconds);
}

rb::ImageResult sampleResult(rb::Status status, rb::FailureKind failure, int salt) {
  rb::ImageResult r;
  r.status = status;
  r.failure = failure;
  r.reason = failure == rb::FailureKind::None ? "" : "why \"" + std::to_string(salt) + "\"\n";
  r.width = 640 + salt;
  r.height = 480;
  r.tags.resize(static_cast<std::size_t>(salt % 5));
  r.roi = {{{1.5, 2.25}, {600.125, 3}, {590, 470.75}}};
  r.roiArea = 12345.678901234567 + salt;
  r.contoursIn = 7 + salt;
  r.contoursOut = 3;
  r.clippedArea = 0.1 + salt;  // not exact in binary: the text must round-trip it exactly
  r.vectorVsRaster.iou = 0.987654321012345;
  r.vectorVsRaster.offBandOnlyExpected = salt;
  r.vectorVsOpenCv.emplace();
  r.vectorVsOpenCv->offBandOnlyActual = 2;
  r.seconds.total = 0.0123456789 * (salt + 1);
  return r;
}

TEST(ResultJson, EveryStatusAndFailureKindRoundTrips) {
  int salt = 0;
  for (rb::Status status : kStatuses) {
    for (rb::FailureKind failure : kFailures) {
      SCOPED_TRACE(std::string(rb::toString(status)) + " / " + rb::toString(failure));
      const rb::ImageResult r = sampleResult(status, failure, ++salt);
      const std::string text = rb::detail::resultToJson(r, "sub/img.png", "key");
      const std::optional<rb::ImageRecord> back = rb::detail::parseRecord(text);
      ASSERT_TRUE(back.has_value());
      rb::ImageRecord expected = rb::detail::recordOf(r);
      expected.image = "sub/img.png";
      expectSameRecord(*back, expected);
    }
  }
}

TEST(ResultJson, ResumeReusesOnlyFinalStatusesMadeWithTheSameOptions) {
  const roiclip::testing::TempDir tmp("result_json");
  const auto file = tmp.path() / "x.json";
  for (rb::Status status : kStatuses) {
    for (rb::FailureKind failure : kFailures) {
      SCOPED_TRACE(std::string(rb::toString(status)) + " / " + rb::toString(failure));
      const rb::ImageResult r = sampleResult(status, failure, 3);
      std::ofstream(file, std::ios::trunc) << rb::detail::resultToJson(r, "x.png", "key");
      const std::optional<rb::ImageRecord> rec = rb::detail::readRecord(file, "key");
      const bool final = status == rb::Status::Ok || status == rb::Status::NoRoi;
      ASSERT_EQ(rec.has_value(), final);
      EXPECT_FALSE(rb::detail::readRecord(file, "other key").has_value());
      if (!final) continue;
      rb::ImageRecord expected = rb::detail::recordOf(r);
      expected.image = "x.png";
      expected.skipped = true;
      expected.seconds = 0;  // nothing was processed
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
      rb::detail::resultToJson(sampleResult(rb::Status::Ok, rb::FailureKind::None, 1), "x.png");
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
