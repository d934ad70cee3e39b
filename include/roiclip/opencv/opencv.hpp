// roiclip::opencv: everything where roiclip meets OpenCV (conversions, exact rasteriser, mask
// checks). Link roiclip::opencv.
#pragma once

#include <roiclip/opencv/convert.hpp>
#include <roiclip/opencv/mask_check.hpp>
#include <roiclip/opencv/rasterize.hpp>
