// SPDX-License-Identifier: MIT
// Tag corners in cv::aruco's order (clockwise on screen from the top-left, or from the
// bottom-right for OpenCV 4's AprilTag dictionaries) and back.
#include <cmath>
#include <string>

#include <roiclip/apriltag/detector.hpp>

#include "homography.hpp"

namespace roiclip::apriltag {
namespace {

// With ArucoFirstCorner::TopLeft, cv::aruco's corner k is Detection::corners[kFromAruco[k]];
// BottomRight starts two places on.
constexpr Corner kFromAruco[4] = {Corner::TopLeft, Corner::TopRight, Corner::BottomRight,
                                  Corner::BottomLeft};

int detectionIndex(int arucoIndex, ArucoFirstCorner first) {
  const int start = first == ArucoFirstCorner::BottomRight ? 2 : 0;
  return static_cast<int>(kFromAruco[(arucoIndex + start) % 4]);
}

}  // namespace

std::array<glm::dvec2, 4> arucoCorners(const Detection& detection, ArucoFirstCorner first) {
  std::array<glm::dvec2, 4> out{};
  for (int k = 0; k < 4; ++k) out[k] = detection.corners[detectionIndex(k, first)];
  return out;
}

Detection detectionFromArucoCorners(int id, const std::array<glm::dvec2, 4>& corners,
                                    const std::string& family, ArucoFirstCorner first) {
  for (int k = 0; k < 4; ++k) {
    if (!std::isfinite(corners[k].x) || !std::isfinite(corners[k].y)) {
      throw InvalidInputError("aruco corner " + std::to_string(k) + " of tag " +
                              std::to_string(id) + " is not a finite point");
    }
  }
  // A tag's image is a convex quadrilateral; clockwise on screen (y down), every corner turns
  // with a positive cross product. This also refuses libapriltag's (counter-clockwise) order.
  for (int k = 0; k < 4; ++k) {
    const glm::dvec2 a = corners[(k + 1) % 4] - corners[k];
    const glm::dvec2 b = corners[(k + 2) % 4] - corners[(k + 1) % 4];
    if (!(a.x * b.y - a.y * b.x > 0)) {
      throw InvalidInputError("aruco corners of tag " + std::to_string(id) +
                              " do not form a convex quadrilateral running clockwise on screen "
                              "(cv::aruco's order; libapriltag's runs counter-clockwise)");
    }
  }
  Detection d;
  d.id = id;
  d.family = family;
  for (int k = 0; k < 4; ++k) d.corners[detectionIndex(k, first)] = corners[k];
  d.homography = detail::tagFrameHomography(d.corners);
  d.centre = d.tagToImage({0.0, 0.0});
  return d;
}

Detection detectionFromArucoCorners(int id, cv::InputArray corners, const std::string& family,
                                    ArucoFirstCorner first) {
  const cv::Mat m = corners.getMat();
  const int n = m.checkVector(2);
  if (n != 4 || (m.depth() != CV_32F && m.depth() != CV_64F)) {
    throw InvalidInputError("aruco corners of tag " + std::to_string(id) +
                            ": expected 4 points of CV_32FC2 or CV_64FC2 (cv::Point2f/2d)");
  }
  cv::Mat points;
  (m.isContinuous() ? m : m.clone()).reshape(2, 4).convertTo(points, CV_64FC2);
  std::array<glm::dvec2, 4> c{};
  for (int k = 0; k < 4; ++k) {
    const cv::Vec2d v = points.at<cv::Vec2d>(k);
    c[k] = {v[0], v[1]};
  }
  return detectionFromArucoCorners(id, c, family, first);
}

}  // namespace roiclip::apriltag
