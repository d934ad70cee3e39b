// SPDX-License-Identifier: MIT
// The per-image pipeline: tags -> ROI -> contours -> exact clip -> mask check.
//
// The region: every ROI spec built from the tags and simplified under the ROI fill rule (one
// simplify each), their union when there are several (one more), minus the tag quads (one
// difference, unless tags are kept). Then per contour with N contours kept: one clip (its part
// inside the region), and one clip of all contours together (ImageResult::clipped, whose polygon
// parents link an island to the hole of another contour it lies in; concatenating the
// per-contour results would lose that), checked by the mask check without clipping again. A
// contour's input area is its shoelace sum (opencv::pixelContourArea: findContours rings never
// cross); with approxEpsilon > 0 it takes one simplify, since approxPolyDP contours may. One ROI:
// N + 3 calls (N + 2 with tags kept; 2N + 3 with approxEpsilon), plus one clipLines with
// openEdges; with R > 1 ROIs, R + 2 for the region and R more per contour inside it (per-ROI
// figures). The region (and each ROI) is prepared once per image (PreparedRegion).
#include <roiclip/batch/process.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
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

using detail::Clock;
using detail::secondsSince;

// A convex tag quad grown outwards by `margin` px: every edge moved along its normal, corners
// where the moved edges meet. Oriented like an outer ring (negative shoelace sum), so that the
// quads of overlapping tags add up under the non-zero rule.
Path grownQuad(const apriltag::Detection& tag, double margin) {
  Path quad(tag.corners.begin(), tag.corners.end());
  if (signedArea(quad) > 0) std::reverse(quad.begin(), quad.end());
  if (margin <= 0) return quad;
  const std::size_t n = quad.size();
  std::vector<glm::dvec2> normals(n);  // outward for a negative shoelace sum in x/y numbers
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec2 d = quad[(i + 1) % n] - quad[i];
    const double length = glm::length(d);
    normals[i] = length > 0 ? glm::dvec2{-d.y, d.x} / length : glm::dvec2{0, 0};
  }
  Path grown(n);
  for (std::size_t i = 0; i < n; ++i) {
    // Corner i joins edge i-1 and edge i: offset = m (n1 + n2) / (1 + n1.n2).
    const glm::dvec2 a = normals[(i + n - 1) % n];
    const glm::dvec2 b = normals[i];
    const double cosine = glm::dot(a, b);
    grown[i] = quad[i] + (cosine > -0.99 ? margin * (a + b) / (1 + cosine) : margin * b);
  }
  return grown;
}

// "board" without a name stands for every ROI of the board, each its own region.
std::vector<std::pair<std::string, apriltag::RoiSpec>> expandSpecs(
    const std::vector<std::string>& texts, const std::optional<apriltag::Board>& board) {
  std::vector<std::pair<std::string, apriltag::RoiSpec>> out;
  for (const std::string& text : texts) {
    apriltag::RoiSpec spec = apriltag::parseRoiSpec(text);
    if (spec.kind == apriltag::RoiSpec::Kind::Board && spec.roiName.empty()) {
      if (board->rois.empty()) throw InvalidInputError("board file has no ROIs");
      for (const apriltag::BoardRoi& roi : board->rois) {
        apriltag::RoiSpec one = spec;
        one.roiName = roi.name;
        out.emplace_back(roi.name, std::move(one));
      }
    } else if (spec.kind == apriltag::RoiSpec::Kind::Board) {
      (void)board->roi(spec.roiName);  // refuses an unknown name up front
      out.emplace_back(spec.roiName, std::move(spec));
    } else {
      out.emplace_back(text, std::move(spec));
    }
  }
  for (std::size_t i = 0; i < out.size(); ++i) {
    for (std::size_t k = 0; k < i; ++k) {
      if (out[i].first == out[k].first) {
        throw InvalidInputError("ROI '" + out[i].first + "' is given twice");
      }
    }
  }
  return out;
}

