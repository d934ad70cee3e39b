// The per-image pipeline: tags -> ROI -> contours -> exact clip -> mask check.
//
// Core calls per image with N contours kept: one simplify of the ROI (its area), per contour
// one simplify (its input area under the fill rule, which self-intersecting approxPolyDP
// contours need) and one clip (its part inside the ROI), and one clip of all contours together
// (ImageResult::clipped, whose polygon parents link an island to the hole of another contour it
// lies in; concatenating the per-contour results would lose that), checked by the mask check
// without clipping again: 2N + 2, plus one clipLines with openEdges.
#include <roiclip/batch/process.hpp>

#include <chrono>
#include <cstdint>
#include <new>
#include <utility>

#include <opencv2/imgproc.hpp>

#include <roiclip/opencv/contours.hpp>
#include <roiclip/opencv/edges.hpp>

#include "detail/image_file.hpp"
#include "detail/process.hpp"

namespace roiclip::batch {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The pipeline's stages, in order; every core call goes through `calls`.
class Pipeline {
 public:
  explicit Pipeline(RunOptions o)
      : options_(std::move(o)),
        detector_(options_.detector),
        spec_(apriltag::parseRoiSpec(options_.roi)) {
    if (spec_.kind == apriltag::RoiSpec::Kind::Board) {
      if (options_.boardFile.empty()) {
        throw InvalidInputError("ROI spec '" + options_.roi + "' needs a board file (--board)");
      }
      board_ = apriltag::Board::load(options_.boardFile);
    }
  }

  [[nodiscard]] const RunOptions& options() const { return options_; }

  void run(const cv::Mat& image, ImageResult& r, detail::CoreCalls& calls) const {
    const auto start = Clock::now();
    checkSize(image);
    const cv::Mat gray = opencv::toGray8(image);
    r.width = gray.cols;
    r.height = gray.rows;
    detectTags(gray, r);
    if (buildRoi(r, calls)) {
      const std::vector<opencv::ContourGroup> groups = findContours(gray, r);
      const Paths all = clipContours(groups, r, calls);
      if (options_.contours.openEdges) clipEdges(gray, r, calls);
      checkMasks(all, r);
    }
    r.seconds.total = secondsSince(start);
  }

 private:
  void checkSize(const cv::Mat& image) const {
    const auto pixels = static_cast<std::int64_t>(image.total());
    if (options_.maxPixels > 0 && pixels > options_.maxPixels) {
      throw ImageTooLargeError("image " + std::to_string(image.cols) + " x " +
                               std::to_string(image.rows) + " = " + std::to_string(pixels) +
                               " pixels, more than the limit of " +
                               std::to_string(options_.maxPixels));
    }
  }

  void detectTags(const cv::Mat& gray, ImageResult& r) const {
    const auto t = Clock::now();
    r.tags = detector_.detect(gray);
    r.seconds.detect = secondsSince(t);
  }

  // False (Status::NoRoi) when the tags the spec needs are not there.
  bool buildRoi(ImageResult& r, detail::CoreCalls& calls) const {
    const auto t = Clock::now();
    const apriltag::RoiResult roi = apriltag::buildRoi(spec_, r.tags, board_ ? &*board_ : nullptr);
    r.seconds.roi = secondsSince(t);
    if (!roi) {
      r.status = Status::NoRoi;
      r.missingTags = roi.missing();
      if (r.tags.empty()) {
        r.failure = FailureKind::NoTags;
        r.reason = "no " + options_.detector.family + " tags detected";
      } else {
        r.failure = FailureKind::MissingTags;
        r.reason = "ROI '" + options_.roi + "': " + roi.missing().describe();
      }
      return false;
    }
    r.roi = roi.value();
    ++calls.simplify;
    r.roiArea = simplify(r.roi, options_.roiFillRule, options_.grid).area();
    return true;
  }

  std::vector<opencv::ContourGroup> findContours(const cv::Mat& gray, ImageResult& r) const {
    const auto t = Clock::now();
    std::vector<opencv::ContourGroup> groups = opencv::detectContours(gray, options_.contours);
    r.seconds.contours = secondsSince(t);
    return groups;
  }

  // Each contour alone, then all together. Returns all contours' rings (the mask check's
  // subject).
  Paths clipContours(const std::vector<opencv::ContourGroup>& groups, ImageResult& r,
                     detail::CoreCalls& calls) const {
    const auto t = Clock::now();
    const FillRule rule = options_.subjectFillRule;
    Paths all;
    r.contours.reserve(groups.size());
    for (const opencv::ContourGroup& group : groups) {
      ContourResult c;
      c.contourIndex = group.index;
      c.input = group.rings;
      ++calls.simplify;
      c.inputArea = simplify(c.input, rule, options_.grid).area();
      ++calls.clip;
      c.clipped =
          clip(ClipOp::Intersection, c.input, r.roi, rule, options_.roiFillRule, options_.grid);
      c.clippedArea = c.clipped.area();
      r.holesIn += static_cast<int>(c.input.size()) - 1;
      if (!c.clipped.empty()) ++r.contoursOut;
      r.contourClippedAreaSum += c.clippedArea;
      all.insert(all.end(), c.input.begin(), c.input.end());
      r.contours.push_back(std::move(c));
    }
    r.contoursIn = static_cast<int>(r.contours.size());
    ++calls.clip;
    r.clipped = clip(ClipOp::Intersection, all, r.roi, rule, options_.roiFillRule, options_.grid);
    r.clippedArea = r.clipped.area();
    r.seconds.clip = secondsSince(t);
    return all;
  }

