// SPDX-License-Identifier: MIT
// roiclip::apriltag::Detector over libapriltag 3.3. AprilTag headers stay in this file (and the
// other .cpp files): common/math_util.h defines a `max` macro.
#include <roiclip/apriltag/detector.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <mutex>
#include <sstream>
#include <utility>

#include <opencv2/imgproc.hpp>

#include "homography.hpp"

extern "C" {
#include <apriltag/apriltag.h>
#include <apriltag/common/zarray.h>
#include <apriltag/tag16h5.h>
#include <apriltag/tag25h9.h>
#include <apriltag/tag36h10.h>
#include <apriltag/tag36h11.h>
#include <apriltag/tagCircle21h7.h>
#include <apriltag/tagCircle49h12.h>
#include <apriltag/tagCustom48h12.h>
#include <apriltag/tagStandard41h12.h>
#include <apriltag/tagStandard52h13.h>
}

namespace roiclip::apriltag {
namespace {

struct FamilyEntry {
  const char* name;
  apriltag_family_t* (*create)();
  void (*destroy)(apriltag_family_t*);
};

constexpr FamilyEntry kFamilies[] = {
    {"tag36h11", tag36h11_create, tag36h11_destroy},
    {"tag25h9", tag25h9_create, tag25h9_destroy},
    {"tag16h5", tag16h5_create, tag16h5_destroy},
    {"tagStandard41h12", tagStandard41h12_create, tagStandard41h12_destroy},
    {"tagStandard52h13", tagStandard52h13_create, tagStandard52h13_destroy},
    {"tagCircle21h7", tagCircle21h7_create, tagCircle21h7_destroy},
    {"tagCircle49h12", tagCircle49h12_create, tagCircle49h12_destroy},
    {"tagCustom48h12", tagCustom48h12_create, tagCustom48h12_destroy},
    {"tag36h10", tag36h10_create, tag36h10_destroy},
};

const FamilyEntry& findFamily(const std::string& name) {
  for (const FamilyEntry& entry : kFamilies) {
    if (name == entry.name) return entry;
  }
  std::ostringstream msg;
  msg << "unknown AprilTag family '" << name << "' (available:";
  for (const FamilyEntry& entry : kFamilies) msg << ' ' << entry.name;
  msg << ')';
  throw InvalidInputError(msg.str());
}

// Owning handle for one family object, destroyed with its own family's destroy function.
class FamilyHandle {
 public:
  explicit FamilyHandle(const FamilyEntry& entry) : entry_(&entry), family_(entry.create()) {
    if (family_ == nullptr) throw Error(std::string("cannot create AprilTag family ") + entry.name);
  }
  ~FamilyHandle() { entry_->destroy(family_); }
  FamilyHandle(const FamilyHandle&) = delete;
  FamilyHandle& operator=(const FamilyHandle&) = delete;
  [[nodiscard]] apriltag_family_t* get() const { return family_; }

