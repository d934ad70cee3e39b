// SPDX-License-Identifier: MIT
// roiclip::opencv conversions between OpenCV contours and roiclip paths / polygon sets.
//
// Pixel convention (the same as OpenCV and the rest of roiclip): x right, y down, (0,0) is the
// centre of the top-left pixel. A contour from cv::findContours runs through the centres of the
// boundary pixels, so the polygon it describes covers only half of each boundary pixel; see
// rasterize.hpp for which pixels a polygon covers.
#pragma once

#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>  // cv::LINE_8

#include <roiclip/roiclip.hpp>

namespace roiclip::opencv {

/// Default number of fractional bits for fixed-point drawing (cv::fillPoly's `shift`).
/// 8 bits = 1/256 px, the same as roiclip's default Grid, so drawing loses nothing the core kept.
constexpr int kDefaultShift = 8;

/// Convert one contour to a roiclip path.
/// @param contour a cv::Mat or std::vector of 2-channel points: CV_32SC2 (cv::Point), CV_32FC2
///        (cv::Point2f) or CV_64FC2 (cv::Point2d); an N x 1, 1 x N or N x 2 single-channel matrix
///        of the same depths is accepted as cv::Mat::checkVector(2) allows it. Empty is allowed.
/// @return the points in order (the path is closed implicitly).
/// @throws InvalidInputError if the type is not one of the above or a coordinate is NaN or
///         infinite; the message names the contour (as "contour 0") and the point index.
Path fromContour(cv::InputArray contour);

/// Convert cv::findContours / cv::approxPolyDP output (any number of contours, each as in
/// fromContour()) to roiclip paths, one path per contour, in the same order. Self-intersecting
/// contours (approxPolyDP makes them) are fine: the core resolves them under a fill rule.
/// Without a hierarchy the orientation of each contour is kept as it is, so read the result with
/// FillRule::EvenOdd (what cv::fillPoly and cv::drawContours(..., FILLED) draw for one call).
/// @throws InvalidInputError naming the contour and point, as fromContour().
Paths fromContours(cv::InputArrayOfArrays contours);

/// As fromContours(contours), using a cv::findContours hierarchy (any retrieval mode) to orient
/// every contour: contours at even depth (outer boundaries) get a negative shoelace sum and
/// contours at odd depth (holes) a positive one, as roiclip outputs them. The result then means
/// the same region under FillRule::NonZero and FillRule::EvenOdd, even when approxPolyDP or a
/// hand-made contour list had inconsistent orientations.
/// @param hierarchy CV_32SC4, one [next, previous, firstChild, parent] entry per contour, or
///        empty (then this is fromContours(contours)).
/// @throws InvalidInputError when the hierarchy has the wrong type or size, refers to a
///         contour that does not exist, or has a cycle.
Paths fromContours(cv::InputArrayOfArrays contours, cv::InputArray hierarchy);

/// One outer contour of cv::findContours with its holes, the unit roiclip clips and reports
/// contours in (detectContours(), groupContours(), clipGroups()).
struct ContourGroup {
  int index = -1;  ///< index of the outer contour in cv::findContours' output
  /// Outer ring first (negative shoelace sum), then its holes (positive), as
  /// fromContours(contours, hierarchy) orients them.
  Paths rings;
};

/// Group cv::findContours output into outer contours with their holes, keeping each outer
/// contour's index. Contours at even depth of the hierarchy are outer contours (with
/// RETR_CCOMP: the top level), each starts a group; a contour at odd depth is a hole of its
/// parent's group. Rings are oriented as fromContours(contours, hierarchy) orients them, so a
/// group means the same region under FillRule::NonZero and EvenOdd (unless approxPolyDP made a
/// ring self-intersect). Groups come in contour order, holes in contour order within a group
/// (for cv::findContours output that is the firstChild/next order).
/// @param hierarchy as fromContours(); RETR_CCOMP or RETR_TREE (islands in holes become groups
///        of their own). Empty: every contour is a group of one ring, its orientation kept.
/// @throws InvalidInputError as fromContours(contours, hierarchy).
std::vector<ContourGroup> groupContours(cv::InputArrayOfArrays contours, cv::InputArray hierarchy);

/// Contours and their hierarchy in cv::findContours' RETR_CCOMP layout: every polygon's outer
/// ring is a top-level contour (parent -1) linked to the other outer rings by next/previous;
/// its holes are its children (linked to each other by next/previous, firstChild of the outer
/// ring points at the first one). Islands inside holes are top-level contours too.
/// hierarchy[i] = {next, previous, firstChild, parent}, -1 where there is none.
template <typename PointT>
struct Contours {
  std::vector<std::vector<PointT>> contours;  ///< the rings, as cv::findContours returns them
  std::vector<cv::Vec4i> hierarchy;           ///< one {next, previous, firstChild, parent} each
};

/// Convert a polygon set to integer cv::Point contours (+ RETR_CCOMP hierarchy). Ring
/// orientations are kept: outer rings have cv::contourArea(c, true) < 0, holes > 0, like
/// cv::findContours output.
///
/// The set is snap-rounded to whole pixels first (roiclip::roundTo(set, 1.0)), so the integer
/// contours never cross or overlap, holes stay inside their outer ring, and cv::fillPoly /
/// cv::drawContours see a valid region: each boundary point moves by at most 0.71 px, parts and
/// holes thinner than a pixel may vanish, and parts closer than a pixel may come to touch. Rings
/// may touch at shared vertices, as cv::findContours output does. For sub-pixel drawing use
/// toFixedPointContours() / fillPolygonSet().
/// @throws InvalidInputError if a coordinate does not fit in an int.
Contours<cv::Point> toContours(const PolygonSet& set);
/// As toContours(), in float (no rounding to pixels; float keeps ~1/256 px up to 32768 px).
Contours<cv::Point2f> toContours2f(const PolygonSet& set);
/// As toContours(), in double: the exact output coordinates.
Contours<cv::Point2d> toContours2d(const PolygonSet& set);

/// Fixed-point contours for cv::fillPoly / cv::polylines, which take a `shift`: each coordinate
/// is v * 2^shift, an integer, so vertices keep 1/2^shift px precision. cv::drawContours takes
/// no shift (only an offset), so it would draw these 2^shift times too large; give it
/// toContours() instead, or draw with fillPolygonSet() / drawPolygonSet().
struct FixedPointContours {
  Contours<cv::Point> contours;  ///< coordinates scaled by 2^shift
  int shift = kDefaultShift;     ///< fractional bits, for cv::fillPoly / cv::polylines
};
/// Convert a polygon set to fixed-point contours; pass `shift` on to OpenCV's drawing calls.
/// As toContours() does at whole pixels, the set is snap-rounded onto the 2^-shift px grid first
/// (roiclip::roundTo(set, 2^-shift)), so the contours never cross or overlap and holes stay
/// inside their outer ring: each boundary point moves by at most 0.71 * 2^-shift px, and parts
/// thinner than 2^-shift px may vanish. The hierarchy is toContours()'s.
/// @param shift fractional bits, 0..16 (cv::fillPoly's limit).
/// @throws InvalidInputError if shift is out of range, a scaled coordinate does not fit in int,
/// or the set spans more than 2^30 steps of 2^-shift px (16384 px at shift 16).
FixedPointContours toFixedPointContours(const PolygonSet& set, int shift = kDefaultShift);
/// The same for raw paths (e.g. an ROI), no hierarchy (every path is a top-level contour). Raw
/// paths may cross anyway, so each vertex is rounded on its own (std::lround(v * 2^shift)).
FixedPointContours toFixedPointContours(const Paths& paths, int shift = kDefaultShift);

/// Fill a polygon set into `image` with cv::fillPoly at sub-pixel precision (kDefaultShift).
/// All rings, snap-rounded to 1/2^kDefaultShift px (toFixedPointContours()), go into one
/// cv::fillPoly call (even-odd), which is exactly the rounded region because they never cross.
/// Like every cv::fillPoly call, it also draws each edge
/// as a line, so pixels up to about 1 px outside the region can be set; rasterize() sets
/// exactly the pixels whose centres are inside.
/// @param image CV_8U..CV_64F image of any channel count, modified in place.
void fillPolygonSet(cv::InputOutputArray image, const PolygonSet& set, const cv::Scalar& color,
                    int lineType = cv::LINE_8);

/// Draw the rings of a polygon set as closed polylines at sub-pixel precision (kDefaultShift),
/// snap-rounded as fillPolygonSet() fills them (the outlines never cross).
void drawPolygonSet(cv::InputOutputArray image, const PolygonSet& set, const cv::Scalar& color,
                    int thickness = 1, int lineType = cv::LINE_8);

/// Fill closed paths (any, e.g. an ROI or raw contours) under a fill rule into `image` at
/// sub-pixel precision (kDefaultShift), drawn as fillPolygonSet() draws.
/// FillRule::EvenOdd is what cv::fillPoly implements, so the paths go into one cv::fillPoly call
/// as they are. For the other rules the paths are first resolved exactly by
/// simplify(paths, rule) (so the same grid snapping), whose rings mean the same under even-odd,
/// and those are filled: the filled region is exactly the rule's, with the same edge-line
/// margin as cv::fillPoly (pixels up to about 1 px outside; rasterize() has none).
/// @throws InvalidInputError as simplify() (NaN, out-of-range coordinates).
void fillPaths(cv::InputOutputArray image, const Paths& paths, FillRule rule,
               const cv::Scalar& color, int lineType = cv::LINE_8);

/// Draw paths with cv::polylines at sub-pixel precision (kDefaultShift): closed (the last point
/// joined to the first) by default, or open for polylines such as clipLines() output.
void drawPaths(cv::InputOutputArray image, const Paths& paths, const cv::Scalar& color,
               int thickness = 1, int lineType = cv::LINE_8, bool closed = true);

}  // namespace roiclip::opencv
