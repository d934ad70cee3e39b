// SPDX-License-Identifier: MIT
// roiclip::apriltag: AprilTag detection on cv::Mat images (a wrapper over libapriltag 3.3).
//
// Pixel convention: every coordinate this header returns is in OpenCV's convention, (0,0) is the
// CENTRE of the top-left pixel, x right, y down (see roiclip/geometry.hpp). libapriltag itself
// puts (0,0) at the top-left CORNER of the first pixel; the wrapper subtracts that 0.5 px.
//
// AprilTag's own headers are deliberately not included here: common/math_util.h defines a `max`
// macro that breaks <algorithm> in any file that includes it.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <opencv2/core/mat.hpp>

#include <roiclip/error.hpp>

namespace roiclip::apriltag {

/// Index of a tag corner in Detection::corners. This is libapriltag's own order: it runs
/// counter-clockwise on screen (y down) starting at the bottom-left corner of an upright tag.
/// "Upright" means the tag looks like the image apriltag_to_image() renders for its id, with
/// no rotation.
enum class Corner : int {
  BottomLeft = 0,
  BottomRight = 1,
  TopRight = 2,
  TopLeft = 3,
};

/// One decoded tag. All coordinates in OpenCV pixel-centre convention.
struct Detection {
  int id = -1;                  ///< the tag's id in its family
  std::string family;           ///< e.g. "tag36h11"
  int hamming = 0;              ///< number of corrected bit errors
  double decisionMargin = 0;    ///< libapriltag's decode quality (higher is better)
  glm::dvec2 centre{0.0, 0.0};  ///< image of the tag centre (the homography's (0,0))
  /// Outer corners of the black border, indexed by Corner (libapriltag's order, see Corner).
  std::array<glm::dvec2, 4> corners{};
  /// Image-from-tag homography. The tag frame has its origin at the tag centre, x to the right
  /// and y down when the tag is upright, and the unit is the side of the black border: the
  /// corners are (-0.5,-0.5) TopLeft, (0.5,-0.5) TopRight, (0.5,0.5) BottomRight,
  /// (-0.5,0.5) BottomLeft. Column-major GLM matrix acting on homogeneous (x, y, 1).
  glm::dmat3 homography{1.0};

