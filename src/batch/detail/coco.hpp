// SPDX-License-Identifier: MIT
// roiclip::batch internal: the run as one COCO instance-annotation file (BatchOptions::coco;
// layout and the choices it makes in docs/outputs.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include <roiclip/batch/run.hpp>

namespace roiclip::batch::detail {

/// The COCO text of a finished run: every ok image of `summary` (images[], ids from 1 in
/// summary order) with one annotation per source contour, read back from the NAME.json files
/// in options.output.
/// @throws Error naming the NAME.json of an ok image that cannot be read back.
std::string cocoJson(const RunSummary& summary, const BatchOptions& options);

/// COCO's uncompressed RLE "counts" of the region `rings` covers under the even-odd rule in an
/// image of `size`, by opencv::rasterize's exact pixel rule: run lengths of the column-major
/// (Fortran order) mask, starting with a run of 0s (possibly empty); they add up to
/// size.area(). Only the rings' bounding box is rasterised.
std::vector<std::int64_t> cocoRleCounts(const Paths& rings, cv::Size size, const Grid& grid = {});

}  // namespace roiclip::batch::detail
