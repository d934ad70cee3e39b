// SPDX-License-Identifier: MIT
// roiclip::opencv mask comparison: the project's proof that vector results match raster masks.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <optional>

#include <opencv2/core.hpp>

#include <roiclip/roiclip.hpp>

namespace roiclip::opencv {

/// Band (px) for comparing two masks made by rasterize(): both follow the same exact pixel
/// rule, and only the clip result's vertices (crossings rounded to double, then snapped to the
/// 1/256 px grid) differ from the exact geometry, by at most 1/256 px. 0.05 px leaves a margin.
constexpr double kExactBand = 0.05;

/// Band (px) for comparing rasterize() with cv::fillPoly (LINE_8). fillPoly draws every edge as
/// a line between its end points rounded to whole pixels (up to 0.71 px off) whose pixels lie up
/// to 0.5 px off that line, and its fixed-point scanline fill rounds vertex rows to whole pixels;
/// so it sets pixels outside the polygon and misses some inside. Measured (an empirical bound,
/// not a proof) over 420,000 random self-intersecting polygons of 24x24 to 300x300 px: pixels
/// set only by fillPoly lie up to 1.31 px from an edge with integer vertices and up to 1.87 px
/// with shift = 8; pixels set only by rasterize() up to 0.48 px. The OpenCvBand test re-measures
/// it. 2 px is far narrower than the regions compared; off the band the masks agree exactly.
constexpr double kOpenCvBand = 2.0;

/// Result of compareMasks(). "On" means non-zero.
struct MaskComparison {
  std::int64_t onlyExpected = 0;  ///< pixels on in expected, off in actual
  std::int64_t onlyActual = 0;    ///< pixels on in actual, off in expected
  std::int64_t both = 0;          ///< pixels on in both
  double iou = 1.0;               ///< both / (both + onlyExpected + onlyActual); 1 if all off
  double boundaryBand = 0.0;      ///< the band used below (px)
  std::int64_t bandPixels = 0;    ///< pixels ignored because they lie within the band
  std::int64_t offBandOnlyExpected = 0;  ///< onlyExpected, excluding band pixels
  std::int64_t offBandOnlyActual = 0;    ///< onlyActual, excluding band pixels
  double offBandIou = 1.0;               ///< IoU over the pixels outside the band

  /// True when the masks agree on every pixel outside the band.
  [[nodiscard]] bool agreesOffBand() const {
    return offBandOnlyExpected == 0 && offBandOnlyActual == 0;
  }
};

/// One line: "IoU 0.9973 (only expected 12, only actual 3, both 5432); off band 2 px: IoU 1
/// (only expected 0, only actual 0, 118 band pixels ignored)".
std::ostream& operator<<(std::ostream& os, const MaskComparison& c);

/// Compare two single-channel masks of the same size, pixel by pixel.
/// @param expected,actual CV_8U single-channel masks, same size; any non-zero value is "on".
/// @param boundaryBand pixels whose centre is within this distance (px, >= 0) of any edge of
///        `edges` are counted in bandPixels instead of the off-band counts.
/// @param edges the paths whose edges define the band: normally every path of both operands
///        (subject and clip), since every boundary of a result lies on one of them.
/// @throws InvalidInputError on a type or size mismatch, a negative or NaN band, or NaN in edges.
MaskComparison compareMasks(cv::InputArray expected, cv::InputArray actual, double boundaryBand,
                            const Paths& edges);

/// Pixels whose centre lies within `band` px (Euclidean distance to the closed segment) of any
/// edge of `paths`, as a CV_8U mask (255 = within the band).
cv::Mat boundaryBandMask(const Paths& paths, double band, cv::Size size);

/// Options of checkRoiClip().
struct MaskCheckOptions {
  /// The operation to check; the ROI case is Intersection. The raster routes combine the two
  /// masks with the matching bitwise operation (and, or, and-not, xor).
  ClipOp op = ClipOp::Intersection;
  double exactBand = kExactBand;    ///< band for (a) vs (b)
  double openCvBand = kOpenCvBand;  ///< band for (a) vs (c)
  Grid grid{};                      ///< the grid the result was clipped on
};

/// What checkRoiClip() found.
struct MaskCheck {
  MaskComparison vectorVsRaster;                 ///< (a) vs (b)
  std::optional<MaskComparison> vectorVsOpenCv;  ///< (a) vs (c); only for even-odd/even-odd
  /// True when every comparison made agrees off its band.
  [[nodiscard]] bool ok() const {
    return vectorVsRaster.agreesOffBand() && (!vectorVsOpenCv || vectorVsOpenCv->agreesOffBand());
  }
};

/// The mask check used by the tests and the batch pipeline: is `result` what the core should
/// have returned for clip(options.op, subject, roi, subjectRule, roiRule, options.grid)?
/// It never clips; it compares
///   (a) rasterize(result)
///   (b) rasterize(subject, subjectRule) AND rasterize(roi, roiRule)       band: exactBand
///   (c) cv::fillPoly(subject) AND cv::fillPoly(roi), both at kDefaultShift, band: openCvBand;
///       only when both rules are FillRule::EvenOdd, the only rule cv::fillPoly implements.
/// (AND is replaced by OR, AND NOT or XOR when options.op is another operation.)
/// The band is measured from the edges of subject and roi. Off the band the masks must agree
/// exactly; any difference there is a bug (in the core or in the rasteriser), or `result` is not
/// the clip of these operands.
/// @param result the clip result to check (e.g. what the caller got from clip()).
/// @param size image size in pixels; geometry outside it is ignored by all three masks.
MaskCheck checkRoiClip(const Paths& subject, const Paths& roi, const PolygonSet& result,
                       FillRule subjectRule, FillRule roiRule, cv::Size size,
                       const MaskCheckOptions& options = {});

}  // namespace roiclip::opencv