  /// The corner `c` (same as corners[int(c)]).
  [[nodiscard]] glm::dvec2 corner(Corner c) const { return corners[static_cast<int>(c)]; }
  /// Map a point given in the tag frame (see homography) into the image.
  [[nodiscard]] glm::dvec2 tagToImage(glm::dvec2 tagPoint) const;
};

/// Which corner of a tag comes first in a cv::aruco corner list; the list then runs clockwise
/// on screen (y down). "Top-left" etc. refer to the upright tag (see Corner).
enum class ArucoFirstCorner {
  /// The tag's top-left: cv::aruco's documented order (top-left, top-right, bottom-right,
  /// bottom-left), as cv::aruco::drawDetectedMarkers and cv::solvePnP with SOLVEPNP_IPPE_SQUARE
  /// take it, and as cv::aruco reports its own ArUco dictionaries.
  TopLeft,
  /// The tag's bottom-right: what cv::aruco::detectMarkers of OpenCV 4 reports for the
  /// DICT_APRILTAG_* dictionaries, which it reads turned by 180 degrees against libapriltag
  /// (tested with OpenCV 4.6 for 16h5, 25h9, 36h10 and 36h11; see opencv/opencv-python#1195 —
  /// OpenCV 5 changes this, opencv/opencv#28823). Use it for corners that cv::aruco found with
  /// an AprilTag dictionary in OpenCV 4.
  BottomRight,
};

/// The corners of `detection` in cv::aruco's order: Detection::corners reordered, for
/// ArucoFirstCorner::TopLeft {TopLeft, TopRight, BottomRight, BottomLeft}, for BottomRight
/// {BottomRight, BottomLeft, TopLeft, TopRight}. (libapriltag's own order runs the other way:
/// counter-clockwise on screen from the bottom-left, see Corner.) Both lists are in OpenCV's
/// pixel-centre convention, so no shift is involved.
std::array<glm::dvec2, 4> arucoCorners(const Detection& detection,
                                       ArucoFirstCorner first = ArucoFirstCorner::TopLeft);

/// A Detection from corners in cv::aruco's order (e.g. one marker cv::aruco found), so that tags
/// found by cv::aruco can be handed to the ROI builders (roi.hpp). The corners become
/// Detection::corners in libapriltag's order, the homography is fitted to them exactly and
/// `centre` is its image of the tag centre; hamming and decisionMargin are 0.
/// arucoCorners(result, first) gives `corners` back.
/// @param corners clockwise on screen from the corner `first` says,
///        in OpenCV's pixel convention (what cv::aruco returns).
/// @param first   which tag corner `corners` starts at; BottomRight for cv::aruco's AprilTag
///        dictionaries in OpenCV 4 (see ArucoFirstCorner).
/// @throws InvalidInputError if a coordinate is not finite, or the corners do not form a convex
///         quadrilateral running clockwise on screen (libapriltag's order runs the other way; so
///         does a mirrored tag; three collinear corners are not strictly convex).
Detection detectionFromArucoCorners(int id, const std::array<glm::dvec2, 4>& corners,
                                    const std::string& family = "",
                                    ArucoFirstCorner first = ArucoFirstCorner::TopLeft);
/// As above, from cv::aruco's own type for one marker: 4 points as std::vector<cv::Point2f>
/// (or any array cv::Mat::checkVector(2) accepts with 4 points, CV_32F or CV_64F).
/// @throws InvalidInputError also when `corners` is not 4 points of those types.
Detection detectionFromArucoCorners(int id, cv::InputArray corners, const std::string& family = "",
                                    ArucoFirstCorner first = ArucoFirstCorner::TopLeft);

/// Detector settings; the names follow libapriltag's apriltag_detector_t fields.
struct DetectorOptions {
  /// Tag family name, or several separated by commas ("tag36h11,tag25h9"); see
  /// availableFamilies(). Unknown or repeated names throw InvalidInputError.
  std::string family = "tag36h11";
  /// Detect quads on an image decimated by this factor (>= 1), or 0 (the default) for automatic
  /// decimation: a coarse factor chosen from each image's size by autoQuadDecimate(), then finer
  /// passes (each at most half the factor before, down to 1) while a pass finds no tag, finds a
  /// tag whose side is below kAutoDecimateMinTagSide decimated pixels, or misses an expected id
  /// (Detector::detectReport). Corners are refined on the full resolution image either way
  /// (refineEdges), so decimation costs little corner accuracy. One pass finds tags whose black
  /// square, divided by the factor, is 14 pixels or more a side; with automatic decimation a
  /// smaller tag is lost only when a larger one is found beside it and no expected id is missing.
  float quadDecimate = 0.0f;
  /// Gaussian blur sigma applied to the quad-detection image (0 = off, negative = sharpen).
  /// The caller's image is never modified (see Detector::detect).
  float quadSigma = 0.0f;
  /// Snap quad edges to strong gradients of the full-resolution image (recommended with
  /// quadDecimate > 1).
  bool refineEdges = true;
  /// libapriltag worker threads for one detect() call (>= 1). Built against libapriltag before
  /// 3.4.3 (Debian 12's 3.3.0), one worker runs whatever this asks: that worker pool can crash
  /// with more than one thread (a worker reads a task while the detector moves the task array;
  /// fixed upstream in AprilRobotics/apriltag#339). DetectionReport::threads tells which.
  /// Detect several images at once with one Detector each (as `roiclip run --jobs` does).
  int threads = 1;
  /// Sharpening of the decoded payload image (libapriltag default 0.25).
  double decodeSharpening = 0.25;
  /// Number of bit errors the decoder may correct (0..3). 2 is libapriltag's default; larger
  /// values need much more memory for the big families.
  int maxBitsCorrected = 2;
  /// Detections with more corrected bit errors than this (0..3) are rejected: a tag decoded
  /// with corrections is often another pattern misread (a wrong family, print texture).
  int maxHamming = 0;
  /// Detections whose decision margin (libapriltag's decode quality) is below this are rejected.
  double minDecisionMargin = 0.0;
};

/// The first pass of automatic decimation searches quads on at least this many pixels (about
/// 0.12 MP: 480 x 270 for a 1080p frame). Tags whose black square is 14 decimated pixels or more
/// a side are found there (56 px at 1080p); tests/apriltag/detector_test.cpp measures it.
constexpr double kAutoDecimatePixels = 120'000;
/// With automatic decimation, a finer pass follows when the last pass found no tag, or its
/// smallest tag side is below this many decimated pixels (a tag that small suggests smaller ones
/// were lost), or an expected id is missing.
constexpr double kAutoDecimateMinTagSide = 16;

/// The decimation DetectorOptions::quadDecimate = 0 uses for a width x height image: the largest
/// of 1, 1.5, 2, 3, 4, 5, 6, 8, 10, 12, 16 that leaves at least kAutoDecimatePixels pixels
/// (so 1.5 for 640 x 480, 2 for 800 x 600, 4 for 1920 x 1080, 8 for 3840 x 2160, 16 for
/// 8000 x 6000).
float autoQuadDecimate(int width, int height);

/// What one Detector::detectReport() call found.
struct DetectionReport {
  std::vector<Detection> tags;      ///< accepted detections, sorted by id (then centre x)
  std::vector<Detection> rejected;  ///< decoded but over maxHamming or under minDecisionMargin
  float quadDecimate = 1.0f;        ///< the decimation of the pass whose detections these are
  int passes = 1;                   ///< libapriltag passes run (automatic decimation may add some)
  int threads = 1;                  ///< libapriltag worker threads each pass ran with
};

/// Family names this build supports (those libapriltag 3.3 ships): tag36h11, tag25h9, tag16h5,
/// tagStandard41h12, tagStandard52h13, tagCircle21h7, tagCircle49h12, tagCustom48h12, tag36h10.
std::vector<std::string> availableFamilies();

/// Number of distinct ids in a family (valid ids are 0 .. familySize-1).
/// @throws InvalidInputError for an unknown family name.
int familySize(const std::string& family);

/// Render tag `id` of `family` as libapriltag draws it: an 8-bit image (0 black, 255 white) of
/// total_width x total_width cells, one pixel per cell, including the white outer border.
/// @param[out] blackBorderCells side of the black border in cells (e.g. 8 for tag36h11).
/// @throws InvalidInputError for an unknown family or an id out of range.
cv::Mat renderTag(const std::string& family, int id, int* blackBorderCells = nullptr);

/// An AprilTag detector for one family.
///
/// Ownership: each Detector creates its own libapriltag family object (libapriltag must not
/// share one family between two detectors: both would free its decode table) and destroys the
/// libapriltag detector before that family.
///
/// Threads: detect() may be called from several threads at once on the same Detector; the calls
/// are serialised by an internal mutex because libapriltag's detector keeps per-call state.
/// For parallel detection give each thread its own Detector.
class Detector {
 public:
  /// @throws InvalidInputError for an unknown family or out-of-range options (the message names
  ///         the option).
  explicit Detector(DetectorOptions options = {});
  ~Detector();
  /// Move only; a moved-from Detector throws Error from detect().
  Detector(Detector&&) noexcept;
  /// Move only, as the move constructor.
  Detector& operator=(Detector&&) noexcept;
  Detector(const Detector&) = delete;
  Detector& operator=(const Detector&) = delete;

  /// Detect all tags of the family in `image`.
  /// @param image 8-bit gray (CV_8UC1; a cv::Mat is used without a copy, any row step), BGR
  ///        (CV_8UC3) or BGRA (CV_8UC4, converted to gray). Never modified.
  /// @return detections sorted by id (then by centre x), coordinates in OpenCV convention.
  /// @throws InvalidInputError if the image is empty or not 8-bit with 1, 3 or 4 channels.
  /// @throws Error if this Detector was moved from.
  [[nodiscard]] std::vector<Detection> detect(cv::InputArray image) const;

  /// As detect(), also returning the rejected detections and the decimation used.
  /// @param image as detect().
  /// @param quadDecimate overrides DetectorOptions::quadDecimate for this call when > 0 (for
  ///        a finer second try after the automatic factor missed a tag).
  /// @param expectedIds with automatic decimation, ids the caller expects in the image (the
  ///        tags an ROI spec names): a pass that misses one of them is followed by a finer one.
  [[nodiscard]] DetectionReport detectReport(cv::InputArray image, float quadDecimate = 0,
                                             const std::vector<int>& expectedIds = {}) const;

  /// The options this Detector was made with.
  [[nodiscard]] const DetectorOptions& options() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace roiclip::apriltag
