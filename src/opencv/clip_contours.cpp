// SPDX-License-Identifier: MIT
// Clipping contour groups one by one, keeping each group's source contour index.
#include <roiclip/opencv/clip_contours.hpp>

#include <string>

namespace roiclip::opencv {

std::vector<ClippedGroup> clipGroups(ClipOp op, const std::vector<ContourGroup>& groups,
                                     const Paths& region, FillRule groupRule, FillRule regionRule,
                                     const Grid& grid) {
  std::vector<ClippedGroup> out;
  out.reserve(groups.size());
  for (const ContourGroup& group : groups) {
    try {
      out.push_back(
          {group.index, roiclip::clip(op, group.rings, region, groupRule, regionRule, grid)});
    } catch (const InvalidInputError& e) {
      if (e.location().operand != Operand::Subject) throw;
      throw e.withSource("contour " + std::to_string(group.index));
    }
  }
  return out;
}

}  // namespace roiclip::opencv
