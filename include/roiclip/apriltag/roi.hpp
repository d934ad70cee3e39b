// SPDX-License-Identifier: MIT
// roiclip::apriltag: regions of interest built from detected AprilTags.
//
// Every builder returns roiclip::Paths (image pixels, OpenCV pixel-centre convention, y down)
// ready for roiclip::clip(). A returned ROI may self-intersect (e.g. tags listed out of spatial
// order); the core reads it under whatever fill rule the caller chooses. When the tags a builder
// needs were not detected it returns a failed RoiResult naming the ids needed and seen, never an
// empty ROI.
//
//   const roiclip::apriltag::Detector detector;                  // tag36h11
//   const auto tags = detector.detect(image);                      // cv::Mat, gray or BGR
//   const auto board = roiclip::apriltag::Board::load("board.json");
//   const roiclip::apriltag::RoiResult roi = roiclip::apriltag::boardRoi(board, tags,
//   "inspection"); if (!roi) std::cerr << roi.missing().describe() << '\n';   // e.g. "... missing
//   [2]" else inside = roiclip::intersect(contours, roi.value(), roiclip::FillRule::NonZero);
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>

#include <roiclip/apriltag/detector.hpp>
#include <roiclip/apriltag/projective.hpp>
#include <roiclip/error.hpp>
#include <roiclip/geometry.hpp>

namespace roiclip::apriltag {

/// Why a builder could not produce its ROI.
struct MissingTags {
  std::vector<int> needed;      ///< ids the builder asked for (sorted, unique)
  std::vector<int> seen;        ///< ids present in the detections (sorted, unique)
  std::vector<int> missing;     ///< needed ids that were not seen
  std::vector<int> duplicated;  ///< needed ids seen more than once (ambiguous)
  int minimumNeeded = 0;        ///< how many of `needed` had to be seen
  /// One line for logs, e.g. "needed tags [0 1 2 3], seen [0 1 3]: missing [2]".
  [[nodiscard]] std::string describe() const;
};

/// Thrown when a failed result is used as if it had succeeded.
class MissingTagsError : public Error {
 public:
  /// The error for `info`; what() includes info.describe().
  explicit MissingTagsError(MissingTags info);
  /// Which tags were needed, seen and missing.
  [[nodiscard]] const MissingTags& info() const { return info_; }

 private:
  MissingTags info_;
};

/// Either a value or the MissingTags that prevented it.
template <class T>
class TagResult {
 public:
  /// A successful result.
  TagResult(T value) : value_(std::move(value)) {}  // NOLINT: implicit on purpose
  /// A failed result.
  TagResult(MissingTags missing) : value_(std::move(missing)) {}  // NOLINT
  /// True when the result holds a value.
  [[nodiscard]] bool ok() const { return value_.index() == 0; }
  /// ok().
  explicit operator bool() const { return ok(); }
  /// The value. @throws MissingTagsError when !ok(), so a failure is never read as empty.
  [[nodiscard]] const T& value() const {
    if (!ok()) throw MissingTagsError(std::get<MissingTags>(value_));
    return std::get<T>(value_);
  }
  /// The failure. @throws Error when ok().
  [[nodiscard]] const MissingTags& missing() const {
    if (ok()) throw Error("TagResult::missing() called on a successful result");
    return std::get<MissingTags>(value_);
  }

 private:
  std::variant<T, MissingTags> value_;
};

using RoiResult = TagResult<Paths>;

/// Which point of a tag a polygon vertex is taken from.
enum class TagAnchor { Centre, BottomLeft, BottomRight, TopRight, TopLeft };

/// Parse "centre"/"center", "bottom-left", "bottom-right", "top-right", "top-left" (also with
/// '_'). @throws InvalidInputError naming the text.
TagAnchor parseTagAnchor(const std::string& text);

/// One closed path through the anchor point of each listed tag, in the order given (as in
/// `--roi tags:0,1,2,3`). Listing ids out of spatial order gives a self-intersecting path; that is
/// a legitimate ROI under a fill rule. The path keeps the given order, so its orientation (and
/// thus its meaning under FillRule::Positive/Negative) is the caller's choice.
/// @param ids at least 3 ids, each at most once. @throws InvalidInputError otherwise.
/// @return fails when a listed id is missing or detected more than once.
RoiResult polygonThroughTags(const std::vector<Detection>& detections, const std::vector<int>& ids,
                             TagAnchor anchor = TagAnchor::Centre);
/// As above with one anchor per id (`anchors.size() == ids.size()`), e.g. the outer corner of
/// each tag. @throws InvalidInputError when the sizes differ.
RoiResult polygonThroughTags(const std::vector<Detection>& detections, const std::vector<int>& ids,
                             const std::vector<TagAnchor>& anchors);

/// Convex hull of the 4 corners of every detected tag in `ids` (all detections when `ids` is
/// empty). The hull is oriented like an outer contour: negative shoelace sum.
/// @return fails when a listed id is missing or detected twice, or (ids empty) nothing was
///         detected.
RoiResult convexHullOfTags(const std::vector<Detection>& detections,
                           const std::vector<int>& ids = {});

/// A polygon given in one tag's own frame (see Detection::homography: origin at the tag centre,
/// x right and y down for an upright tag, unit = black-border side), mapped into the image.
/// E.g. the area 2 tag-widths to the right of tag 5: {{{0.5,-0.5},{2.5,-0.5},{2.5,0.5},{0.5,0.5}}}.
/// Orientation is kept (a tag homography never mirrors).
/// @return fails when the tag is missing or detected twice.
/// @throws InvalidInputError if the polygon reaches the tag plane's horizon.
RoiResult tagFrameRoi(const std::vector<Detection>& detections, int id, const Paths& tagFramePaths);

/// A named ROI in a board frame.
struct BoardRoi {
  std::string name;  ///< the name `--roi board:NAME` and boardRoi() select it by
  Paths paths;       ///< board frame units
};

/// A planar board: tag corners and ROI polygons in one board frame (any unit, e.g. mm).
struct Board {
  std::string family = "tag36h11";  ///< tag family of the board's tags
  /// Corners per tag id, indexed by Corner (bottom-left, bottom-right, top-right, top-left of the
  /// upright tag), in board units.
  std::map<int, std::array<glm::dvec2, 4>> tags;
  std::vector<BoardRoi> rois;      ///< the named ROIs, in file order
  std::string units;               ///< board frame unit ("mm"); informative, empty if not given
  std::optional<glm::dvec2> size;  ///< board width and height in `units`; informative

