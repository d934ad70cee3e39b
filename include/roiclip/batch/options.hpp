// SPDX-License-Identifier: MIT
// roiclip::batch options and outcome codes: what `roiclip run` can be told (RunOptions, with the
// one set of defaults), how each enum is spelled in options and output files (both ways, from
// one table each), and optionsKey().
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <roiclip/apriltag/detector.hpp>
#include <roiclip/opencv/contours.hpp>
#include <roiclip/roiclip.hpp>

namespace roiclip::batch {

using opencv::ContourMethod;
using opencv::ContourOptions;
using opencv::Polarity;

/// Default pixel limit of one image (width x height): 100 megapixels, e.g. 10000 x 10000. A run
/// holds about 20 bytes per pixel of an 8-bit gray image in flight (the image, its gray copy,
/// AprilTag's buffers, the contour and mask-check masks; measured: 2560 x 1920 through the
/// whole pipeline, 195 MB peak against 103 MB for 640 x 480), so about 2 GB per image at the
/// limit, times --jobs; more for 16-bit, float or colour images.
constexpr std::int64_t kDefaultMaxPixels = 100'000'000;

/// Everything the per-image pipeline needs. Options are plain values so a config file can hold
/// them; the member initialisers are the defaults of the library and of `roiclip run`.
struct RunOptions {
  apriltag::DetectorOptions detector;  ///< AprilTag detection (family, decimation, doubtful tags)
  /// ROI specs as parsed by apriltag::parseRoiSpec: "hull" (default: convex hull of all detected
  /// tags), "hull:0,2,5", "tags:0,1,2,3[@anchor]", "board[:name]", "tag:ID:x,y;x,y;...". Each
  /// spec is one named region ("board" without a name gives one per board ROI); the image's
  /// region is their union. At least one.
  std::vector<std::string> rois = {"hull"};
  /// Board JSON for "board" specs (apriltag::Board::load format).
  std::string boardFile;
  /// The tags are not objects: by default the region is the ROI minus every detected tag's quad
  /// (its black border), each grown outwards by tagMargin px (>= 0) to take in the white margin
  /// and blur. keepTags keeps the tags in the region (the behaviour before 0.2).
  double tagMargin = 0.0;
  bool keepTags = false;    ///< keep the tags in the region (see tagMargin)
  ContourOptions contours;  ///< how contours are found (method, polarity, minimum area, ...)
  FillRule subjectFillRule = FillRule::EvenOdd;  ///< for the contours (as cv::fillPoly draws)
  FillRule roiFillRule = FillRule::EvenOdd;      ///< for the ROI paths
  /// The core's coordinate grid for every clip of the image: the library's default, fitted to
  /// each call (pixel contours are exact on it, tag corners move by ~2^-31 of the extent), so
  /// that code calling the library with its defaults gets the areas `roiclip run` reports. The
  /// mask check rasterises at opencv::kRasterGrid (1/256 px) whatever this is, and compares off
  /// a boundary band; a fixed grid (Grid::fixed()) gives identical snapping across calls.
  Grid grid{};
  /// The work budget of each clip of the image (the clips run one after another, so this bounds
  /// the memory of the image): 25,000,000 crossings by default (--max-crossings); an image over it
  /// fails with its reason. Not part of optionsKey(), like maxPixels.
  Limits limits{Limits::kToolMaxCrossings};
  /// Images with more pixels (width x height) are refused (FailureKind::TooLarge); run() checks
  /// the file's header before decoding. <= 0: no limit. Not part of optionsKey(): it guards
  /// decoding and changes no result, so up-to-date outputs stay up to date.
  std::int64_t maxPixels = kDefaultMaxPixels;
};

/// Every option that changes the pipeline's result, as one line of text. A run stores it in
/// NAME.json and only skips an image when it matches, so changing an option reprocesses.
std::string optionsKey(const RunOptions& options);

/// Parse "otsu", "adaptive", "canny" or "threshold:T" (T in 0..255) into options.method (and
/// options.threshold). @throws InvalidInputError quoting the text.
void parseContourMethod(const std::string& text, ContourOptions& options);
/// "otsu", "adaptive", "canny", "threshold" (without the threshold value).
const char* toString(ContourMethod method);
/// Parse "dark" or "light". @throws InvalidInputError quoting the text.
Polarity parsePolarity(const std::string& text);
/// "dark", "light".
const char* toString(Polarity polarity);

/// Outcome of one image.
enum class Status {
  Ok,            ///< processed and the mask check agrees off its band
  NoRoi,         ///< the ROI could not be built (no tags, a required id missing or duplicated)
  Failed,        ///< unreadable or unsupported image, bad options, or an error while processing
  MaskMismatch,  ///< processed, but the vector result and the raster route disagree off the band
};
/// "ok", "no-roi", "failed", "mask-mismatch".
const char* toString(Status status);
/// The inverse of toString(Status); nothing for any other text.
std::optional<Status> parseStatus(std::string_view text);

/// Why an image did not reach Status::Ok.
enum class FailureKind {
  None,
  Unreadable,  ///< missing, empty, not an image, truncated or corrupt file
  TooLarge,    ///< more pixels than RunOptions::maxPixels (refused before decoding)
  NoTags,
  MissingTags,
  InvalidInput,  ///< an image type the pipeline cannot use, bad options, out-of-range input
  Internal,
  Mismatch,
};
/// "none", "unreadable", "too-large", "no-tags", "missing-tags", "invalid-input", "internal",
/// "mismatch".
const char* toString(FailureKind kind);
/// The inverse of toString(FailureKind); nothing for any other text.
std::optional<FailureKind> parseFailureKind(std::string_view text);

}  // namespace roiclip::batch