 private:
  const FamilyEntry* entry_;
  apriltag_family_t* family_;
};

struct DetectorDeleter {
  void operator()(apriltag_detector_t* td) const { apriltag_detector_destroy(td); }
};
struct DetectionsDeleter {
  void operator()(zarray_t* detections) const { apriltag_detections_destroy(detections); }
};
// Debian's libapriltag 3.3 does not export image_u8_destroy; this is its body (the image and
// its buffer are both malloc'd by image_u8_create_stride).
struct ImageDeleter {
  void operator()(image_u8_t* image) const {
    std::free(image->buf);
    std::free(image);
  }
};

std::string matTypeName(const cv::Mat& image) {
  static const char* const kDepths[] = {"8U", "8S", "16U", "16S", "32S", "32F", "64F", "16F"};
  std::ostringstream out;
  out << "CV_" << kDepths[image.depth()] << 'C' << image.channels();
  return out.str();
}

// "tag36h11,tag25h9" -> each family once, in the order given.
std::vector<const FamilyEntry*> parseFamilies(const std::string& list) {
  std::vector<const FamilyEntry*> families;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = list.find(',', start);
    const std::string name = list.substr(start, end == std::string::npos ? end : end - start);
    const FamilyEntry* entry = &findFamily(name);
    if (std::find(families.begin(), families.end(), entry) != families.end()) {
      throw InvalidInputError("AprilTag family '" + name + "' is listed twice in '" + list + "'");
    }
    families.push_back(entry);
    if (end == std::string::npos) return families;
    start = end + 1;
  }
}

void checkOptions(const DetectorOptions& o) {
  if (!std::isfinite(o.quadDecimate) || !(o.quadDecimate == 0.0f || o.quadDecimate >= 1.0f)) {
    throw InvalidInputError("DetectorOptions::quadDecimate must be 0 (automatic) or >= 1, got " +
                            std::to_string(o.quadDecimate));
  }
  if (o.maxHamming < 0 || o.maxHamming > 3) {
    throw InvalidInputError("DetectorOptions::maxHamming must be in 0..3, got " +
                            std::to_string(o.maxHamming));
  }
  if (!std::isfinite(o.minDecisionMargin) || o.minDecisionMargin < 0) {
    throw InvalidInputError("DetectorOptions::minDecisionMargin must be finite and >= 0");
  }
  if (!std::isfinite(o.quadSigma))
    throw InvalidInputError("DetectorOptions::quadSigma is not finite");
  if (o.threads < 1) {
    throw InvalidInputError("DetectorOptions::threads must be >= 1, got " +
                            std::to_string(o.threads));
  }
  if (!std::isfinite(o.decodeSharpening) || o.decodeSharpening < 0) {
    throw InvalidInputError("DetectorOptions::decodeSharpening must be finite and >= 0");
  }
  if (o.maxBitsCorrected < 0 || o.maxBitsCorrected > 3) {
    throw InvalidInputError("DetectorOptions::maxBitsCorrected must be in 0..3, got " +
                            std::to_string(o.maxBitsCorrected));
  }
}

// libapriltag puts (0,0) at the top-left corner of the first pixel; OpenCV at its centre.
constexpr double kAprilTagToOpenCv = -0.5;

}  // namespace

namespace {
constexpr float kDecimateSteps[] = {1.5f, 2, 3, 4, 5, 6, 8, 10, 12, 16};

// The factor of the pass after one at `factor`: the largest step at most half of it, or 1.
float finerDecimate(float factor) {
  float chosen = 1.0f;
  for (float step : kDecimateSteps) {
    if (step <= factor / 2) chosen = step;
  }
  return chosen;
}
}  // namespace

float autoQuadDecimate(int width, int height) {
  float chosen = 1.0f;
  const double pixels = static_cast<double>(std::max(width, 0)) * std::max(height, 0);
  for (float step : kDecimateSteps) {
    if (pixels / (static_cast<double>(step) * step) < kAutoDecimatePixels) break;
    chosen = step;
  }
  return chosen;
}

glm::dvec2 Detection::tagToImage(glm::dvec2 tagPoint) const {
  return detail::applyHomography(homography, tagPoint);
}

std::vector<std::string> availableFamilies() {
  std::vector<std::string> names;
  for (const FamilyEntry& entry : kFamilies) names.emplace_back(entry.name);
  return names;
}

int familySize(const std::string& family) {
  FamilyHandle handle(findFamily(family));
  return static_cast<int>(handle.get()->ncodes);
}

cv::Mat renderTag(const std::string& family, int id, int* blackBorderCells) {
  FamilyHandle handle(findFamily(family));
  if (id < 0 || id >= static_cast<int>(handle.get()->ncodes)) {
    throw InvalidInputError("tag id " + std::to_string(id) + " is out of range for family " +
                            family + " (0.." + std::to_string(handle.get()->ncodes - 1) + ")");
  }
  std::unique_ptr<image_u8_t, ImageDeleter> tag(apriltag_to_image(handle.get(), id));
  if (!tag) throw Error("apriltag_to_image failed for " + family + " id " + std::to_string(id));
  // The image_u8 rows are padded to `stride` bytes: wrap with that step, then copy out.
  cv::Mat view(tag->height, tag->width, CV_8UC1, tag->buf, static_cast<size_t>(tag->stride));
  if (blackBorderCells != nullptr) *blackBorderCells = handle.get()->width_at_border;
  return view.clone();
}