  /// Parse a board from JSON text (format in images/README.md). `source` names the input in
  /// error messages. @throws InvalidInputError on malformed JSON, a missing field, an unknown
  /// family, or a tag id the family does not have.
  static Board fromJson(const std::string& text, const std::string& source = "board");
  /// Read and parse a board file. @throws InvalidInputError as fromJson or if unreadable.
  static Board load(const std::string& path);
  /// The board as JSON text that fromJson() reads back to an equal board: family, units and
  /// size (when set), every tag with its four corners, every ROI.
  /// @param indent spaces per indentation level, or -1 for a single line.
  [[nodiscard]] std::string toJson(int indent = 1) const;
  /// The ROI called `name`. @throws InvalidInputError naming the missing ROI.
  [[nodiscard]] const BoardRoi& roi(const std::string& name) const;
};

/// The fitted image-from-board homography.
struct BoardFit {
  glm::dmat3 imageFromBoard{1.0};  ///< maps board (x, y, 1) to image pixels (column-major GLM)
  std::vector<int> tagsUsed;       ///< board tags found in the detections
  int cornersUsed = 0;             ///< 4 per used tag
  int inliers = 0;                 ///< corners RANSAC kept (all of them for one tag)
  double rmsError = 0;             ///< reprojection RMS over the inlier corners, px
};

/// Fit image-from-board to the corners of every detected board tag (detections of other
/// families or ids are ignored): an exact fit for one tag; for more, RANSAC, then least squares
/// on the corners within `ransacThreshold` pixels of the refined model, repeated until that
/// inlier set is stable.
/// @return fails when no board tag (or a board tag more than once) was detected.
TagResult<BoardFit> fitBoard(const Board& board, const std::vector<Detection>& detections,
                             double ransacThreshold = 2.0);

/// The board ROI `roiName` (all ROIs together when empty) mapped into the image through
/// fitBoard(). Orientation is that of the board polygons when the fit does not mirror.
RoiResult boardRoi(const Board& board, const std::vector<Detection>& detections,
                   const std::string& roiName = {}, double ransacThreshold = 2.0);

/// A parsed ROI description, as a command line gives it (`--roi tags:0,1,2,3`).
struct RoiSpec {
  /// Which builder the spec calls.
  enum class Kind {
    Tags,     ///< polygonThroughTags()
    Hull,     ///< convexHullOfTags()
    Board,    ///< boardRoi()
    TagFrame  ///< tagFrameRoi()
  };
  Kind kind = Kind::Tags;  ///< the builder
  std::vector<int> ids;    ///< Tags: the order; Hull: the set (empty = all); TagFrame: 1
  /// Tags only: the anchor of each id (same length as ids).
  std::vector<TagAnchor> anchors;
  std::string roiName;  ///< Board only (empty = all of the board's ROIs)
  Paths tagFramePaths;  ///< TagFrame only
};

/// Parse one of
///   `tags:0,1,2,3`                                polygonThroughTags through the tag centres
///   `tags:22@top-left,24@top-right,25@bottom-right,23@bottom-left`   each tag's own anchor
///   `tags:0,1,2,3@top-left`                       one anchor after the last id: for every tag
///   `hull`  `hull:0,2,5`                          convexHullOfTags
///   `board`  `board:inspection`                   boardRoi (the board file is given separately)
///   `tag:5:0.5,-0.5;2.5,-0.5;2.5,0.5;0.5,0.5`     tagFrameRoi; vertices `x,y` separated by `;`,
///                                                 several paths separated by `|`
/// An id listed twice (`tags:0,0,0`, `hull:1,1`) is refused.
/// @throws InvalidInputError quoting the text and saying what is wrong.
RoiSpec parseRoiSpec(const std::string& text);

/// Build the ROI a spec describes from one image's detections.
/// @param board required for RoiSpec::Kind::Board (InvalidInputError when null).
RoiResult buildRoi(const RoiSpec& spec, const std::vector<Detection>& detections,
                   const Board* board = nullptr);

}  // namespace roiclip::apriltag
