// SPDX-License-Identifier: MIT
// roiclip::opencv contour detection: an image in, roiclip paths out (each outer contour of
// cv::findContours with its holes, oriented as roiclip outputs rings), and the image conversions
// the detection needs.
#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include <roiclip/opencv/convert.hpp>  // ContourGroup
#include <roiclip/roiclip.hpp>

namespace roiclip::opencv {

/// Convert any image cv::imread returns (8- or 16-bit, float; 1, 3 or 4 channels; 2 channels
/// are read as gray + alpha) to 8-bit gray. 16-bit is scaled by 255/65535, float by 255
/// (assumed in [0, 1]; values outside saturate, NaN becomes 0). An 8-bit gray input is returned
/// as is (no copy).
/// @throws InvalidInputError naming `source` if the image is empty or of an unsupported type.
cv::Mat toGray8(cv::InputArray image, const std::string& source = "image");

/// The same conversion to 8-bit BGR (always a new image), e.g. to draw on in colour.
/// @throws InvalidInputError naming `source` if the image is empty or of an unsupported type.
cv::Mat toBgr8(cv::InputArray image, const std::string& source = "image");

/// How the object mask for cv::findContours is made from the gray image.
enum class ContourMethod {
  Otsu,       ///< global threshold chosen by Otsu's method (default)
  Adaptive,   ///< cv::adaptiveThreshold (Gaussian), block `adaptiveBlock`, offset `adaptiveC`
  Canny,      ///< cv::Canny edges (`cannyLow`, `cannyHigh`); every edge pixel is a region
  Threshold,  ///< fixed threshold `threshold`
};

/// Which pixels are objects: dark ones on a light background (default) or light on dark.
enum class Polarity { Dark, Light };

/// Contour detection settings.
struct ContourOptions {
  ContourMethod method = ContourMethod::Otsu;  ///< how the object mask is made
  Polarity polarity = Polarity::Dark;          ///< which pixels are objects
  int threshold = 128;       ///< ContourMethod::Threshold: objects are <= threshold (Dark) or > it
  int adaptiveBlock = 51;    ///< odd, >= 3
  double adaptiveC = 10.0;   ///< ContourMethod::Adaptive: offset subtracted from the local mean
  double cannyLow = 50.0;    ///< cv::Canny's lower hysteresis threshold
  double cannyHigh = 150.0;  ///< cv::Canny's upper hysteresis threshold
  /// cv::approxPolyDP epsilon in px applied to every contour (0 = off). approxPolyDP may make
  /// contours self-intersect; the core resolves them under the fill rule.
  double approxEpsilon = 0.0;
  /// Outer contours whose absolute cv::contourArea is below this (px^2) are dropped with their
  /// holes.
  double minArea = 0.0;
  /// Also trace the Canny edges (cannyLow, cannyHigh) as open polylines (see edges.hpp).
  /// Independent of `method`; detectContours() itself ignores it.
  bool openEdges = false;
};

/// Detect contours as `options` says (RETR_CCOMP, CHAIN_APPROX_SIMPLE, then approxPolyDP when
/// options.approxEpsilon > 0) and group each outer contour with its holes (groupContours()).
/// Outer contours below options.minArea are dropped with their holes. Groups come in
/// findContours' order.
/// @param gray CV_8UC1, not empty.
/// @throws InvalidInputError for another image type or a bad adaptive block size.
std::vector<ContourGroup> detectContours(cv::InputArray gray, const ContourOptions& options);

/// The area of a group that came straight from cv::findContours (no cv::approxPolyDP), under
/// every fill rule, without a core call: such rings follow pixel borders, so they touch
/// themselves and each other at most (never cross) and holes lie inside their outer ring; the
/// winding number is then 0 or 1 everywhere and the area is the rings' shoelace sum (computed in
/// integers, then rounded once to double). For a group that may cross itself (approxPolyDP
/// output), use roiclip::simplify(group.rings, rule).area().
double pixelContourArea(const ContourGroup& group);

}  // namespace roiclip::opencv
