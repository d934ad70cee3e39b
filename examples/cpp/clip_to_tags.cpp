// SPDX-License-Identifier: MIT
// Clip the contours of an image to the region its AprilTags mark, and draw the result.
//
//   clip_to_tags IMAGE [OVERLAY.png]
//
// The region is the convex hull of all tags minus the tags themselves (the tags are not
// objects), as `roiclip run` does by default; the contours are Otsu's dark objects, each outer
// contour with its holes (cv::RETR_CCOMP), read under the even-odd rule. Prints the clipped area
// in px^2 (the `clipped_area` of `roiclip run`'s summary.csv for the same image).
#include <roiclip/apriltag/detector.hpp>
#include <roiclip/apriltag/roi.hpp>
#include <roiclip/opencv/opencv.hpp>
#include <roiclip/roiclip.hpp>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <cstdio>
#include <iostream>
#include <vector>

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: clip_to_tags IMAGE [OVERLAY.png]\n";
    return 1;
  }
  const cv::Mat gray = cv::imread(argv[1], cv::IMREAD_GRAYSCALE);
  if (gray.empty()) {
    std::cerr << argv[1] << ": cannot read the image\n";
    return 1;
  }

  // The region: hull of the tags (tag36h11) minus every tag quad.
  const roiclip::apriltag::Detector detector;
  const std::vector<roiclip::apriltag::Detection> tags = detector.detect(gray);
  const roiclip::apriltag::RoiResult hull = roiclip::apriltag::convexHullOfTags(tags);
  if (!hull) {
    std::cerr << argv[1] << ": " << hull.missing().describe() << "\n";
    return 2;
  }
  roiclip::Paths tagQuads;
  for (const roiclip::apriltag::Detection& tag : tags) {
    tagQuads.emplace_back(tag.corners.begin(), tag.corners.end());
  }
  const roiclip::PolygonSet region =
      roiclip::subtract(hull.value(), tagQuads, roiclip::FillRule::NonZero);

  // The contours, straight from OpenCV.
  cv::Mat binary;
  cv::threshold(gray, binary, 0, 255, cv::THRESH_BINARY_INV | cv::THRESH_OTSU);
  std::vector<std::vector<cv::Point>> contours;
  std::vector<cv::Vec4i> hierarchy;
  cv::findContours(binary, contours, hierarchy, cv::RETR_CCOMP, cv::CHAIN_APPROX_SIMPLE);

  // Clip exactly: the region as a PolygonSet operand, the contours under even-odd.
  const roiclip::PolygonSet inside =
      roiclip::intersect(roiclip::opencv::fromContours(contours, hierarchy), region);
  std::printf("tags %zu, contours %zu, clipped polygons %zu, clipped area %.3f px^2\n", tags.size(),
              contours.size(), inside.polygons.size(), inside.area());

  // Draw: the region in yellow, the clipped parts filled in green at sub-pixel precision, and
  // their rounded contours (cv::drawContours takes RETR_CCOMP contours + hierarchy) in red.
  if (argc > 2) {
    cv::Mat overlay;
    cv::cvtColor(gray, overlay, cv::COLOR_GRAY2BGR);
    roiclip::opencv::fillPolygonSet(overlay, inside, cv::Scalar(0, 200, 0));
    const roiclip::opencv::Contours<cv::Point> drawn = roiclip::opencv::toContours(inside);
    cv::drawContours(overlay, drawn.contours, -1, cv::Scalar(0, 0, 255), 1, cv::LINE_8,
                     drawn.hierarchy);
    roiclip::opencv::drawPaths(overlay, region.toPaths(), cv::Scalar(0, 255, 255), 2);
    if (!cv::imwrite(argv[2], overlay)) {
      std::cerr << argv[2] << ": cannot write the overlay\n";
      return 1;
    }
  }
  return inside.empty() ? 3 : 0;
}