  void clipEdges(const cv::Mat& gray, ImageResult& r, detail::CoreCalls& calls) const {
    const auto t = Clock::now();
    const opencv::ContourOptions& c = options_.contours;
    cv::Mat edgeImage;
    cv::Canny(gray, edgeImage, c.cannyLow, c.cannyHigh);
    Paths lines = opencv::traceEdges(edgeImage);
    if (c.approxEpsilon > 0) opencv::approximatePolylines(lines, c.approxEpsilon);
    r.edgesIn = static_cast<int>(lines.size());
    ++calls.clipLines;
    r.edges = clipLines(lines, r.roi, options_.roiFillRule, LinePart::Inside, options_.grid);
    r.edgeLength = opencv::polylineLength(r.edges);
    r.seconds.clip += secondsSince(t);
  }

  void checkMasks(const Paths& subject, ImageResult& r) const {
    const auto t = Clock::now();
    opencv::MaskCheckOptions checkOptions;
    checkOptions.grid = options_.grid;
    const opencv::MaskCheck check =
        opencv::checkRoiClip(subject, r.roi, r.clipped, options_.subjectFillRule,
                             options_.roiFillRule, cv::Size(r.width, r.height), checkOptions);
    r.seconds.check = secondsSince(t);
    r.vectorVsRaster = check.vectorVsRaster;
    r.vectorVsOpenCv = check.vectorVsOpenCv;
    if (check.ok()) {
      r.status = Status::Ok;
      r.failure = FailureKind::None;
    } else {
      r.status = Status::MaskMismatch;
      r.failure = FailureKind::Mismatch;
      r.reason = "mask check: " + std::to_string(r.offBandMismatches()) +
                 " pixels disagree off the boundary band";
    }
  }

  RunOptions options_;
  apriltag::Detector detector_;
  apriltag::RoiSpec spec_;
  std::optional<apriltag::Board> board_;
};

// Pipeline::run with per-image problems turned into Status::Failed.
ImageResult runCaught(const Pipeline& pipeline, const cv::Mat& image, detail::CoreCalls& calls) {
  ImageResult r;
  const auto start = Clock::now();
  try {
    pipeline.run(image, r, calls);
    return r;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const ImageTooLargeError& e) {
    r.failure = FailureKind::TooLarge;
    r.reason = e.what();
  } catch (const InvalidInputError& e) {
    r.failure = FailureKind::InvalidInput;
    r.reason = e.what();
  } catch (const cv::Exception& e) {
    r.failure = FailureKind::Internal;
    r.reason = std::string("OpenCV: ") + e.what();
  } catch (const std::exception& e) {
    r.failure = FailureKind::Internal;
    r.reason = e.what();
  }
  r.status = Status::Failed;
  r.seconds.total = secondsSince(start);
  return r;
}

ImageResult optionsFailure(const Error& e) {
  ImageResult r;
  r.status = Status::Failed;
  r.failure = FailureKind::InvalidInput;
  r.reason = e.what();
  return r;
}

}  // namespace

std::int64_t ImageResult::offBandMismatches() const {
  std::int64_t n = vectorVsRaster.offBandOnlyExpected + vectorVsRaster.offBandOnlyActual;
  if (vectorVsOpenCv) n += vectorVsOpenCv->offBandOnlyExpected + vectorVsOpenCv->offBandOnlyActual;
  return n;
}

struct Processor::Impl {
  Pipeline pipeline;
};

Processor::Processor(RunOptions options)
    : impl_(std::make_unique<Impl>(Impl{Pipeline(std::move(options))})) {}
Processor::~Processor() = default;
Processor::Processor(Processor&&) noexcept = default;
Processor& Processor::operator=(Processor&&) noexcept = default;

const RunOptions& Processor::options() const { return impl_->pipeline.options(); }

ImageResult Processor::process(const cv::Mat& image) const {
  detail::CoreCalls calls;
  return runCaught(impl_->pipeline, image, calls);
}

ImageResult processImage(const cv::Mat& image, const RunOptions& options) {
  std::optional<Processor> processor;
  try {
    processor.emplace(options);
  } catch (const Error& e) {
    return optionsFailure(e);
  }
  return processor->process(image);
}

namespace detail {

ImageResult processCountingCoreCalls(const cv::Mat& image, const RunOptions& options,
                                     CoreCalls& calls) {
  std::optional<Pipeline> pipeline;
  try {
    pipeline.emplace(options);
  } catch (const Error& e) {
    return optionsFailure(e);
  }
  return runCaught(*pipeline, image, calls);
}

}  // namespace detail

}  // namespace roiclip::batch
