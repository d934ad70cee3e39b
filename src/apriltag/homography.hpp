// SPDX-License-Identifier: MIT
// Private helpers: conversions between cv::Matx33d and glm::dmat3, tag-frame homographies.
#pragma once

#include <array>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <opencv2/core/matx.hpp>

#include <roiclip/apriltag/projective.hpp>

namespace roiclip::apriltag::detail {

using roiclip::apriltag::applyHomography;

/// OpenCV matrices are row-major (m(row, col)); GLM is column-major (m[col][row]).
inline glm::dmat3 toGlm(const cv::Matx33d& m) {
  glm::dmat3 g(1.0);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) g[c][r] = m(r, c);
  }
  return g;
}

inline cv::Matx33d toCv(const glm::dmat3& g) {
  cv::Matx33d m;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) m(r, c) = g[c][r];
  }
  return m;
}

/// Corner positions in the tag frame, indexed like Detection::corners (libapriltag's order:
/// bottom-left, bottom-right, top-right, top-left; y down, unit = black-border side).
constexpr double kTagFrameCorners[4][2] = {{-0.5, 0.5}, {0.5, 0.5}, {0.5, -0.5}, {-0.5, -0.5}};

/// The exact homography taking from[k] to to[k] (no three points collinear).
/// @throws InvalidInputError for a degenerate quadrilateral.
glm::dmat3 homographyFrom4(const glm::dvec2 (&from)[4], const glm::dvec2 (&to)[4]);

/// The exact homography taking the tag-frame corners to `corners`.
glm::dmat3 tagFrameHomography(const std::array<glm::dvec2, 4>& corners);

}  // namespace roiclip::apriltag::detail
