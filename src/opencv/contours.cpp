// SPDX-License-Identifier: MIT
// Contour detection (threshold / Canny -> cv::findContours -> groups of roiclip rings) and the
// image conversions it needs.
#include <roiclip/opencv/contours.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include <opencv2/imgproc.hpp>

#include <roiclip/opencv/convert.hpp>

namespace roiclip::opencv {

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

void checkImage(const cv::Mat& image, const std::string& source) {
  if (image.empty()) throw InvalidInputError(source + ": empty image");
  const int channels = image.channels();
  if (channels < 1 || channels > 4) {
    throw InvalidInputError(source + ": unsupported channel count " + std::to_string(channels));
  }
}

// The object mask cv::findContours traces.
cv::Mat objectMask(const cv::Mat& gray, const ContourOptions& options) {
  const int binaryType =
      options.polarity == Polarity::Dark ? cv::THRESH_BINARY_INV : cv::THRESH_BINARY;
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
  return binary;
}

}  // namespace

cv::Mat toGray8(cv::InputArray input, const std::string& source) {
  const cv::Mat image = input.getMat();
  checkImage(image, source);
  const int channels = image.channels();
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

cv::Mat toBgr8(cv::InputArray input, const std::string& source) {
  const cv::Mat image = input.getMat();
  checkImage(image, source);
  const cv::Mat depth8 = toDepth8(image, source);
  cv::Mat bgr;
  switch (depth8.channels()) {
    case 1:
      cv::cvtColor(depth8, bgr, cv::COLOR_GRAY2BGR);
      break;
    case 2: {  // gray + alpha
      cv::Mat gray;
      cv::extractChannel(depth8, gray, 0);
      cv::cvtColor(gray, bgr, cv::COLOR_GRAY2BGR);
      break;
    }
    case 4:
      cv::cvtColor(depth8, bgr, cv::COLOR_BGRA2BGR);
      break;
    default:
      bgr = depth8.clone();
  }
  return bgr;
}

std::vector<ContourGroup> detectContours(cv::InputArray input, const ContourOptions& options) {
  const cv::Mat gray = input.getMat();
  if (gray.empty() || gray.type() != CV_8UC1) {
    throw InvalidInputError("detectContours: need a non-empty CV_8UC1 image");
  }
  std::vector<std::vector<cv::Point>> contours;
  std::vector<cv::Vec4i> hierarchy;
  cv::findContours(objectMask(gray, options), contours, hierarchy, cv::RETR_CCOMP,
                   cv::CHAIN_APPROX_SIMPLE);
  if (options.approxEpsilon > 0) {
    for (auto& c : contours) {
      std::vector<cv::Point> approx;
      cv::approxPolyDP(c, approx, options.approxEpsilon, true);
      c = std::move(approx);
    }
  }
  std::vector<ContourGroup> groups = groupContours(contours, hierarchy);
  if (options.minArea > 0) {
    const auto tooSmall = [&](const ContourGroup& g) {
      return std::abs(cv::contourArea(contours[std::size_t(g.index)])) < options.minArea;
    };
    groups.erase(std::remove_if(groups.begin(), groups.end(), tooSmall), groups.end());
  }
  return groups;
}

double pixelContourArea(const ContourGroup& group) {
  // Twice the shoelace sum over all rings, in integers (the points are cv::Point coordinates).
  __int128 twice = 0;
  for (const Path& ring : group.rings) {
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      const Point& a = ring[i];
      const Point& b = ring[(i + 1) % n];
      twice += __int128(std::int64_t(a.x)) * std::int64_t(b.y) -
               __int128(std::int64_t(b.x)) * std::int64_t(a.y);
    }
  }
  return 0.5 * std::fabs(static_cast<double>(twice));
}

}  // namespace roiclip::opencv
