// roiclip::batch: the per-image pipeline behind `roiclip run` (tags -> ROI -> contours -> exact
// clip -> mask check), as a library function.
//
// Pixel convention as everywhere in roiclip: x right, y down, (0,0) is the centre of the top-left
// pixel. Clipped rings follow cv::findContours: outer rings have a negative shoelace sum, holes a
// positive one.
//
//   roiclip::batch::RunOptions options;               // hull of all tags, Otsu, even-odd
//   options.roi = "board:inspection";
//   options.boardFile = "images/board.json";
//   const roiclip::batch::ImageResult r = roiclip::batch::processImage(cv::imread(f), options);
//   if (r.status == roiclip::batch::Status::Ok) use(r.clipped, r.clippedArea);
//   else std::cerr << r.reason << '\n';
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include <roiclip/apriltag/detector.hpp>
#include <roiclip/apriltag/roi.hpp>
#include <roiclip/batch/image_file.hpp>
#include <roiclip/opencv/mask_check.hpp>
#include <roiclip/roiclip.hpp>

namespace roiclip::batch {

/// How the subject mask for cv::findContours is made from the gray image.
enum class ContourMethod {
  Otsu,       ///< global threshold chosen by Otsu's method (default)
  Adaptive,   ///< cv::adaptiveThreshold (Gaussian), block `adaptiveBlock`, offset `adaptiveC`
  Canny,      ///< cv::Canny edges (`cannyLow`, `cannyHigh`); every edge pixel is a region
  Threshold,  ///< fixed threshold `threshold`
};

/// Which pixels are objects: dark ones on a light background (default) or light on dark.
enum class Polarity { Dark, Light };

/// Contour detection settings.
struct ContourOptions {
  ContourMethod method = ContourMethod::Otsu;
  Polarity polarity = Polarity::Dark;
  int threshold = 128;     ///< ContourMethod::Threshold: objects are <= threshold (Dark) or > it
  int adaptiveBlock = 51;  ///< odd, >= 3
  double adaptiveC = 10.0;
  double cannyLow = 50.0;
  double cannyHigh = 150.0;
  /// cv::approxPolyDP epsilon in px applied to every contour (0 = off). approxPolyDP may make
  /// contours self-intersect; the core resolves them under the fill rule.
  double approxEpsilon = 0.0;
  /// Outer contours whose |cv::contourArea| is below this (px^2) are dropped with their holes.
  double minArea = 0.0;
  /// Also trace the Canny edges (cannyLow, cannyHigh) as open polylines and clip them to the ROI
  /// (ImageResult::edges). Independent of `method`.
  bool openEdges = false;
};

/// Parse "otsu", "adaptive", "canny" or "threshold:T" (T in 0..255) into options.method (and
/// options.threshold). @throws InvalidInputError quoting the text.
void parseContourMethod(const std::string& text, ContourOptions& options);
/// Parse "dark" or "light". @throws InvalidInputError quoting the text.
Polarity parsePolarity(const std::string& text);

/// Everything processImage() needs. Options are plain values so a config file can hold them.
struct RunOptions {
  apriltag::DetectorOptions detector;
  /// ROI spec as parsed by apriltag::parseRoiSpec: "hull" (default: convex hull of all detected
  /// tags), "hull:0,2,5", "tags:0,1,2,3[@anchor]", "board[:name]", "tag:ID:x,y;x,y;...".
  std::string roi = "hull";
  /// Board JSON for "board" specs (apriltag::Board::load format).
  std::string boardFile;
  ContourOptions contours;
  FillRule subjectFillRule = FillRule::EvenOdd;  ///< for the contours (as cv::fillPoly draws)
  FillRule roiFillRule = FillRule::EvenOdd;      ///< for the ROI paths
  Grid grid{};
  /// Images with more pixels (width x height) are refused (FailureKind::TooLarge); run() checks
  /// the file's header before decoding (readImage). <= 0: no limit. Not part of optionsKey():
  /// it guards decoding and changes no result, so up-to-date outputs stay up to date.
  std::int64_t maxPixels = kDefaultMaxPixels;
};

/// Outcome of one image.
enum class Status {
  Ok,            ///< processed and the mask check agrees off its band
  NoRoi,         ///< the ROI could not be built (no tags, a required id missing or duplicated)
  Failed,        ///< unreadable or unsupported image, bad options, or an error while processing
  MaskMismatch,  ///< processed, but the vector result and the raster route disagree off the band
};
/// "ok", "no-roi", "failed", "mask-mismatch".
const char* toString(Status status);

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

/// One clipped contour: an outer contour from cv::findContours with its holes (RETR_CCOMP).
struct ContourResult {
  int contourIndex = -1;  ///< index of the outer contour in cv::findContours' output
  Paths input;            ///< outer ring + holes, oriented like roiclip output
  double inputArea = 0;   ///< area of `input` under the subject fill rule (px^2)
  PolygonSet clipped;     ///< input AND ROI
  double clippedArea = 0;
};

/// Seconds spent in each stage.
struct StageTimes {
  double detect = 0, roi = 0, contours = 0, clip = 0, check = 0, total = 0;
};

/// Everything processImage() found; filled as far as the pipeline got.
struct ImageResult {
  Status status = Status::Failed;
  FailureKind failure = FailureKind::Internal;
  std::string reason;  ///< empty when Ok; one line otherwise
  int width = 0, height = 0;
  std::vector<apriltag::Detection> tags;
  std::optional<apriltag::MissingTags> missingTags;  ///< set when the ROI builder failed
  Paths roi;                            ///< as built (may self-intersect; read with roiFillRule)
  double roiArea = 0;                   ///< area of roi under roiFillRule, px^2
  std::vector<ContourResult> contours;  ///< every contour kept (after minArea), clipped
  int contoursIn = 0;                   ///< outer contours detected and kept
  int contoursOut = 0;                  ///< of those, how many have a non-empty part inside the ROI
  int holesIn = 0;                      ///< holes of the kept contours
  PolygonSet clipped;                   ///< all contours together AND ROI (the mask check's clip)
  double clippedArea = 0;
  /// Sum of the per-contour clipped areas; equals clippedArea (contours never overlap) up to
  /// rounding of output vertices; kept as a consistency figure.
  double contourClippedAreaSum = 0;
  /// With ContourOptions::openEdges: the parts of the Canny edge polylines inside the ROI
  /// (ROI read under roiFillRule), and their total length in px.
  std::vector<Path> edges;
  double edgeLength = 0;
  int edgesIn = 0;                                       ///< polylines traced before clipping
  opencv::MaskComparison vectorVsRaster;                 ///< exact raster route
  std::optional<opencv::MaskComparison> vectorVsOpenCv;  ///< cv::fillPoly route (even-odd only)
  StageTimes seconds;