// Whether libapriltag's worker pool may run several threads (src/apriltag/CMakeLists.txt).
#if defined(ROICLIP_APRILTAG_ONE_WORKER)
constexpr bool kWorkerThreadsSafe = false;
#else
constexpr bool kWorkerThreadsSafe = true;
#endif

struct Detector::Impl {
  explicit Impl(DetectorOptions o) : options(std::move(o)) {
    for (const FamilyEntry* entry : parseFamilies(options.family)) {
      families.push_back(std::make_unique<FamilyHandle>(*entry));
    }
    detector.reset(apriltag_detector_create());
    if (!detector) throw Error("apriltag_detector_create failed");
    detector->quad_sigma = options.quadSigma;
    detector->refine_edges = options.refineEdges;
    detector->nthreads = kWorkerThreadsSafe ? options.threads : 1;
    detector->decode_sharpening = options.decodeSharpening;
    for (const auto& family : families) {
      apriltag_detector_add_family_bits(detector.get(), family->get(), options.maxBitsCorrected);
    }
  }

  // One libapriltag pass with quads searched on the image decimated by `decimateBy`.
  DetectionReport detectAt(const cv::Mat& image, float decimateBy) {
    // libapriltag 3.3 crashes (out-of-bounds read in apriltag_quad_thresh) on images whose
    // decimated height is below 3 rows (1x1, 100x2, 100x4 at decimate 2, ...). No tag fits in
    // so few pixels anyway.
    DetectionReport report;
    report.quadDecimate = decimateBy;
    report.threads = detector->nthreads;
    const int decimate = std::max(1, static_cast<int>(std::ceil(report.quadDecimate)));
    if (std::min(image.rows, image.cols) < 3 * decimate) return report;

    cv::Mat gray;
    if (image.channels() == 3) {
      cv::cvtColor(image, gray, cv::COLOR_BGR2GRAY);
    } else if (image.channels() == 4) {
      cv::cvtColor(image, gray, cv::COLOR_BGRA2GRAY);
    } else if (options.quadSigma != 0.0f && report.quadDecimate <= 1.0f) {
      // Without decimation libapriltag blurs (or sharpens) the input buffer in place.
      gray = image.clone();
    } else {
      gray = image;  // shared, no copy: libapriltag only reads it
    }

    // Wrap the Mat's buffer; `stride` is the row step so ROI views work without a copy.
    image_u8_t wrapped{gray.cols, gray.rows, static_cast<int32_t>(gray.step[0]), gray.data};

    std::vector<Detection> result;
    {
      std::lock_guard<std::mutex> lock(mutex);
      detector->quad_decimate = report.quadDecimate;
      std::unique_ptr<zarray_t, DetectionsDeleter> found(
          apriltag_detector_detect(detector.get(), &wrapped));
      if (!found) throw Error("apriltag_detector_detect failed");
      const int count = zarray_size(found.get());
      result.reserve(static_cast<size_t>(count));
      for (int i = 0; i < count; ++i) {
        apriltag_detection_t* det = nullptr;
        zarray_get(found.get(), i, &det);
        Detection d;
        d.id = det->id;
        d.family = det->family->name;
        d.hamming = det->hamming;
        d.decisionMargin = det->decision_margin;
        d.centre = {det->c[0] + kAprilTagToOpenCv, det->c[1] + kAprilTagToOpenCv};
        for (int k = 0; k < 4; ++k) {
          d.corners[k] = {det->p[k][0] + kAprilTagToOpenCv, det->p[k][1] + kAprilTagToOpenCv};
        }
        result.push_back(std::move(d));
      }
    }
    const auto byId = [](const Detection& a, const Detection& b) {
      return a.id != b.id ? a.id < b.id : a.centre.x < b.centre.x;
    };
    std::sort(result.begin(), result.end(), byId);
    for (Detection& d : result) {
      // Fit to the (shifted) corners in our tag frame rather than converting libapriltag's H, whose
      // ideal frame is 2 units wide and in its pixel convention.
      d.homography = detail::tagFrameHomography(d.corners);
      const bool doubtful =
          d.hamming > options.maxHamming || d.decisionMargin < options.minDecisionMargin;
      (doubtful ? report.rejected : report.tags).push_back(std::move(d));
    }
    return report;
  }

