// SPDX-License-Identifier: MIT
// roiclip::batch: the per-image pipeline behind `roiclip run` (tags -> ROI -> contours -> exact
// clip -> mask check), as a library function.
//
// Pixel convention as everywhere in roiclip: x right, y down, (0,0) is the centre of the top-left
// pixel. Clipped rings follow cv::findContours: outer rings have a negative shoelace sum, holes a
// positive one.
//
//   roiclip::batch::RunOptions options;               // hull of all tags, Otsu, even-odd
//   options.rois = {"board:inspection"};
//   options.boardFile = "images/board.json";
//   const roiclip::batch::ImageResult r = roiclip::batch::processImage(cv::imread(f), options);
//   if (r.status == roiclip::batch::Status::Ok) use(r.clipped, r.clippedArea);
//   else std::cerr << r.reason << '\n';
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>  // cv::Mat in and out

#include <roiclip/apriltag/detector.hpp>
#include <roiclip/apriltag/roi.hpp>
#include <roiclip/batch/options.hpp>
#include <roiclip/opencv/mask_check.hpp>
#include <roiclip/roiclip.hpp>

namespace roiclip::batch {

/// One clipped contour: an outer contour from cv::findContours with its holes (RETR_CCOMP).
struct ContourResult {
  int contourIndex = -1;   ///< index of the outer contour in cv::findContours' output
  Paths input;             ///< outer ring + holes, oriented like roiclip output
  double inputArea = 0;    ///< area of `input` under the subject fill rule (px^2)
  PolygonSet clipped;      ///< input AND ROI
  double clippedArea = 0;  ///< area of `clipped` (px^2)
  /// Indices into ImageResult::rois of the named ROIs this contour has a part inside.
  std::vector<int> rois;
};

/// One named ROI of the run: each spec of RunOptions::rois ("board" alone gives one per board
/// ROI). The image's region is the union of all of them, minus the tag quads.
struct RoiRegion {
  std::string name;     ///< the board ROI's name, or the spec as given ("hull", "tags:0,1,2,3")
  Paths paths;          ///< as built from the tags (may self-intersect; read with roiFillRule)
  Paths region;         ///< this ROI minus the excluded tag quads: simple rings, read with EvenOdd
  double area = 0;      ///< area of `region`, px^2
  int contoursOut = 0;  ///< contours with a part inside `region`
  double clippedArea = 0;  ///< area of the contours' parts inside `region`
};

/// Seconds spent in each stage of one image, in pipeline order. Processor::process() fills
/// detect to check; processFile() also `read`; `roiclip run` (batch::run) also overlay and write.
/// The stages cover the whole image: total is their sum but for a little glue (checks, moves).
struct StageTimes {
  double read = 0;      ///< reading and decoding the image file
  double detect = 0;    ///< conversion to 8-bit gray and AprilTag detection
  double roi = 0;       ///< building the region from the tags
  double contours = 0;  ///< cv::findContours and friends
  double clip = 0;      ///< exact clipping of every contour (and the Canny edges)
  double check = 0;     ///< the mask check
  double overlay = 0;   ///< rendering and PNG-encoding NAME.overlay.png and NAME.mask.png
  double write = 0;     ///< writing the output files
  double total = 0;     ///< the whole image, from the first stage to the last
};

/// Everything processImage() found; filled as far as the pipeline got.
struct ImageResult {
  Status status = Status::Failed;               ///< the image's outcome
  FailureKind failure = FailureKind::Internal;  ///< why it is not Ok (None when it is)
  std::string reason;                           ///< empty when Ok; one line otherwise
  int width = 0;                                ///< image width, px (0 when not read)
  int height = 0;                               ///< image height, px
  std::vector<apriltag::Detection> tags;        ///< accepted detections, sorted by id
  /// Detections dropped as doubtful (DetectorOptions::maxHamming, minDecisionMargin).
  std::vector<apriltag::Detection> rejectedTags;
  float quadDecimate = 1.0f;  ///< the AprilTag decimation that found `tags`
  int detectPasses = 0;       ///< AprilTag passes run (automatic decimation: coarse to fine)
  std::optional<apriltag::MissingTags> missingTags;  ///< set when the ROI builder failed
  std::vector<RoiRegion> rois;  ///< every named ROI (one unless several specs or a whole board)
  /// The tag quads taken out of the region (each grown by RunOptions::tagMargin); empty with
  /// RunOptions::keepTags.
  Paths excludedTags;
  /// The region every contour is clipped against: the union of `rois` minus `excludedTags`, as
  /// simple rings read with FillRule::EvenOdd.
  Paths roi;
  double roiArea = 0;                   ///< area of roi, px^2
  std::vector<ContourResult> contours;  ///< every contour kept (after minArea), clipped
  int contoursIn = 0;                   ///< outer contours detected and kept (with an area)
  /// Outer contours detected (after minArea) without an area: a lone pixel or a 1 px wide
  /// straight line gives cv::findContours 1 or 2 points, and --approx can flatten small contours
  /// onto a line. They contribute nothing, so they are counted here and not kept in `contours`.
  int contoursDegenerate = 0;
  int contoursOut = 0;     ///< of those, how many have a non-empty part inside the ROI
  int holesIn = 0;         ///< holes of the kept contours
  PolygonSet clipped;      ///< all contours together AND ROI (one clip; the mask
                           ///< check checks it; polygon parents link across contours)
  double clippedArea = 0;  ///< area of `clipped`, px^2
  /// Sum of the per-contour clipped areas; equals clippedArea (contours never overlap) up to
  /// rounding of output vertices; kept as a consistency figure.
  double contourClippedAreaSum = 0;
  /// With ContourOptions::openEdges: the parts of the Canny edge polylines inside the ROI
  /// (ROI read under roiFillRule), and their total length in px.
  std::vector<Path> edges;
  double edgeLength = 0;                                 ///< total length of `edges`, px
  int edgesIn = 0;                                       ///< polylines traced before clipping
  opencv::MaskComparison vectorVsRaster;                 ///< exact raster route
  std::optional<opencv::MaskComparison> vectorVsOpenCv;  ///< cv::fillPoly route (even-odd only)
  StageTimes seconds;                                    ///< time spent in each stage