  /// Off-band mismatching pixels over all comparisons made.
  [[nodiscard]] std::int64_t offBandMismatches() const;
};

/// Convert any image cv::imread returns (8- or 16-bit, float; 1, 3 or 4 channels; 2 channels
/// are read as gray + alpha) to 8-bit gray. 16-bit is scaled by 255/65535, float by 255
/// (assumed in [0, 1]; values outside saturate, NaN becomes 0).
/// @throws InvalidInputError naming `source` if the image is empty or of an unsupported type.
cv::Mat toGray8(const cv::Mat& image, const std::string& source = "image");

/// Detect contours as `options` says (RETR_CCOMP, CHAIN_APPROX_NONE) and group each outer
/// contour with its holes, oriented (outer negative, holes positive).
/// @param gray CV_8UC1.
/// @return one Paths per kept outer contour; `indices` (optional) receives the outer contours'
///         indices in the findContours output.
std::vector<Paths> detectContours(const cv::Mat& gray, const ContourOptions& options,
                                  std::vector<int>* indices = nullptr);

/// Trace a binary edge image (non-zero = edge, CV_8UC1, e.g. cv::Canny output) into open
/// polylines through the pixel centres: 8-connected chains, each pixel used once, starting at
/// chain ends (pixels with one neighbour) and then on closed loops. A branch ends one chain and
/// starts another. Single pixels give one-point polylines.
std::vector<Path> traceEdges(const cv::Mat& edges);

/// Total length of open polylines (px).
double polylineLength(const std::vector<Path>& polylines);

/// A prepared pipeline: the tag detector and the board file are set up once and reused for
/// many images. Not thread-safe; give each thread its own Processor.
class Processor {
 public:
  /// @throws InvalidInputError for a bad ROI spec, an unreadable board file, a board spec without
  ///         a board file, or bad detector options.
  explicit Processor(RunOptions options);
  ~Processor();
  Processor(Processor&&) noexcept;
  Processor& operator=(Processor&&) noexcept;

  /// Run the pipeline on one image (any type toGray8 accepts; the overlay uses it as is).
  /// Never throws for per-image problems: an empty, unsupported or too large image gives
  /// Status::Failed, missing tags Status::NoRoi, each with a reason; only std::bad_alloc
  /// propagates.
  [[nodiscard]] ImageResult process(const cv::Mat& image) const;

  [[nodiscard]] const RunOptions& options() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// One-shot convenience: Processor(options).process(image). Options problems (bad ROI spec,
/// unreadable board file) are reported as Status::Failed with FailureKind::InvalidInput.
ImageResult processImage(const cv::Mat& image, const RunOptions& options);

/// The overlay image: the input (as BGR, 8-bit) dimmed outside the ROI, the ROI outline, every
/// clipped region filled in a translucent colour with its outline, tag outlines and ids, and a
/// one-line caption. Same size as `image`.
cv::Mat renderOverlay(const cv::Mat& image, const ImageResult& result);

/// The clipped region (ImageResult::clipped) as a CV_8U mask (255 inside), exact pixel rule of
/// opencv::rasterize.
cv::Mat renderMask(const ImageResult& result, const Grid& grid = {});

/// NAME.json text for one image: status, reason, size, tags, ROI, every clipped polygon with
/// holes (image coordinates), areas, mask-check figures, stage times. `imageName` is stored
/// as "image", `optionsKey` (when not empty) as "options" (see optionsKey()).
std::string resultToJson(const ImageResult& result, const std::string& imageName,
                         const std::string& optionsKey = {});

/// Every option that changes processImage()'s result, as one line of text. A run stores it in
/// NAME.json and only skips an image when it matches, so changing an option reprocesses.
std::string optionsKey(const RunOptions& options);

}  // namespace roiclip::batch
