// SPDX-License-Identifier: MIT
// roiclip::opencv open polylines from edge images (for clipLines()).
#pragma once

#include <opencv2/core.hpp>

#include <roiclip/roiclip.hpp>

namespace roiclip::opencv {

/// Trace a binary edge image (non-zero = edge, CV_8UC1, e.g. cv::Canny output) into open
/// polylines through the pixel centres: 8-connected chains, each pixel used once, starting at
/// chain ends (pixels with one neighbour) and then on closed loops. A branch ends one chain and
/// starts another. Single pixels give one-point polylines.
/// @throws InvalidInputError for another image type (an empty image gives no polylines).
Paths traceEdges(cv::InputArray edges);

/// cv::approxPolyDP (open curves) on every polyline, with epsilon in px. The points pass
/// through float (approxPolyDP takes no double): exact for pixel centres up to 2^24 px.
void approximatePolylines(Paths& polylines, double epsilon);

/// Total length of open polylines (px).
double polylineLength(const Paths& polylines);

}  // namespace roiclip::opencv
