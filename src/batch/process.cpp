// The per-image pipeline: tags -> ROI -> contours -> exact clip -> mask check.
#include <roiclip/batch/process.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <new>
#include <sstream>
#include <utility>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <roiclip/opencv/convert.hpp>
#include <roiclip/opencv/rasterize.hpp>

namespace roiclip::batch {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void orient(Path& path, bool negative) {
  const double a = signedArea(path);
  if ((negative && a > 0) || (!negative && a < 0)) std::reverse(path.begin(), path.end());
}

}  // namespace

const char* toString(Status status) {
  switch (status) {
    case Status::Ok:
      return "ok";
    case Status::NoRoi:
      return "no-roi";
    case Status::Failed:
      return "failed";
    case Status::MaskMismatch:
      return "mask-mismatch";
  }
  return "failed";
}

const char* toString(FailureKind kind) {
  switch (kind) {
    case FailureKind::None:
      return "none";
    case FailureKind::Unreadable:
      return "unreadable";
    case FailureKind::TooLarge:
      return "too-large";
    case FailureKind::NoTags:
      return "no-tags";
    case FailureKind::MissingTags:
      return "missing-tags";
    case FailureKind::InvalidInput:
      return "invalid-input";
    case FailureKind::Internal:
      return "internal";
    case FailureKind::Mismatch:
      return "mismatch";
  }
  return "internal";
}

