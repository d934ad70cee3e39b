// The overlay image and the mask of a processed image.
#include <array>
#include <sstream>

#include <opencv2/imgproc.hpp>

#include <roiclip/batch/process.hpp>
#include <roiclip/opencv/contours.hpp>
#include <roiclip/opencv/convert.hpp>
#include <roiclip/opencv/rasterize.hpp>

namespace roiclip::batch {

namespace {

// Distinct, readable colours (BGR) for neighbouring regions.
const std::array<cv::Scalar, 8> kPalette = {cv::Scalar(230, 120, 30), cv::Scalar(40, 160, 250),
                                            cv::Scalar(60, 190, 60),  cv::Scalar(200, 60, 200),
                                            cv::Scalar(40, 40, 220),  cv::Scalar(200, 200, 40),
                                            cv::Scalar(140, 90, 240), cv::Scalar(30, 200, 200)};

// Draw paths as polylines at sub-pixel precision (opencv::kDefaultShift).
void drawPaths(cv::Mat& out, const Paths& paths, bool closed, const cv::Scalar& colour,
               int thickness) {
  if (paths.empty()) return;
  const opencv::FixedPointContours c = opencv::toFixedPointContours(paths);
  cv::polylines(out, c.contours.contours, closed, colour, thickness, cv::LINE_AA, c.shift);
}

void drawTags(cv::Mat& out, const std::vector<apriltag::Detection>& tags) {
  for (const auto& tag : tags) {
    drawPaths(out, {Path(tag.corners.begin(), tag.corners.end())}, true, cv::Scalar(60, 220, 60),
              2);
    const cv::Point centre(static_cast<int>(std::lround(tag.centre.x)) - 8,
                           static_cast<int>(std::lround(tag.centre.y)) + 8);
    cv::putText(out, std::to_string(tag.id), centre, cv::FONT_HERSHEY_SIMPLEX, 0.8,
                cv::Scalar(0, 0, 0), 4, cv::LINE_AA);
    cv::putText(out, std::to_string(tag.id), centre, cv::FONT_HERSHEY_SIMPLEX, 0.8,
                cv::Scalar(60, 255, 60), 2, cv::LINE_AA);
  }
}

void drawCaption(cv::Mat& out, const ImageResult& result) {
  std::ostringstream caption;
  caption << toString(result.status) << "  tags " << result.tags.size() << "  contours "
          << result.contoursOut << "/" << result.contoursIn << "  area " << std::fixed;
  caption.precision(1);
  caption << result.clippedArea << " px2";
  if (result.status != Status::Ok && !result.reason.empty()) caption << "  " << result.reason;
  cv::rectangle(out, cv::Rect(0, 0, out.cols, 22), cv::Scalar(0, 0, 0), cv::FILLED);
  cv::putText(out, caption.str(), cv::Point(5, 16), cv::FONT_HERSHEY_SIMPLEX, 0.5,
              result.status == Status::Ok ? cv::Scalar(255, 255, 255) : cv::Scalar(80, 80, 255), 1,
              cv::LINE_AA);
}

}  // namespace

cv::Mat renderOverlay(const cv::Mat& image, const ImageResult& result) {
  if (image.empty()) return {};
  cv::Mat out = opencv::toBgr8(image);
  if (!result.roi.empty()) {
    const cv::Mat roiMask = opencv::rasterize(result.roi, FillRule::EvenOdd, out.size());
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
  drawPaths(out, result.edges, false, cv::Scalar(255, 0, 255), 1);
  drawPaths(out, result.roi, true, cv::Scalar(0, 230, 255), 2);
  drawTags(out, result.tags);
  drawCaption(out, result);
  return out;
}

cv::Mat renderMask(const ImageResult& result, const Grid& grid) {
  return opencv::rasterize(result.clipped, cv::Size(result.width, result.height), grid);
}

}  // namespace roiclip::batch
