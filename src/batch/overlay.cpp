// SPDX-License-Identifier: MIT
// The overlay image and the mask of a processed image.
//
// Every line width, font size and gap of the overlay is a multiple of one unit that grows with
// the image (kReferenceSide px long side = 1), so a 4000 px photo gets annotations as readable
// as an 800 px scene. The caption is drawn in a band above the image, never over it.
#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include <opencv2/imgproc.hpp>

#include <roiclip/batch/process.hpp>
#include <roiclip/opencv/contours.hpp>
#include <roiclip/opencv/convert.hpp>
#include <roiclip/opencv/rasterize.hpp>

#include "detail/overlay.hpp"

namespace roiclip::batch {

namespace {

// Distinct, readable colours (BGR) for neighbouring regions.
const std::array<cv::Scalar, 8> kPalette = {cv::Scalar(230, 120, 30), cv::Scalar(40, 160, 250),
                                            cv::Scalar(60, 190, 60),  cv::Scalar(200, 60, 200),
                                            cv::Scalar(40, 40, 220),  cv::Scalar(200, 200, 40),
                                            cv::Scalar(140, 90, 240), cv::Scalar(30, 200, 200)};
// One colour per named ROI; the first is the region's yellow.
const std::array<cv::Scalar, 4> kRoiColours = {cv::Scalar(0, 230, 255), cv::Scalar(255, 200, 0),
                                               cv::Scalar(0, 140, 255), cv::Scalar(255, 120, 255)};
const cv::Scalar kRegionColour = kRoiColours[0];
const cv::Scalar kExcludedColour(40, 40, 255);  // red: hatched, taken out of the region
const cv::Scalar kTagColour(60, 220, 60);
const cv::Scalar kEdgeColour(255, 0, 255);
const cv::Scalar kText(255, 255, 255);
const cv::Scalar kOkText(80, 220, 80);
const cv::Scalar kBadText(80, 80, 255);
constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
constexpr double kReferenceSide = 800.0;  // the bundled scenes' width: unit 1

// Sizes of one overlay, all from its unit.
struct Scale {
  double unit;
  explicit Scale(cv::Size size)
      : unit(std::max(0.5, std::max(size.width, size.height) / kReferenceSide)) {}
  [[nodiscard]] int px(double atUnitOne) const {
    return std::max(1, static_cast<int>(std::lround(atUnitOne * unit)));
  }
  [[nodiscard]] double font(double atUnitOne) const { return atUnitOne * unit; }
};

// Draw paths as polylines at sub-pixel precision (opencv::kDefaultShift).
void drawPaths(cv::Mat& out, const Paths& paths, bool closed, const cv::Scalar& colour,
               int thickness) {
  if (paths.empty()) return;
  const opencv::FixedPointContours c = opencv::toFixedPointContours(paths);
  cv::polylines(out, c.contours.contours, closed, colour, thickness, cv::LINE_AA, c.shift);
}

// Text in `colour` with a black outline, readable on any background.
void drawLabel(cv::Mat& out, const std::string& text, cv::Point origin, double fontScale,
               int thickness, const cv::Scalar& colour) {
  cv::putText(out, text, origin, kFont, fontScale, cv::Scalar(0, 0, 0), thickness * 3, cv::LINE_AA);
  cv::putText(out, text, origin, kFont, fontScale, colour, thickness, cv::LINE_AA);
}

void drawTags(cv::Mat& out, const std::vector<apriltag::Detection>& tags, const Scale& s) {
  for (const auto& tag : tags) {
    drawPaths(out, {Path(tag.corners.begin(), tag.corners.end())}, true, kTagColour, s.px(2));
    const std::string id = std::to_string(tag.id);
    int baseline = 0;
    const cv::Size size = cv::getTextSize(id, kFont, s.font(0.8), s.px(2), &baseline);
    const cv::Point origin(static_cast<int>(std::lround(tag.centre.x)) - size.width / 2,
                           static_cast<int>(std::lround(tag.centre.y)) + size.height / 2);
    drawLabel(out, id, origin, s.font(0.8), s.px(2), cv::Scalar(60, 255, 60));
  }
}

// The excluded tag quads: diagonal red hatching inside, red outline.
void drawExcluded(cv::Mat& out, const Paths& quads, const Scale& s) {
  if (quads.empty()) return;
  std::vector<cv::Point2f> corners;
  for (const Path& quad : quads) {
    for (const Point& p : quad)
      corners.emplace_back(static_cast<float>(p.x), static_cast<float>(p.y));
  }
  const cv::Rect box = cv::boundingRect(corners) & cv::Rect(0, 0, out.cols, out.rows);
  if (box.empty()) return;
  cv::Mat hatched = out.clone();
  const int step = s.px(10);
  for (int k = 0; k <= box.width + box.height; k += step) {
    cv::line(hatched, {box.x + k, box.y}, {box.x + k - box.height, box.y + box.height},
             kExcludedColour, s.px(1), cv::LINE_AA);
  }
  // NonZero: grown quads may overlap, and the overlap is excluded too.
  hatched.copyTo(out, opencv::rasterize(quads, FillRule::NonZero, out.size()));
  drawPaths(out, quads, true, kExcludedColour, s.px(1.5));
}

// Each named ROI as built from the tags, in its own colour, with its name above its top-left
// vertex.
void drawRois(cv::Mat& out, const std::vector<RoiRegion>& rois, const Scale& s) {
  for (std::size_t i = 0; i < rois.size(); ++i) {
    const RoiRegion& roi = rois[i];
    const cv::Scalar& colour = kRoiColours[i % kRoiColours.size()];
    drawPaths(out, roi.paths, true, colour, s.px(2));
    const Point* top = nullptr;
    for (const Path& path : roi.paths) {
      for (const Point& p : path) {
        if (top == nullptr || p.x + p.y < top->x + top->y) top = &p;
      }
    }
    if (top == nullptr || roi.name.empty()) continue;
    int baseline = 0;
    const cv::Size size = cv::getTextSize(roi.name, kFont, s.font(0.7), s.px(1.5), &baseline);
    int x = static_cast<int>(std::lround(top->x));
    int y = static_cast<int>(std::lround(top->y)) - s.px(6);
    if (y - size.height < 0) y = static_cast<int>(std::lround(top->y)) + size.height + s.px(6);
    x = std::clamp(x, 0, std::max(0, out.cols - size.width));
    drawLabel(out, roi.name, {x, y}, s.font(0.7), s.px(1.5), colour);
  }
}

// The caption: words in colours, wrapped to the image width, drawn in a band of its own.
class Caption {
 public:
  explicit Caption(const Scale& s)
      : fontScale_(s.font(0.55)), thickness_(s.px(1)), margin_(s.px(6)) {
    int baseline = 0;
    const cv::Size size = cv::getTextSize("Ag", kFont, fontScale_, thickness_, &baseline);
    ascent_ = size.height;
    descent_ = baseline;
    lineHeight_ = ascent_ + descent_ + s.px(6);
    space_ = cv::getTextSize(" ", kFont, fontScale_, thickness_, &baseline).width;
  }