  /// Off-band mismatching pixels over all comparisons made.
  [[nodiscard]] std::int64_t offBandMismatches() const;
};

/// A prepared pipeline: the tag detector and the board file are set up once and reused for
/// many images. Not thread-safe; give each thread its own Processor.
class Processor {
 public:
  /// @throws InvalidInputError for a bad ROI spec, an unreadable board file, a board spec without
  ///         a board file, or bad detector options.
  explicit Processor(RunOptions options);
  ~Processor();
  Processor(Processor&&) noexcept;             ///< a moved-from Processor may only be destroyed
  Processor& operator=(Processor&&) noexcept;  ///< as the move constructor

  /// Run the pipeline on one image (any type opencv::toGray8 accepts; the overlay uses it as is).
  /// Never throws for per-image problems: an empty, unsupported or too large image gives
  /// Status::Failed, missing tags Status::NoRoi, each with a reason; only std::bad_alloc
  /// propagates.
  [[nodiscard]] ImageResult process(const cv::Mat& image) const;

  /// Read an image file as `roiclip run` does (its header checked against
  /// RunOptions::maxPixels before decoding; see docs/outputs.md) and process it. A file that
  /// cannot be read gives Status::Failed with FailureKind::Unreadable or TooLarge and a reason
  /// naming the file; seconds.read is the time spent reading and decoding.
  /// @param file the image file.
  /// @param image receives the decoded image (empty when unreadable), e.g. for renderOverlay().
  [[nodiscard]] ImageResult processFile(const std::string& file, cv::Mat* image = nullptr) const;

  /// The options this Processor was made with.
  [[nodiscard]] const RunOptions& options() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// One-shot convenience: Processor(options).process(image). Options problems (bad ROI spec,
/// unreadable board file) are reported as Status::Failed with FailureKind::InvalidInput.
ImageResult processImage(const cv::Mat& image, const RunOptions& options);

/// The version of the layout of every output JSON (NAME.json, summary.json, the COCO file), in
/// their "schema_version" member (docs/outputs.md). Version 1 was the layout before roiclip 0.2,
/// which had no such member.
constexpr int kSchemaVersion = 2;

/// The roiclip version that wrote an output ("0.1.0"); every output JSON carries it.
const char* roiclipVersion();

/// One image's record as NAME.json holds it (docs/outputs.md): status, reason, size, tags,
/// ROIs, the clipped polygons as a GeoJSON FeatureCollection in pixel coordinates, every figure
/// and the stage times, as one line of JSON text. `imageName` is stored as "image" (the path
/// relative to the run's input folder in `roiclip run`), `optionsKey` (when not empty) as
/// "options" (see optionsKey()), `frame` (a video frame's index, when >= 0) as "frame".
std::string resultToJson(const ImageResult& result, const std::string& imageName = {},
                         const std::string& optionsKey = {}, int frame = -1);

/// The overlay image: the input (as BGR, 8-bit) dimmed outside the region, the region outline,
/// each named ROI (ImageResult::rois) outlined in its own colour with its name, the excluded tag
/// quads hatched in red, every clipped region filled in a translucent colour with its outline,
/// tag outlines and ids. Line widths and fonts grow with the image (an 800 px long side is the
/// reference). Above the image, in a black band of its own, the caption ("ok  tags 4  contours
/// 11 of 16 inside  area ... px2", the reason when not ok) and a legend, wrapped to the width.
/// @return `image.cols` wide and `image.rows` + the band's height tall; the image's pixels are
///         rows [band, band + image.rows), band = result.rows - image.rows. Empty for an empty
///         image.
cv::Mat renderOverlay(const cv::Mat& image, const ImageResult& result);

/// The clipped region (ImageResult::clipped) as a CV_8U mask (255 inside), exact pixel rule of
/// opencv::rasterize; the image's size (no caption band).
cv::Mat renderMask(const ImageResult& result, const Grid& grid = {});

}  // namespace roiclip::batch
