// SPDX-License-Identifier: MIT
// roiclip::opencv: everything where roiclip meets OpenCV (conversions, clipping contours, exact
// rasteriser, mask checks, contour detection, edge tracing). Link roiclip::opencv.
#pragma once

#include <roiclip/opencv/clip_contours.hpp>
#include <roiclip/opencv/contours.hpp>
#include <roiclip/opencv/convert.hpp>
#include <roiclip/opencv/edges.hpp>
#include <roiclip/opencv/mask_check.hpp>
#include <roiclip/opencv/rasterize.hpp>