  // One phrase: its words stay one space apart, phrases two.
  void phrase(const std::string& text, const cv::Scalar& colour) {
    std::istringstream words(text);
    bool first = true;
    for (std::string w; words >> w; first = false) words_.push_back({w, colour, first, false});
  }
  void newLine() {
    if (!words_.empty()) words_.back().breakAfter = true;
  }

  // Lay the words out for a band `width` px wide; returns the band's height.
  int layout(int width) {
    int x = margin_, line = 0;
    for (Word& w : words_) {
      int baseline = 0;
      const int wide = cv::getTextSize(w.text, kFont, fontScale_, thickness_, &baseline).width;
      const int gap = x == margin_ ? 0 : (w.phraseStart ? 2 : 1) * space_;
      if (x > margin_ && x + gap + wide > width - margin_) {
        ++line;
        x = margin_;
      } else {
        x += gap;
      }
      w.position = {x, margin_ + ascent_ + line * lineHeight_};
      x += wide;
      if (w.breakAfter) {
        ++line;
        x = margin_;
      }
    }
    const int lines = words_.empty() ? 1 : line + (words_.back().breakAfter ? 0 : 1);
    return 2 * margin_ + ascent_ + (lines - 1) * lineHeight_ + descent_;
  }

  void draw(cv::Mat& band) const {
    for (const Word& w : words_) {
      cv::putText(band, w.text, w.position, kFont, fontScale_, w.colour, thickness_, cv::LINE_AA);
    }
  }