// Ids a spec names that no detector family has, refused before any image is read.
void checkIds(const std::pair<std::string, apriltag::RoiSpec>& spec,
              const apriltag::DetectorOptions& detector) {
  int largest = 0;
  std::size_t start = 0;
  const std::string& families = detector.family;
  while (true) {
    const std::size_t end = families.find(',', start);
    largest = std::max(largest, apriltag::familySize(families.substr(
                                    start, end == std::string::npos ? end : end - start)));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  for (int id : spec.second.ids) {
    if (id >= largest) {
      throw InvalidInputError("ROI '" + spec.first + "': tag id " + std::to_string(id) +
                              " does not exist in " + families + " (ids 0.." +
                              std::to_string(largest - 1) + ")");
    }
  }
}

std::optional<apriltag::Board> loadBoard(const RunOptions& o) {
  for (const std::string& text : o.rois) {
    if (apriltag::parseRoiSpec(text).kind != apriltag::RoiSpec::Kind::Board) continue;
    if (o.boardFile.empty()) {
      throw InvalidInputError("ROI spec '" + text + "' needs a board file (--board)");
    }
    return apriltag::Board::load(o.boardFile);
  }
  return std::nullopt;
}

// The pipeline's stages, in order; every core call goes through `calls`.
class Pipeline {
 public:
  explicit Pipeline(RunOptions o)
      : options_(std::move(o)), detector_(options_.detector), board_(loadBoard(options_)) {
    if (options_.rois.empty()) throw InvalidInputError("no ROI given");
    if (!(options_.tagMargin >= 0) || !std::isfinite(options_.tagMargin)) {
      throw InvalidInputError("tag margin must be a finite number >= 0, got " +
                              std::to_string(options_.tagMargin));
    }
    specs_ = expandSpecs(options_.rois, board_);
    for (const auto& spec : specs_) checkIds(spec, options_.detector);
    // The ids a spec cannot do without: automatic decimation looks again, finer, when one is
    // missing. A board fits any subset of its tags, so its ids are not required.
    for (const auto& [name, spec] : specs_) {
      if (spec.kind == apriltag::RoiSpec::Kind::Board) continue;
      expectedIds_.insert(expectedIds_.end(), spec.ids.begin(), spec.ids.end());
    }
    std::sort(expectedIds_.begin(), expectedIds_.end());
    expectedIds_.erase(std::unique(expectedIds_.begin(), expectedIds_.end()), expectedIds_.end());
  }

  [[nodiscard]] const RunOptions& options() const { return options_; }
  /// The grid and work budget of every clip of an image.
  [[nodiscard]] Options coreOptions() const { return {options_.grid, options_.limits}; }

  void run(const cv::Mat& image, ImageResult& r, detail::CoreCalls& calls) const {
    const auto start = Clock::now();
    checkSize(image);
    const cv::Mat gray = opencv::toGray8(image);
    r.width = gray.cols;
    r.height = gray.rows;
    r.seconds.detect = secondsSince(start);  // the gray image is the detector's input
    detectTags(gray, r);
    if (buildRoi(r, calls)) {
      const std::vector<opencv::ContourGroup> groups = findContours(gray, r);
      const PreparedRegion roi(r.roi, FillRule::EvenOdd, coreOptions());  // once per image
      const Paths all = clipContours(groups, roi, r, calls);
      if (options_.contours.openEdges) clipEdges(gray, roi, r, calls);
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
    apriltag::DetectionReport found = detector_.detectReport(gray, 0, expectedIds_);
    r.tags = std::move(found.tags);
    r.rejectedTags = std::move(found.rejected);
    r.quadDecimate = found.quadDecimate;
    r.detectPasses = found.passes;
    r.seconds.detect += secondsSince(t);
  }

  // False (Status::NoRoi) when the tags a spec needs are not there.
  bool buildRoi(ImageResult& r, detail::CoreCalls& calls) const {
    const auto t = Clock::now();
    r.rois.clear();
    r.excludedTags.clear();
    r.missingTags.reset();
    for (const auto& [name, spec] : specs_) {
      const apriltag::RoiResult roi = apriltag::buildRoi(spec, r.tags, board_ ? &*board_ : nullptr);
      if (!roi) {
        r.status = Status::NoRoi;
        r.missingTags = roi.missing();
        if (r.tags.empty()) {
          r.failure = FailureKind::NoTags;
          r.reason = "no " + options_.detector.family + " tags detected";
          if (!r.rejectedTags.empty()) {
            r.reason += " (" + std::to_string(r.rejectedTags.size()) +
                        " doubtful detections rejected: --max-hamming, --min-margin)";
          }
        } else {
          r.failure = FailureKind::MissingTags;
          r.reason = "ROI '" + name + "': " + roi.missing().describe();
        }
        r.rois.clear();
        r.seconds.roi = secondsSince(t);
        return false;
      }
      RoiRegion region;
      region.name = name;
      region.paths = roi.value();
      ++calls.simplify;
      const PolygonSet simple = simplify(region.paths, options_.roiFillRule, coreOptions());
      region.region = simple.toPaths();
      region.area = simple.area();
      r.rois.push_back(std::move(region));
    }
    Paths all = r.rois[0].region;
    double allArea = r.rois[0].area;
    if (r.rois.size() > 1) {  // the union: simple rings of one orientation add up
      for (std::size_t i = 1; i < r.rois.size(); ++i) {
        all.insert(all.end(), r.rois[i].region.begin(), r.rois[i].region.end());
      }
      ++calls.simplify;
      const PolygonSet united = simplify(all, FillRule::NonZero, coreOptions());
      all = united.toPaths();
      allArea = united.area();
    }
    if (!options_.keepTags) {
      for (const apriltag::Detection& tag : r.tags) {
        r.excludedTags.push_back(grownQuad(tag, options_.tagMargin));
      }
    }
    if (!r.excludedTags.empty()) {
      const auto minusTags = [&](const Paths& region) {
        ++calls.clip;
        return clip(ClipOp::Difference, region, r.excludedTags, FillRule::EvenOdd,
                    FillRule::NonZero, coreOptions());
      };
      const PolygonSet region = minusTags(all);
      r.roi = region.toPaths();
      r.roiArea = region.area();
      if (r.rois.size() == 1) {
        r.rois[0].region = r.roi;
        r.rois[0].area = r.roiArea;
      } else {
        for (RoiRegion& one : r.rois) {
          const PolygonSet part = minusTags(one.region);
          one.region = part.toPaths();
          one.area = part.area();
        }
      }
    } else {
      r.roi = std::move(all);
      r.roiArea = allArea;
    }
    r.seconds.roi = secondsSince(t);
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
  Paths clipContours(const std::vector<opencv::ContourGroup>& groups, const PreparedRegion& roi,
                     ImageResult& r, detail::CoreCalls& calls) const {
    const auto t = Clock::now();
    const FillRule rule = options_.subjectFillRule;
    Paths all;
    r.contours.reserve(groups.size());
    std::vector<PreparedRegion> perRoi;  // with several ROIs, each prepared once
    if (r.rois.size() > 1) {
      perRoi.reserve(r.rois.size());
      for (const RoiRegion& one : r.rois)
        perRoi.emplace_back(one.region, FillRule::EvenOdd, coreOptions());
    }
    for (const opencv::ContourGroup& group : groups) {
      ContourResult c;
      c.contourIndex = group.index;
      c.input = group.rings;
      if (options_.contours.approxEpsilon > 0) {  // approxPolyDP output may cross itself
        ++calls.simplify;
        c.inputArea = simplify(c.input, rule, coreOptions()).area();
      } else {
        c.inputArea = opencv::pixelContourArea(group);
      }
      // No area (a lone pixel, a 1 px wide straight line, a contour --approx flattens): it
      // contributes nothing to any clip, so it is counted, not kept as an object.
      if (c.inputArea == 0) {
        ++r.contoursDegenerate;
        continue;
      }
      ++calls.clip;
      c.clipped = roi.intersect(c.input, rule);
      c.clippedArea = c.clipped.area();
      if (r.rois.size() > 1 && !c.clipped.empty()) {
        const Paths inside = c.clipped.toPaths();
        for (std::size_t i = 0; i < r.rois.size(); ++i) {
          RoiRegion& one = r.rois[i];
          ++calls.clip;
          const double area = perRoi[i].intersect(inside, FillRule::EvenOdd).area();
          if (area > 0) {
            ++one.contoursOut;
            c.rois.push_back(static_cast<int>(i));
          }
          one.clippedArea += area;
        }
      } else if (!c.clipped.empty()) {
        c.rois = {0};
      }
      r.holesIn += static_cast<int>(c.input.size()) - 1;
      if (!c.clipped.empty()) ++r.contoursOut;
      r.contourClippedAreaSum += c.clippedArea;
      all.insert(all.end(), c.input.begin(), c.input.end());
      r.contours.push_back(std::move(c));
    }
    r.contoursIn = static_cast<int>(r.contours.size());
    ++calls.clip;
    r.clipped = roi.intersect(all, rule);
    r.clippedArea = r.clipped.area();
    if (r.rois.size() == 1) {
      r.rois[0].contoursOut = r.contoursOut;
      r.rois[0].clippedArea = r.clippedArea;
    }
    r.seconds.clip = secondsSince(t);
    return all;
  }

  void clipEdges(const cv::Mat& gray, const PreparedRegion& roi, ImageResult& r,
                 detail::CoreCalls& calls) const {
    const auto t = Clock::now();
    const opencv::ContourOptions& c = options_.contours;
    cv::Mat edgeImage;
    cv::Canny(gray, edgeImage, c.cannyLow, c.cannyHigh);
    Paths lines = opencv::traceEdges(edgeImage);
    if (c.approxEpsilon > 0) opencv::approximatePolylines(lines, c.approxEpsilon);
    r.edgesIn = static_cast<int>(lines.size());
    ++calls.clipLines;
    r.edges = roi.clipLines(lines, LinePart::Inside);
    r.edgeLength = opencv::polylineLength(r.edges);
    r.seconds.clip += secondsSince(t);
  }

  void checkMasks(const Paths& subject, ImageResult& r) const {
    const auto t = Clock::now();
    opencv::MaskCheckOptions checkOptions;
    checkOptions.grid = options_.grid;
    const opencv::MaskCheck check =
        opencv::checkRoiClip(subject, r.roi, r.clipped, options_.subjectFillRule, FillRule::EvenOdd,
                             cv::Size(r.width, r.height), checkOptions);
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
  std::optional<apriltag::Board> board_;
  std::vector<std::pair<std::string, apriltag::RoiSpec>> specs_;  // name, spec
  std::vector<int> expectedIds_;  // ids the specs need, sorted (detectTags)
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
  } catch (const ResourceLimitError& e) {  // ProcessOptions::limits
    r.failure = FailureKind::TooLarge;
    r.reason = std::string("clipping: ") + e.what() + " (--max-crossings)";
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

// readImage() with its problems turned into Status::Failed.
cv::Mat readCaught(const std::string& file, std::int64_t maxPixels, ImageResult& r) {
  try {
    return readImage(file, maxPixels);
  } catch (const ImageTooLargeError& e) {
    r.failure = FailureKind::TooLarge;
    r.reason = e.what();
  } catch (const InvalidInputError& e) {
    r.failure = FailureKind::Unreadable;
    r.reason = e.what();
  }
  r.status = Status::Failed;
  return {};
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

ImageResult Processor::processFile(const std::string& file, cv::Mat* image) const {
  const auto start = Clock::now();
  ImageResult r;
  const cv::Mat decoded = readCaught(file, options().maxPixels, r);
  const double read = secondsSince(start);
  if (!decoded.empty()) r = process(decoded);
  r.seconds.read = read;
  r.seconds.total = secondsSince(start);
  if (image) *image = decoded;
  return r;
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
