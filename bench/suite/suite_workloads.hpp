// SPDX-License-Identifier: MIT
// The W1-W5 workloads of issue 13: integer pixel contours (std::vector<cv::Point>) in a
// 1920x1080 frame, each clipped against a convex region. Every generator is deterministic (fixed
// parameters and seeds), so every library and every run sees the same input.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include <roiclip/roiclip.hpp>

namespace roiclip::bench::suite {

using Contour = std::vector<cv::Point>;
using Contours = std::vector<Contour>;

/// One clipping call: intersection(subject, clip) under the row's fill rule (both operands).
struct Job {
  Contours subject;
  Contours clip;
  /// The subject as polygons for Boost.Geometry and GEOS: outer contour index first, then the
  /// indices of its holes (a RETR_CCOMP hierarchy). A single-contour subject is {{0}}.
  std::vector<std::vector<int>> groups;
};

/// One table row: every job of it is one timed unit (W4 has 10,000 jobs, the others one).
struct Row {
  std::string name;
  FillRule rule = FillRule::EvenOdd;
  std::vector<Job> jobs;
  [[nodiscard]] std::size_t vertices() const;
};

/// The 1920x1080 frame and the ROI quad Q = (930,70) (1640,170) (1560,1000) (900,950).
extern const cv::Size kFrame;
Contour roiQuad();

/// W1: the smooth star r(t) = 430 + 230 tanh(c sin kt) / tanh c (c = kStarSharpness), y scaled by
/// 0.75, centred in the frame, resampled to `vertices` points at equal arc length and rounded to
/// integers; consecutive repeats dropped.
constexpr double kStarSharpness = 3.0;
Contour starContour(int lobes, std::size_t vertices);
/// W1-100k: the cv::findContours(RETR_EXTERNAL, CHAIN_APPROX_NONE) pixel chain of the star with
/// `lobes` lobes rasterised (cv::fillPoly of a dense sampling, 1/256 px fixed point).
Contour starPixelChain(int lobes);

/// W2: the epitrochoid x = R cos t + d cos mt, y = R sin t + d sin mt with m = vertices / 16,
/// sampled at `vertices` equal steps of t and rounded (consecutive repeats dropped). Its m - 1
/// loops have diameter 2d = 2.5 loop spacings (2 pi R / (m - 1)), so each loop overlaps its
/// neighbours about 2.5 deep and even-odd and non-zero give different regions. R + d = 500 px.
Contour epitrochoid(std::size_t vertices);

/// W3: `vertices` uniform integer points in [0, 1000)^2, joined in draw order (std::mt19937).
Contour randomIntegerPolygon(std::size_t vertices, unsigned seed);

/// W4: 10,000 filled ellipses (one per cell of a 125x80 grid over the frame, semi-axes 2.5 to
/// 4.5 px, random angle, cv::RNG seed 4), traced with findContours(RETR_EXTERNAL, NONE).
Contours ellipseContours();

/// W5: an image of images/, Otsu threshold (inverted) and findContours(RETR_CCOMP, method).
struct ImageContours {
  Contours contours;
  std::vector<std::vector<int>> groups;  ///< outer contour index, then its holes
};
ImageContours imageContours(const std::string& pngFile, int method);
/// The convex hull (cv::convexHull, rounded to integer pixels) of every tag corner listed in an
/// images/scene_NN.json ground-truth file.
Contour tagHull(const std::string& jsonFile);

/// A row by name, generated only when needed (generation of W1-100k, W4 and W5 takes a while
/// under callgrind).
struct RowRecipe {
  std::string name;
  std::function<Row()> make;
};
/// Every row of the suite in table order. `imagesDir` holds the scene_NN.png / .json pairs.
std::vector<RowRecipe> rowRecipes(const std::string& imagesDir);

}  // namespace roiclip::bench::suite
