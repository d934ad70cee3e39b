// SPDX-License-Identifier: MIT
// roiclip::batch internal: the words the overlay caption and report.html share, so both say the
// same thing.
#pragma once

#include <string>

namespace roiclip::batch::detail {

/// "11 of 16 inside": `inside` contours (ImageResult::contoursOut) of the `found` ones kept
/// (contoursIn) have a part inside the region.
std::string contoursInsideText(int inside, int found);

}  // namespace roiclip::batch::detail
