// SPDX-License-Identifier: MIT
// Hostile image files through readImage() and run(): every one gets a status and a reason that
// names the problem, the other images of the same run are processed, and decompression bombs
// are refused from their header (the 20000 x 20000 PNG would take 400 MB decoded).
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include <roiclip/batch/process.hpp>
#include <roiclip/batch/run.hpp>

#include "detail/image_file.hpp"

#include "hostile_images.hpp"

namespace fs = std::filesystem;
namespace rb = roiclip::batch;
using Json = nlohmann::json;

namespace {

const fs::path kScene = fs::path(ROICLIP_IMAGES) / "scene_07.png";

// The hostile folder, made once for the whole file.
class Hostile : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("roiclip_hostile_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "in");
    cv::Mat scene = cv::imread(kScene.string(), cv::IMREAD_COLOR);
    ASSERT_FALSE(scene.empty());
    expected_ = roiclip::testing::writeHostileImages(dir_ / "in", scene);
  }
  static void TearDownTestSuite() {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  static fs::path dir_;
  static std::vector<roiclip::testing::HostileImage> expected_;
};
fs::path Hostile::dir_;
std::vector<roiclip::testing::HostileImage> Hostile::expected_;

TEST_F(Hostile, EveryFileGetsItsStatusAndReasonAndTheRunCarriesOn) {
  rb::BatchOptions o;
  o.inputs = {dir_ / "in"};
  o.output = dir_ / "out";
  o.jobs = 2;
  o.force = true;
  const rb::RunSummary s = rb::run(o);
  ASSERT_EQ(s.images.size(), expected_.size());
  std::map<std::string, const rb::ImageRecord*> byName;
  for (const auto& r : s.images) byName[r.image] = &r;
  for (const auto& e : expected_) {
    SCOPED_TRACE(e.file);
    ASSERT_EQ(byName.count(e.file), 1u);
    const rb::ImageRecord& r = *byName[e.file];
    EXPECT_EQ(rb::toString(r.status), e.status) << r.reason;
    EXPECT_EQ(rb::toString(r.failure), e.failure) << r.reason;
    if (e.reason.empty()) {
      EXPECT_EQ(r.reason, "");
    } else {
      EXPECT_NE(r.reason.find(e.reason), std::string::npos) << r.reason;
      if (e.status == "failed") {
        EXPECT_NE(r.reason.find(e.file), std::string::npos) << "names the file: " << r.reason;
      }
    }
    if (e.status == "ok") {
      EXPECT_EQ(r.offBandMismatches, 0);
      EXPECT_GT(r.clippedArea, 0);
    }
  }
  // The same in the files a person reads.
  std::ifstream csv(o.output / "summary.csv");
  std::stringstream text;
  text << csv.rdbuf();
  EXPECT_NE(text.str().find("bomb_zeros.png,failed,too-large,"), std::string::npos);
  EXPECT_NE(text.str().find("text.png,failed,unreadable,"), std::string::npos);
  std::ifstream in(o.output / "bomb_zeros.json");
  const Json j = Json::parse(in);
  EXPECT_EQ(j["failure"], "too-large");
  EXPECT_FALSE(fs::exists(o.output / "bomb_zeros.overlay.png"));
  EXPECT_TRUE(fs::exists(o.output / "gray_alpha.overlay.png"));
}

TEST_F(Hostile, HeadersAreReadWithoutDecoding) {
  const auto header = [&](const std::string& file) {
    return rb::readImageHeader(dir_ / "in" / file);
  };
  const auto bomb = header("bomb_zeros.png");
  ASSERT_TRUE(bomb);
  EXPECT_EQ(bomb->format, "png");
  EXPECT_EQ(bomb->width, 20000);
  EXPECT_EQ(bomb->height, 20000);
  EXPECT_EQ(bomb->channels, 1);
  EXPECT_EQ(header("bomb_header.png")->width, 100000);
  EXPECT_EQ(header("bomb_header.jpg")->height, 60000);
  EXPECT_EQ(header("png_named.jpg")->format, "png");  // by content, not by name
  const auto grayAlpha = header("gray_alpha.png");
  ASSERT_TRUE(grayAlpha);
  EXPECT_EQ(grayAlpha->format, "png");
  EXPECT_EQ(grayAlpha->channels, 2);
  const auto floatTiff = header("float.tiff");
  ASSERT_TRUE(floatTiff);
  EXPECT_EQ(floatTiff->format, "tiff");
  EXPECT_EQ(floatTiff->width, header("good.png")->width);
  EXPECT_EQ(header("truncated.jpg")->format, "jpeg");
  std::vector<uchar> webp;
  ASSERT_TRUE(cv::imencode(".webp", cv::Mat(30, 40, CV_8UC3, cv::Scalar(1, 2, 3)), webp));
  std::ofstream(dir_ / "small.webp", std::ios::binary)
      .write(reinterpret_cast<const char*>(webp.data()), static_cast<std::streamsize>(webp.size()));
  const auto w = rb::readImageHeader((dir_ / "small.webp").string());
  ASSERT_TRUE(w);
  EXPECT_EQ(w->format, "webp");
  EXPECT_EQ(w->width, 40);
  EXPECT_EQ(w->height, 30);
  EXPECT_FALSE(header("text.png"));
  EXPECT_FALSE(header("empty.png"));
  EXPECT_FALSE(header("missing.png"));
}

TEST_F(Hostile, PixelLimitIsInclusiveAndAlsoGuardsDecodedImages) {
  const std::string good = (dir_ / "in" / "good.png").string();
  const cv::Mat scene = rb::readImage(good);
  const auto pixels = static_cast<std::int64_t>(scene.total());
  EXPECT_NO_THROW(rb::readImage(good, pixels));
  EXPECT_NO_THROW(rb::readImage(good, 0));  // no limit
  try {
    rb::readImage(good, pixels - 1);
    FAIL() << "limit not applied";
  } catch (const rb::ImageTooLargeError& e) {
    EXPECT_NE(std::string(e.what()).find("more than the limit of " + std::to_string(pixels - 1)),
              std::string::npos)
        << e.what();
  }
  // processImage() gets a decoded image: the same limit, same failure kind.
  rb::RunOptions options;
  options.maxPixels = pixels - 1;
  const rb::ImageResult r = rb::processImage(scene, options);
  EXPECT_EQ(r.status, rb::Status::Failed);
  EXPECT_EQ(r.failure, rb::FailureKind::TooLarge);
  options.maxPixels = pixels;
  EXPECT_EQ(rb::processImage(scene, options).status, rb::Status::Ok);
  EXPECT_THROW(rb::readImage((dir_ / "in" / "nowhere.png").string()), roiclip::InvalidInputError);
  EXPECT_THROW(rb::readImage(dir_.string()), roiclip::InvalidInputError);  // a folder
}

}  // namespace
