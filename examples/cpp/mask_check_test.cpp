// SPDX-License-Identifier: MIT
// Check a clip result against raster masks in a GoogleTest, as roiclip's own tests do: the
// rasterised result must equal (subject mask AND ROI mask) off a thin band around the edges.
#include <roiclip/opencv/mask_check.hpp>
#include <roiclip/roiclip.hpp>

#include <gtest/gtest.h>

namespace {

const cv::Size kImage(64, 48);
// A self-intersecting subject (a bow-tie) and a tilted quad as the ROI.
const roiclip::Paths kSubject = {{{4.5, 4}, {50, 40.25}, {50, 6}, {6, 42}}};
const roiclip::Paths kRoi = {{{10, 2}, {40, 8}, {36, 44}, {8, 40}}};

}  // namespace

TEST(MaskCheck, ClipAgreesWithTheRasterRoute) {
  const roiclip::PolygonSet result = roiclip::intersect(kSubject, kRoi, roiclip::FillRule::EvenOdd);
  ASSERT_FALSE(result.empty());
  const roiclip::opencv::MaskCheck check = roiclip::opencv::checkRoiClip(
      kSubject, kRoi, result, roiclip::FillRule::EvenOdd, roiclip::FillRule::EvenOdd, kImage);
  EXPECT_TRUE(check.ok()) << "vector vs raster: " << check.vectorVsRaster;
  // Within the band the raster routes may differ (a pixel centre on an edge, rounding of the
  // result's vertices); off it they agree exactly. The whole-image IoU includes the band.
  EXPECT_EQ(check.vectorVsRaster.offBandIou, 1.0);
  EXPECT_GT(check.vectorVsRaster.iou, 0.95);
}

TEST(MaskCheck, CatchesAWrongResult) {
  // The union instead of the intersection: many pixels off the band disagree.
  const roiclip::PolygonSet wrong = roiclip::unite(kSubject, kRoi, roiclip::FillRule::EvenOdd);
  const roiclip::opencv::MaskCheck check = roiclip::opencv::checkRoiClip(
      kSubject, kRoi, wrong, roiclip::FillRule::EvenOdd, roiclip::FillRule::EvenOdd, kImage);
  EXPECT_FALSE(check.ok());
  EXPECT_GT(check.vectorVsRaster.offBandOnlyActual, 0);
}