 private:
  struct Word {
    std::string text;
    cv::Scalar colour;
    bool phraseStart;
    bool breakAfter;
    cv::Point position{};
  };
  double fontScale_;
  int thickness_, margin_;
  int ascent_ = 0, descent_ = 0, lineHeight_ = 0, space_ = 0;
  std::vector<Word> words_;
};

Caption captionOf(const ImageResult& result, const Scale& s) {
  Caption c(s);
  c.phrase(toString(result.status), result.status == Status::Ok ? kOkText : kBadText);
  std::string tags = "tags " + std::to_string(result.tags.size());
  if (!result.rejectedTags.empty()) {
    tags += " (" + std::to_string(result.rejectedTags.size()) + " rejected)";
  }
  c.phrase(tags, kText);
  // Contours and area only where the pipeline clipped (as report.html shows them).
  if (result.status == Status::Ok || result.status == Status::MaskMismatch) {
    c.phrase("contours " + detail::contoursInsideText(result.contoursOut, result.contoursIn),
             kText);
    std::ostringstream area;
    area << "area " << std::fixed;
    area.precision(1);
    area << result.clippedArea << " px2";
    c.phrase(area.str(), kText);
  }
  if (result.status != Status::Ok && !result.reason.empty()) c.phrase(result.reason, kBadText);
  c.newLine();
  // The legend: only what is drawn.
  if (!result.rois.empty() || !result.roi.empty()) {
    c.phrase(result.rois.size() > 1 ? "ROIs" : "ROI", kRegionColour);
  }
  if (!result.excludedTags.empty()) c.phrase("excluded tags (hatched)", kExcludedColour);
  if (!result.tags.empty()) c.phrase("tag ids", kTagColour);
  if (!result.contours.empty()) c.phrase("clipped contours (filled)", kPalette[0]);
  if (!result.edges.empty()) c.phrase("edges", kEdgeColour);
  return c;
}

}  // namespace

namespace detail {

std::string contoursInsideText(int inside, int found) {
  return std::to_string(inside) + " of " + std::to_string(found) + " inside";
}

}  // namespace detail

cv::Mat renderOverlay(const cv::Mat& image, const ImageResult& result) {
  if (image.empty()) return {};
  const Scale s(image.size());
  Caption caption = captionOf(result, s);
  const int band = caption.layout(image.cols);
  cv::Mat canvas(image.rows + band, image.cols, CV_8UC3, cv::Scalar(0, 0, 0));
  cv::Mat bandView = canvas.rowRange(0, band);
  cv::Mat out = canvas.rowRange(band, canvas.rows);  // the image's own pixels, drawn in place
  opencv::toBgr8(image).copyTo(out);
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
                             s.px(1), cv::LINE_AA);
    }
  }
  drawPaths(out, result.edges, false, kEdgeColour, s.px(1));
  drawExcluded(out, result.excludedTags, s);
  drawPaths(out, result.roi, true, kRegionColour, s.px(1));
  drawRois(out, result.rois, s);
  drawTags(out, result.tags, s);
  caption.draw(bandView);
  return canvas;
}

cv::Mat renderMask(const ImageResult& result, const Grid& grid) {
  return opencv::rasterize(result.clipped, cv::Size(result.width, result.height), grid);
}

}  // namespace roiclip::batch