void parseContourMethod(const std::string& text, ContourOptions& options) {
  if (text == "otsu") {
    options.method = ContourMethod::Otsu;
  } else if (text == "adaptive") {
    options.method = ContourMethod::Adaptive;
  } else if (text == "canny") {
    options.method = ContourMethod::Canny;
  } else if (text.rfind("threshold:", 0) == 0) {
    const std::string value = text.substr(10);
    std::size_t used = 0;
    int t = -1;
    try {
      t = std::stoi(value, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != value.size() || t < 0 || t > 255) {
      throw InvalidInputError("contour method '" + text + "': threshold must be 0..255");
    }
    options.method = ContourMethod::Threshold;
    options.threshold = t;
  } else {
    throw InvalidInputError("contour method '" + text +
                            "': expected otsu, adaptive, canny or threshold:T");
  }
}

Polarity parsePolarity(const std::string& text) {
  if (text == "dark") return Polarity::Dark;
  if (text == "light") return Polarity::Light;
  throw InvalidInputError("polarity '" + text + "': expected dark or light");
}

std::int64_t ImageResult::offBandMismatches() const {
  std::int64_t n = vectorVsRaster.offBandOnlyExpected + vectorVsRaster.offBandOnlyActual;
  if (vectorVsOpenCv) n += vectorVsOpenCv->offBandOnlyExpected + vectorVsOpenCv->offBandOnlyActual;
  return n;
}

namespace {

// 8-bit copy (or view) of any depth cv::imread returns: 16-bit scaled by 255/65535, float by 255.
cv::Mat toDepth8(const cv::Mat& image, const std::string& source) {
  cv::Mat depth8;
  switch (image.depth()) {
    case CV_8U:
      depth8 = image;
      break;
    case CV_16U:
      image.convertTo(depth8, CV_8U, 255.0 / 65535.0);
      break;
    case CV_32F:
    case CV_64F:
      image.convertTo(depth8, CV_8U, 255.0);
      break;
    default:
      throw InvalidInputError(source + ": unsupported pixel depth (need 8-bit, 16-bit or float)");
  }
  return depth8;
}

}  // namespace

cv::Mat toGray8(const cv::Mat& image, const std::string& source) {
  if (image.empty()) throw InvalidInputError(source + ": empty image");
  const int channels = image.channels();
  if (channels < 1 || channels > 4) {
    throw InvalidInputError(source + ": unsupported channel count " + std::to_string(channels));
  }
  const cv::Mat depth8 = toDepth8(image, source);
  if (channels == 1) return depth8;
  cv::Mat gray;
  if (channels == 2) {  // gray + alpha
    cv::extractChannel(depth8, gray, 0);
    return gray;
  }
  cv::cvtColor(depth8, gray, channels == 3 ? cv::COLOR_BGR2GRAY : cv::COLOR_BGRA2GRAY);
  return gray;
}

std::vector<Paths> detectContours(const cv::Mat& gray, const ContourOptions& options,
                                  std::vector<int>* indices) {
  if (gray.empty() || gray.type() != CV_8UC1) {
    throw InvalidInputError("detectContours: need a non-empty CV_8UC1 image");
  }
  const bool dark = options.polarity == Polarity::Dark;
  const int binaryType = dark ? cv::THRESH_BINARY_INV : cv::THRESH_BINARY;
  cv::Mat binary;
  switch (options.method) {
    case ContourMethod::Otsu:
      cv::threshold(gray, binary, 0, 255, binaryType | cv::THRESH_OTSU);
      break;
    case ContourMethod::Threshold:
      cv::threshold(gray, binary, options.threshold, 255, binaryType);
      break;
    case ContourMethod::Adaptive:
      if (options.adaptiveBlock < 3 || options.adaptiveBlock % 2 == 0) {
        throw InvalidInputError("adaptive block size must be odd and >= 3, got " +
                                std::to_string(options.adaptiveBlock));
      }
      cv::adaptiveThreshold(gray, binary, 255, cv::ADAPTIVE_THRESH_GAUSSIAN_C, binaryType,
                            options.adaptiveBlock, options.adaptiveC);
      break;
    case ContourMethod::Canny:
      cv::Canny(gray, binary, options.cannyLow, options.cannyHigh);
      break;
  }
  std::vector<std::vector<cv::Point>> contours;
  std::vector<cv::Vec4i> hierarchy;
  cv::findContours(binary, contours, hierarchy, cv::RETR_CCOMP, cv::CHAIN_APPROX_SIMPLE);
  if (options.approxEpsilon > 0) {
    for (auto& c : contours) {
      std::vector<cv::Point> approx;
      cv::approxPolyDP(c, approx, options.approxEpsilon, true);
      c = std::move(approx);
    }
  }
  std::vector<Paths> groups;
  if (indices) indices->clear();
  for (std::size_t i = 0; i < contours.size(); ++i) {
    if (hierarchy[i][3] != -1) continue;  // a hole; taken with its outer contour below
    if (options.minArea > 0 && std::abs(cv::contourArea(contours[i])) < options.minArea) continue;
    Paths group;
    group.push_back(opencv::fromContour(contours[i]));
    orient(group.back(), true);
    for (int h = hierarchy[i][2]; h >= 0; h = hierarchy[static_cast<std::size_t>(h)][0]) {
      group.push_back(opencv::fromContour(contours[static_cast<std::size_t>(h)]));
      orient(group.back(), false);
    }
    groups.push_back(std::move(group));
    if (indices) indices->push_back(static_cast<int>(i));
  }
  return groups;
}

struct Processor::Impl {
  RunOptions options;
  apriltag::Detector detector;
  apriltag::RoiSpec spec;
  std::optional<apriltag::Board> board;

  explicit Impl(RunOptions o)
      : options(std::move(o)),
        detector(options.detector),
        spec(apriltag::parseRoiSpec(options.roi)) {
    if (spec.kind == apriltag::RoiSpec::Kind::Board) {
      if (options.boardFile.empty()) {
        throw InvalidInputError("ROI spec '" + options.roi + "' needs a board file (--board)");
      }
      board = apriltag::Board::load(options.boardFile);
    }
  }

  void run(const cv::Mat& image, ImageResult& r) const {
    const auto start = Clock::now();
    const auto pixels = static_cast<std::int64_t>(image.total());
    if (options.maxPixels > 0 && pixels > options.maxPixels) {
      throw ImageTooLargeError("image " + std::to_string(image.cols) + " x " +
                               std::to_string(image.rows) + " = " + std::to_string(pixels) +
                               " pixels, more than the limit of " +
                               std::to_string(options.maxPixels));
    }
    const cv::Mat gray = toGray8(image);
    r.width = gray.cols;
    r.height = gray.rows;

    auto t = Clock::now();
    r.tags = detector.detect(gray);
    r.seconds.detect = secondsSince(t);

    t = Clock::now();
    const apriltag::RoiResult roi = apriltag::buildRoi(spec, r.tags, board ? &*board : nullptr);
    r.seconds.roi = secondsSince(t);
    if (!roi) {
      r.status = Status::NoRoi;
      r.missingTags = roi.missing();
      if (r.tags.empty()) {
        r.failure = FailureKind::NoTags;
        r.reason = "no " + options.detector.family + " tags detected";
      } else {
        r.failure = FailureKind::MissingTags;
        r.reason = "ROI '" + options.roi + "': " + roi.missing().describe();
      }
      r.seconds.total = secondsSince(start);
      return;
    }
    r.roi = roi.value();
    const PolygonSet roiRegion = simplify(r.roi, options.roiFillRule, options.grid);
    r.roiArea = roiRegion.area();

    t = Clock::now();
    std::vector<int> indices;
    std::vector<Paths> groups = detectContours(gray, options.contours, &indices);
    r.seconds.contours = secondsSince(t);

    t = Clock::now();
    Paths all;
    r.contours.reserve(groups.size());
    for (std::size_t i = 0; i < groups.size(); ++i) {
      ContourResult c;
      c.contourIndex = indices[i];
      c.input = std::move(groups[i]);
      c.inputArea = simplify(c.input, options.subjectFillRule, options.grid).area();
      c.clipped = clip(ClipOp::Intersection, c.input, r.roi, options.subjectFillRule,
                       options.roiFillRule, options.grid);
      c.clippedArea = c.clipped.area();
      r.holesIn += static_cast<int>(c.input.size()) - 1;
      if (!c.clipped.empty()) ++r.contoursOut;
      r.contourClippedAreaSum += c.clippedArea;
      all.insert(all.end(), c.input.begin(), c.input.end());
      r.contours.push_back(std::move(c));
    }
    r.contoursIn = static_cast<int>(r.contours.size());
    if (options.contours.openEdges) {
      cv::Mat edgeImage;
      cv::Canny(gray, edgeImage, options.contours.cannyLow, options.contours.cannyHigh);
      std::vector<Path> lines = traceEdges(edgeImage);
      if (options.contours.approxEpsilon > 0) {
        for (Path& line : lines) {
          std::vector<cv::Point2d> in;
          std::vector<cv::Point2d> approx;
          for (const Point& p : line) in.emplace_back(p.x, p.y);
          cv::approxPolyDP(in, approx, options.contours.approxEpsilon, false);
          line.clear();
          for (const auto& p : approx) line.emplace_back(p.x, p.y);
        }
      }
      r.edgesIn = static_cast<int>(lines.size());
      r.edges = clipLines(lines, r.roi, options.roiFillRule, LinePart::Inside, options.grid);
      r.edgeLength = polylineLength(r.edges);
    }
    r.seconds.clip = secondsSince(t);

    t = Clock::now();
    opencv::MaskCheckOptions checkOptions;
    checkOptions.grid = options.grid;
    opencv::MaskCheck check =
        opencv::checkRoiClip(all, r.roi, options.subjectFillRule, options.roiFillRule,
                             cv::Size(gray.cols, gray.rows), checkOptions);
    r.seconds.check = secondsSince(t);
    r.clipped = std::move(check.clipped);
    r.clippedArea = r.clipped.area();
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
    r.seconds.total = secondsSince(start);
  }
};

Processor::Processor(RunOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {}
Processor::~Processor() = default;
Processor::Processor(Processor&&) noexcept = default;
Processor& Processor::operator=(Processor&&) noexcept = default;

const RunOptions& Processor::options() const { return impl_->options; }

ImageResult Processor::process(const cv::Mat& image) const {
  ImageResult r;
  const auto start = Clock::now();
  try {
    impl_->run(image, r);
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

ImageResult processImage(const cv::Mat& image, const RunOptions& options) {
  std::optional<Processor> processor;
  try {
    processor.emplace(options);
  } catch (const Error& e) {
    ImageResult r;
    r.status = Status::Failed;
    r.failure = FailureKind::InvalidInput;
    r.reason = e.what();
    return r;
  }
  return processor->process(image);
}

// ---------------------------------------------------------------------------------------------
// Overlay and mask

namespace {

cv::Mat toBgr8(const cv::Mat& image) {
  const cv::Mat depth8 = toDepth8(image, "image");
  cv::Mat bgr;
  if (depth8.channels() == 2) {  // gray + alpha
    cv::Mat gray;
    cv::extractChannel(depth8, gray, 0);
    cv::cvtColor(gray, bgr, cv::COLOR_GRAY2BGR);
  } else if (depth8.channels() == 1) {
    cv::cvtColor(depth8, bgr, cv::COLOR_GRAY2BGR);
  } else if (depth8.channels() == 4) {
    cv::cvtColor(depth8, bgr, cv::COLOR_BGRA2BGR);
  } else {
    bgr = depth8.clone();
  }
  return bgr;
}

// Distinct, readable colours (BGR) for neighbouring regions.
const std::array<cv::Scalar, 8> kPalette = {cv::Scalar(230, 120, 30), cv::Scalar(40, 160, 250),
                                            cv::Scalar(60, 190, 60),  cv::Scalar(200, 60, 200),
                                            cv::Scalar(40, 40, 220),  cv::Scalar(200, 200, 40),
                                            cv::Scalar(140, 90, 240), cv::Scalar(30, 200, 200)};

}  // namespace

cv::Mat renderOverlay(const cv::Mat& image, const ImageResult& result) {
  if (image.empty()) return {};
  cv::Mat out = toBgr8(image);
  const cv::Size size = out.size();
  const int shift = opencv::kDefaultShift;
  if (!result.roi.empty()) {
    const cv::Mat roiMask = opencv::rasterize(result.roi, FillRule::EvenOdd, size);
    cv::Mat dimmed;
    out.convertTo(dimmed, -1, 0.35);
    dimmed.copyTo(out, ~roiMask);
  }
  if (!result.contours.empty()) {
    cv::Mat layer = out.clone();
    for (std::size_t i = 0; i < result.contours.size(); ++i) {
      opencv::fillPolygonSet(layer, result.contours[i].clipped, kPalette[i % kPalette.size()]);
    }
    cv::addWeighted(out, 0.5, layer, 0.5, 0.0, out);
    for (std::size_t i = 0; i < result.contours.size(); ++i) {
      opencv::drawPolygonSet(out, result.contours[i].clipped, kPalette[i % kPalette.size()] * 0.6,
                             1, cv::LINE_AA);
    }
  }
  for (const Path& line : result.edges) {
    std::vector<cv::Point> pts;
    for (const Point& p : line) {
      pts.emplace_back(static_cast<int>(std::lround(p.x * (1 << shift))),
                       static_cast<int>(std::lround(p.y * (1 << shift))));
    }
    cv::polylines(out, std::vector<std::vector<cv::Point>>{pts}, false, cv::Scalar(255, 0, 255), 1,
                  cv::LINE_AA, shift);
  }
  if (!result.roi.empty()) {
    const opencv::FixedPointContours roi = opencv::toFixedPointContours(result.roi, shift);
    cv::polylines(out, roi.contours.contours, true, cv::Scalar(0, 230, 255), 2, cv::LINE_AA,
                  roi.shift);
  }
  for (const auto& tag : result.tags) {
    std::vector<cv::Point> corners;
    for (const auto& c : tag.corners) {
      corners.emplace_back(static_cast<int>(std::lround(c.x * (1 << shift))),
                           static_cast<int>(std::lround(c.y * (1 << shift))));
    }
    cv::polylines(out, std::vector<std::vector<cv::Point>>{corners}, true, cv::Scalar(60, 220, 60),
                  2, cv::LINE_AA, shift);
    const cv::Point centre(static_cast<int>(std::lround(tag.centre.x)) - 8,
                           static_cast<int>(std::lround(tag.centre.y)) + 8);
    cv::putText(out, std::to_string(tag.id), centre, cv::FONT_HERSHEY_SIMPLEX, 0.8,
                cv::Scalar(0, 0, 0), 4, cv::LINE_AA);
    cv::putText(out, std::to_string(tag.id), centre, cv::FONT_HERSHEY_SIMPLEX, 0.8,
                cv::Scalar(60, 255, 60), 2, cv::LINE_AA);
  }
  std::ostringstream caption;
  caption << toString(result.status) << "  tags " << result.tags.size() << "  contours "
          << result.contoursOut << "/" << result.contoursIn << "  area " << std::fixed;
  caption.precision(1);
  caption << result.clippedArea << " px2";
  if (result.status != Status::Ok && !result.reason.empty()) caption << "  " << result.reason;
  cv::rectangle(out, cv::Rect(0, 0, size.width, 22), cv::Scalar(0, 0, 0), cv::FILLED);
  cv::putText(out, caption.str(), cv::Point(5, 16), cv::FONT_HERSHEY_SIMPLEX, 0.5,
              result.status == Status::Ok ? cv::Scalar(255, 255, 255) : cv::Scalar(80, 80, 255), 1,
              cv::LINE_AA);
  return out;
}

cv::Mat renderMask(const ImageResult& result, const Grid& grid) {
  return opencv::rasterize(result.clipped, cv::Size(result.width, result.height), grid);
}

// ---------------------------------------------------------------------------------------------
// JSON

namespace {

using Json = nlohmann::json;

Json pathJson(const Path& path) {
  Json a = Json::array();
  for (const Point& p : path) a.push_back({p.x, p.y});
  return a;
}

Json pathsJson(const Paths& paths) {
  Json a = Json::array();
  for (const Path& p : paths) a.push_back(pathJson(p));
  return a;
}

Json polygonSetJson(const PolygonSet& set) {
  Json a = Json::array();
  for (const Polygon& poly : set.polygons) {
    Json holes = Json::array();
    for (const Path& h : poly.holes) holes.push_back(pathJson(h));
    a.push_back({{"outer", pathJson(poly.outer)},
                 {"holes", std::move(holes)},
                 {"parent", poly.parent},
                 {"parent_hole", poly.parentHole}});
  }
  return a;
}

Json comparisonJson(const opencv::MaskComparison& c) {
  return {{"iou", c.iou},
          {"only_expected", c.onlyExpected},
          {"only_actual", c.onlyActual},
          {"both", c.both},
          {"band_px", c.boundaryBand},
          {"band_pixels", c.bandPixels},
          {"off_band_only_expected", c.offBandOnlyExpected},
          {"off_band_only_actual", c.offBandOnlyActual},
          {"off_band_iou", c.offBandIou},
          {"agrees_off_band", c.agreesOffBand()}};
}

}  // namespace

std::string optionsKey(const RunOptions& o) {
  std::ostringstream os;
  os.precision(17);
  const ContourOptions& c = o.contours;
  os << "roi=" << o.roi << ";board=" << o.boardFile << ";family=" << o.detector.family
     << ";decimate=" << o.detector.quadDecimate << ";sigma=" << o.detector.quadSigma
     << ";refine=" << o.detector.refineEdges << ";sharpen=" << o.detector.decodeSharpening
     << ";bits=" << o.detector.maxBitsCorrected << ";method=" << static_cast<int>(c.method)
     << ";polarity=" << static_cast<int>(c.polarity) << ";threshold=" << c.threshold
     << ";block=" << c.adaptiveBlock << ";c=" << c.adaptiveC << ";canny=" << c.cannyLow << ","
     << c.cannyHigh << ";approx=" << c.approxEpsilon << ";min_area=" << c.minArea
     << ";edges=" << c.openEdges << ";fill=" << toString(o.subjectFillRule)
     << ";roi_fill=" << toString(o.roiFillRule) << ";grid=" << o.grid.scale;
  return os.str();
}

std::string resultToJson(const ImageResult& r, const std::string& imageName,
                         const std::string& optionsKey) {
  Json j;
  j["image"] = imageName;
  if (!optionsKey.empty()) j["options"] = optionsKey;
  j["status"] = toString(r.status);
  j["failure"] = toString(r.failure);
  j["reason"] = r.reason;
  j["width"] = r.width;
  j["height"] = r.height;
  Json tags = Json::array();
  for (const auto& t : r.tags) {
    Json corners = Json::array();
    for (const auto& c : t.corners) corners.push_back({c.x, c.y});
    tags.push_back({{"id", t.id},
                    {"family", t.family},
                    {"hamming", t.hamming},
                    {"decision_margin", t.decisionMargin},
                    {"centre", {t.centre.x, t.centre.y}},
                    {"corners", std::move(corners)}});
  }
  j["tags"] = std::move(tags);
  if (r.missingTags) {
    j["missing_tags"] = {{"needed", r.missingTags->needed},
                         {"seen", r.missingTags->seen},
                         {"missing", r.missingTags->missing},
                         {"duplicated", r.missingTags->duplicated}};
  }
  j["roi"] = {{"paths", pathsJson(r.roi)}, {"area", r.roiArea}};
  j["contours_in"] = r.contoursIn;
  j["contours_out"] = r.contoursOut;
  j["holes_in"] = r.holesIn;
  j["clipped_area"] = r.clippedArea;
  j["contour_clipped_area_sum"] = r.contourClippedAreaSum;
  j["clipped"] = polygonSetJson(r.clipped);
  Json contours = Json::array();
  for (const auto& c : r.contours) {
    if (c.clipped.empty()) continue;  // only what lies inside the ROI; counts say the rest
    contours.push_back({{"contour_index", c.contourIndex},
                        {"holes", static_cast<int>(c.input.size()) - 1},
                        {"input_area", c.inputArea},
                        {"clipped_area", c.clippedArea},
                        {"polygons", polygonSetJson(c.clipped)}});
  }
  j["contours"] = std::move(contours);
  if (!r.edges.empty() || r.edgesIn > 0) {
    j["edges"] = {{"traced", r.edgesIn},
                  {"clipped", r.edges.size()},
                  {"length", r.edgeLength},
                  {"polylines", pathsJson(r.edges)}};
  }
  Json check = {{"exact", comparisonJson(r.vectorVsRaster)},
                {"off_band_mismatches", r.offBandMismatches()}};
  if (r.vectorVsOpenCv) check["opencv"] = comparisonJson(*r.vectorVsOpenCv);
  j["mask_check"] = std::move(check);
  j["seconds"] = {{"detect", r.seconds.detect},     {"roi", r.seconds.roi},
                  {"contours", r.seconds.contours}, {"clip", r.seconds.clip},
                  {"check", r.seconds.check},       {"total", r.seconds.total}};
  return j.dump() + "\n";  // compact: polygons with thousands of vertices
}

}  // namespace roiclip::batch
