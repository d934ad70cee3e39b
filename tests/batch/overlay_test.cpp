// SPDX-License-Identifier: MIT
// renderOverlay(): the caption band above the image, annotations that grow with the image, the
// excluded tag quads and the named ROIs drawn; the caption's words shared with report.html.
#include <algorithm>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <roiclip/batch/process.hpp>
#include <roiclip/opencv/rasterize.hpp>

#include "detail/overlay.hpp"

namespace rb = roiclip::batch;

namespace {

const std::string kImages = ROICLIP_IMAGES;

cv::Mat scene(const std::string& name) {
  const cv::Mat image = cv::imread(kImages + "/" + name + ".png", cv::IMREAD_UNCHANGED);
  EXPECT_FALSE(image.empty()) << name;
  return image;
}

// Pixels of `overlay` (BGR) close to `colour`.
cv::Mat near(const cv::Mat& overlay, const cv::Scalar& colour, int tolerance = 40) {
  cv::Mat mask;
  cv::inRange(overlay, colour - cv::Scalar::all(tolerance), colour + cv::Scalar::all(tolerance),
              mask);
  return mask;
}

// The widest run of `mask` pixels along row `y`.
int widestRun(const cv::Mat& mask, int y) {
  int best = 0, run = 0;
  for (int x = 0; x < mask.cols; ++x) {
    run = mask.at<uchar>(y, x) != 0 ? run + 1 : 0;
    best = std::max(best, run);
  }
  return best;
}

const cv::Scalar kRoiYellow(0, 230, 255);
const cv::Scalar kHatchRed(40, 40, 255);

TEST(BatchOverlay, CaptionIsABandAboveTheImage) {
  const cv::Mat image = scene("scene_01");
  const rb::ImageResult r = rb::processImage(image, {});
  ASSERT_EQ(r.status, rb::Status::Ok) << r.reason;
  const cv::Mat overlay = rb::renderOverlay(image, r);
  ASSERT_EQ(overlay.cols, image.cols);
  const int band = overlay.rows - image.rows;
  // Two lines (figures, legend) of a readable font, not a sliver and not half the picture.
  EXPECT_GT(band, 30);
  EXPECT_LT(band, image.rows / 4);
  // The band is black behind its text; the image below it starts with the image's first row
  // (dimmed: the top rows are outside the ROI).
  const cv::Mat bandPixels = overlay.rowRange(0, band);
  cv::Mat gray;
  cv::cvtColor(bandPixels, gray, cv::COLOR_BGR2GRAY);
  EXPECT_GT(cv::countNonZero(gray == 0), static_cast<int>(0.8 * double(gray.total())));
  EXPECT_LT(cv::countNonZero(gray == 0), static_cast<int>(gray.total()));  // some text
  for (int x = 0; x < image.cols; x += 50) {
    EXPECT_NEAR(overlay.at<cv::Vec3b>(band, x)[1], 0.35 * image.at<uchar>(0, x), 1.0) << x;
  }
  // The mask keeps the image's size.
  EXPECT_EQ(rb::renderMask(r).size(), image.size());
}

TEST(BatchOverlay, AnnotationsGrowWithTheImage) {
  const cv::Mat small = scene("scene_01");
  cv::Mat large;
  cv::resize(small, large, {}, 4.0, 4.0, cv::INTER_LINEAR);
  const rb::ImageResult rs = rb::processImage(small, {});
  const rb::ImageResult rl = rb::processImage(large, {});
  ASSERT_EQ(rs.status, rb::Status::Ok) << rs.reason;
  ASSERT_EQ(rl.status, rb::Status::Ok) << rl.reason;
  const cv::Mat os = rb::renderOverlay(small, rs);
  const cv::Mat ol = rb::renderOverlay(large, rl);
  const int bandSmall = os.rows - small.rows;
  const int bandLarge = ol.rows - large.rows;
  EXPECT_NEAR(static_cast<double>(bandLarge) / bandSmall, 4.0, 0.5)
      << bandSmall << " vs " << bandLarge;
  // The ROI's left edge crosses the middle row: its stroke is about 4 times as wide.
  const int strokeSmall = widestRun(near(os, kRoiYellow), bandSmall + small.rows / 2);
  const int strokeLarge = widestRun(near(ol, kRoiYellow), bandLarge + large.rows / 2);
  EXPECT_GE(strokeSmall, 1);
  EXPECT_NEAR(static_cast<double>(strokeLarge) / strokeSmall, 4.0, 1.5)
      << strokeSmall << " vs " << strokeLarge;
  // All yellow: 4 times as long and 4 times as wide.
  EXPECT_GT(cv::countNonZero(near(ol, kRoiYellow)), 10 * cv::countNonZero(near(os, kRoiYellow)));
}

TEST(BatchOverlay, ExcludedTagsAreHatchedAndKeptTagsAreNot) {
  const cv::Mat image = scene("scene_01");
  const rb::ImageResult r = rb::processImage(image, {});
  ASSERT_EQ(r.status, rb::Status::Ok) << r.reason;
  ASSERT_EQ(r.excludedTags.size(), 4u);
  const cv::Mat overlay = rb::renderOverlay(image, r);
  const int band = overlay.rows - image.rows;
  const cv::Mat quads =
      roiclip::opencv::rasterize(r.excludedTags, roiclip::FillRule::NonZero, image.size());
  cv::Mat red;
  cv::bitwise_and(near(overlay.rowRange(band, overlay.rows), kHatchRed, 60), quads, red);
  // About one pixel in ten of the quads is on a hatch line.
  EXPECT_GT(cv::countNonZero(red), cv::countNonZero(quads) / 20);

  rb::RunOptions keep;
  keep.keepTags = true;
  const rb::ImageResult k = rb::processImage(image, keep);
  ASSERT_EQ(k.status, rb::Status::Ok) << k.reason;
  EXPECT_TRUE(k.excludedTags.empty());
  const cv::Mat kept = rb::renderOverlay(image, k);
  cv::bitwise_and(near(kept.rowRange(kept.rows - image.rows, kept.rows), kHatchRed, 60), quads,
                  red);
  EXPECT_LT(cv::countNonZero(red), cv::countNonZero(quads) / 100);
}

TEST(BatchOverlay, EveryNamedRoiIsOutlinedInItsOwnColour) {
  const cv::Mat image = scene("scene_05");
  rb::RunOptions options;
  options.rois = {"board"};  // every ROI of the board: "inspection" and "window"
  options.boardFile = kImages + "/board.json";
  const rb::ImageResult r = rb::processImage(image, options);
  ASSERT_EQ(r.status, rb::Status::Ok) << r.reason;
  ASSERT_EQ(r.rois.size(), 2u);
  const cv::Mat overlay = rb::renderOverlay(image, r);
  const cv::Mat pixels = overlay.rowRange(overlay.rows - image.rows, overlay.rows);
  // Each ROI's outline in its colour: pixels along its paths have it.
  const cv::Scalar colours[] = {kRoiYellow, cv::Scalar(255, 200, 0)};
  for (std::size_t i = 0; i < 2; ++i) {
    cv::Mat outline = cv::Mat::zeros(image.size(), CV_8U);
    for (const auto& path : r.rois[i].paths) {
      std::vector<cv::Point> pts;
      for (const auto& p : path) pts.emplace_back(cvRound(p.x), cvRound(p.y));
      cv::polylines(outline, pts, true, 255, 1);
    }
    cv::Mat hit;
    cv::bitwise_and(near(pixels, colours[i], 50), outline, hit);
    EXPECT_GT(cv::countNonZero(hit), cv::countNonZero(outline) / 2) << r.rois[i].name;
  }
}

TEST(BatchOverlay, CaptionAndReportSayTheSameWords) {
  EXPECT_EQ(rb::detail::contoursInsideText(11, 16), "11 of 16 inside");
}

TEST(BatchOverlay, FailedImageGetsACaptionAndNoAnnotations) {
  const cv::Mat blank(120, 160, CV_8UC1, cv::Scalar(200));
  const rb::ImageResult r = rb::processImage(blank, {});
  ASSERT_EQ(r.status, rb::Status::NoRoi);
  const cv::Mat overlay = rb::renderOverlay(blank, r);
  ASSERT_EQ(overlay.cols, blank.cols);
  const int band = overlay.rows - blank.rows;
  EXPECT_GT(band, 0);
  // Below the band the image is as it was (nothing dimmed: there is no ROI, nothing drawn).
  cv::Mat gray;
  cv::cvtColor(overlay.rowRange(band, overlay.rows), gray, cv::COLOR_BGR2GRAY);
  EXPECT_EQ(cv::countNonZero(gray != 200), 0);
  EXPECT_TRUE(rb::renderOverlay(cv::Mat(), r).empty());
}

}  // namespace