  DetectorOptions options;
  // Declaration order matters: members are destroyed in reverse, so the detector (whose destroy
  // function still walks its families' decode tables) goes before the families it uses.
  std::vector<std::unique_ptr<FamilyHandle>> families;
  std::unique_ptr<apriltag_detector_t, DetectorDeleter> detector;
  std::mutex mutex;
};

Detector::Detector(DetectorOptions options) {
  checkOptions(options);
  impl_ = std::make_unique<Impl>(std::move(options));
}

Detector::~Detector() = default;
Detector::Detector(Detector&&) noexcept = default;
Detector& Detector::operator=(Detector&&) noexcept = default;

const DetectorOptions& Detector::options() const {
  if (!impl_) throw Error("roiclip::apriltag::Detector used after it was moved from");
  return impl_->options;
}

std::vector<Detection> Detector::detect(cv::InputArray input) const {
  return detectReport(input).tags;
}

DetectionReport Detector::detectReport(cv::InputArray input, float quadDecimate,
                                       const std::vector<int>& expectedIds) const {
  if (!impl_) throw Error("roiclip::apriltag::Detector used after it was moved from");
  if (!std::isfinite(quadDecimate) || !(quadDecimate == 0.0f || quadDecimate >= 1.0f)) {
    throw InvalidInputError("AprilTag detect: quadDecimate must be 0 or >= 1, got " +
                            std::to_string(quadDecimate));
  }
  const cv::Mat image = input.getMat();  // a view for cv::Mat input, no copy
  if (image.empty()) throw InvalidInputError("AprilTag detect: the input image is empty");
  if (image.dims != 2 || image.depth() != CV_8U ||
      (image.channels() != 1 && image.channels() != 3 && image.channels() != 4)) {
    throw InvalidInputError(
        "AprilTag detect: the input image must be 8-bit gray, BGR or BGRA (CV_8UC1/3/4), got " +
        matTypeName(image));
  }

  const bool automatic = quadDecimate == 0.0f && impl_->options.quadDecimate == 0.0f;
  const float decimateBy = quadDecimate > 0 ? quadDecimate
                           : impl_->options.quadDecimate > 0
                               ? impl_->options.quadDecimate
                               : autoQuadDecimate(image.cols, image.rows);
  DetectionReport report = impl_->detectAt(image, decimateBy);
  if (!automatic) return report;
  // Coarse to fine: small tags may be lost on the decimated image. Look again, finer, when a
  // pass found none, found one near the size where quads stop being found, or missed an id the
  // caller expects.
  const auto wantsFiner = [&](const DetectionReport& r) {
    if (r.tags.empty()) return true;
    double smallest = std::numeric_limits<double>::infinity();
    for (const Detection& d : r.tags) {
      for (int k = 0; k < 4; ++k) {
        smallest = std::min(smallest, glm::length(d.corners[(k + 1) % 4] - d.corners[k]));
      }
    }
    if (smallest / r.quadDecimate < kAutoDecimateMinTagSide) return true;
    return std::any_of(expectedIds.begin(), expectedIds.end(), [&](int id) {
      return std::none_of(r.tags.begin(), r.tags.end(),
                          [id](const Detection& d) { return d.id == id; });
    });
  };
  int passes = 1;
  while (report.quadDecimate > 1.0f && wantsFiner(report)) {
    report = impl_->detectAt(image, finerDecimate(report.quadDecimate));
    ++passes;
  }
  report.passes = passes;
  return report;
}

}  // namespace roiclip::apriltag
