// SPDX-License-Identifier: MIT
// roiclip::opencv clipping at the OpenCV boundary: cv::findContours output in, contours with a
// RETR_CCOMP hierarchy (or per-group polygon sets keeping the source contour index) out.
#pragma once

#include <type_traits>
#include <vector>

#include <opencv2/core.hpp>

#include <roiclip/opencv/convert.hpp>
#include <roiclip/roiclip.hpp>

namespace roiclip::opencv {

// The core's clip() and intersect() stay callable unqualified inside roiclip::opencv next to
// the contour overloads below (otherwise these would hide them).
using roiclip::clip;
using roiclip::intersect;

/// Clip OpenCV contours against a region and return the result as contours:
///   toContours*(roiclip::clip(op, fromContours(contours, hierarchy), region, ...)).
/// All contours together are one subject (read with `contourRule`), so overlapping contours
/// merge; clip per outer contour with clipGroups() to keep them apart.
/// @tparam PointT cv::Point (default; toContours(): snap-rounded to whole pixels, ready for
///         cv::drawContours, cv::pointPolygonTest, cv::moments; rings never cross, parts thinner
///         than a pixel vanish, see toContours()), cv::Point2f (toContours2f()) or cv::Point2d (the
///         exact output, toContours2d()).
/// @param contours  as fromContours(): cv::findContours / cv::approxPolyDP output.
/// @param hierarchy its cv::findContours hierarchy (any retrieval mode), or cv::noArray() to keep
///        every contour's orientation (see fromContours()).
/// @param contourRule the contours' fill rule; EvenOdd is what cv::drawContours(..., FILLED)
///        shows, and with a hierarchy NonZero reads simple contours the same.
/// @return {contours, hierarchy} in RETR_CCOMP layout (see Contours), outer rings with
///         cv::contourArea(c, true) < 0, holes > 0, like cv::findContours output.
/// @throws InvalidInputError as fromContours() and roiclip::clip().
template <typename PointT = cv::Point>
Contours<PointT> clip(ClipOp op, cv::InputArrayOfArrays contours, cv::InputArray hierarchy,
                      const Paths& region, FillRule contourRule = FillRule::EvenOdd,
                      FillRule regionRule = FillRule::EvenOdd, const Grid& grid = {}) {
  static_assert(std::is_same_v<PointT, cv::Point> || std::is_same_v<PointT, cv::Point2f> ||
                    std::is_same_v<PointT, cv::Point2d>,
                "PointT must be cv::Point, cv::Point2f or cv::Point2d");
  const PolygonSet set =
      roiclip::clip(op, fromContours(contours, hierarchy), region, contourRule, regionRule, grid);
  if constexpr (std::is_same_v<PointT, cv::Point>) {
    return toContours(set);
  } else if constexpr (std::is_same_v<PointT, cv::Point2f>) {
    return toContours2f(set);
  } else {
    return toContours2d(set);
  }
}

/// clip(ClipOp::Intersection, ...): the parts of the contours inside `roi`.
template <typename PointT = cv::Point>
Contours<PointT> intersect(cv::InputArrayOfArrays contours, cv::InputArray hierarchy,
                           const Paths& roi, FillRule contourRule = FillRule::EvenOdd,
                           FillRule roiRule = FillRule::EvenOdd, const Grid& grid = {}) {
  return clip<PointT>(ClipOp::Intersection, contours, hierarchy, roi, contourRule, roiRule, grid);
}

/// One ContourGroup after clipping.
struct ClippedGroup {
  int index = -1;       ///< the group's ContourGroup::index (its outer contour's index)
  PolygonSet polygons;  ///< the group's region clipped; may be empty (e.g. outside the ROI)
};

/// Clip every group on its own against `region`: result[i] is
/// { groups[i].index, roiclip::clip(op, groups[i].rings, region, groupRule, regionRule, grid) },
/// so every piece keeps the index of the contour it came from, and groups that overlap stay
/// apart. One entry per group, in order, empty results included.
/// @throws InvalidInputError as roiclip::clip(); an error in a group's rings carries the source
///         "contour INDEX" (location().source; "path P" is then the ring within the group).
std::vector<ClippedGroup> clipGroups(ClipOp op, const std::vector<ContourGroup>& groups,
                                     const Paths& region, FillRule groupRule = FillRule::EvenOdd,
                                     FillRule regionRule = FillRule::EvenOdd,
                                     const Grid& grid = {});

}  // namespace roiclip::opencv
