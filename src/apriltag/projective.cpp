// SPDX-License-Identifier: MIT
#include <roiclip/apriltag/projective.hpp>

#include <cmath>
#include <string>

#include <opencv2/core.hpp>

#include <roiclip/error.hpp>

#include "homography.hpp"

namespace roiclip::apriltag {
namespace {

double homogeneousW(const glm::dmat3& h, glm::dvec2 p) {
  return h[0][2] * p.x + h[1][2] * p.y + h[2][2];
}

}  // namespace

glm::dvec2 applyHomography(const glm::dmat3& h, glm::dvec2 p) {
  const glm::dvec3 q = h * glm::dvec3(p, 1.0);
  if (q.z == 0.0 || !std::isfinite(q.z)) {
    throw Error("homography maps (" + std::to_string(p.x) + ", " + std::to_string(p.y) +
                ") to infinity");
  }
  return {q.x / q.z, q.y / q.z};
}

Paths mapPaths(const glm::dmat3& h, const Paths& paths) {
  int sign = 0;
  Paths out;
  out.reserve(paths.size());
  for (std::size_t i = 0; i < paths.size(); ++i) {
    Path mapped;
    mapped.reserve(paths[i].size());
    for (std::size_t k = 0; k < paths[i].size(); ++k) {
      const double w = homogeneousW(h, paths[i][k]);
      const int s = w > 0 ? 1 : (w < 0 ? -1 : 0);
      if (s == 0 || (sign != 0 && s != sign)) {
        throw InvalidInputError("path " + std::to_string(i) + " vertex " + std::to_string(k) +
                                " lies on or beyond the homography's line at infinity");
      }
      sign = s;
      mapped.push_back(applyHomography(h, paths[i][k]));
    }
    out.push_back(std::move(mapped));
  }
  return out;
}

namespace detail {

glm::dmat3 homographyFrom4(const glm::dvec2 (&from)[4], const glm::dvec2 (&to)[4]) {
  // Direct 8x8 solve with h33 = 1, in double (cv::getPerspectiveTransform takes float points).
  cv::Matx<double, 8, 8> a;
  cv::Vec<double, 8> b;
  for (int k = 0; k < 4; ++k) {
    const double x = from[k].x, y = from[k].y, u = to[k].x, v = to[k].y;
    const double rowU[8] = {x, y, 1, 0, 0, 0, -x * u, -y * u};
    const double rowV[8] = {0, 0, 0, x, y, 1, -x * v, -y * v};
    for (int c = 0; c < 8; ++c) {
      a(2 * k, c) = rowU[c];
      a(2 * k + 1, c) = rowV[c];
    }
    b(2 * k) = u;
    b(2 * k + 1) = v;
  }
  cv::Vec<double, 8> h;
  if (!cv::solve(a, b, h, cv::DECOMP_LU)) {
    throw InvalidInputError("degenerate quadrilateral: no homography through its 4 corners");
  }
  return toGlm(cv::Matx33d(h(0), h(1), h(2), h(3), h(4), h(5), h(6), h(7), 1.0));
}

glm::dmat3 tagFrameHomography(const std::array<glm::dvec2, 4>& corners) {
  glm::dvec2 from[4];
  glm::dvec2 to[4];
  for (int k = 0; k < 4; ++k) {
    from[k] = {kTagFrameCorners[k][0], kTagFrameCorners[k][1]};
    to[k] = corners[k];
  }
  return homographyFrom4(from, to);
}

}  // namespace detail
}  // namespace roiclip::apriltag
