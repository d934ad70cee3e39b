// SPDX-License-Identifier: MIT
// Mask comparison and the vector-vs-raster check of an ROI clip.
#include <roiclip/opencv/mask_check.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>
#include <string>

#include <opencv2/imgproc.hpp>

#include <roiclip/opencv/convert.hpp>
#include <roiclip/opencv/rasterize.hpp>

namespace roiclip::opencv {
namespace {

struct Interval {
  double lo = INFINITY;
  double hi = -INFINITY;
  [[nodiscard]] bool empty() const { return !(lo <= hi); }
  void intersect(double a, double b) {
    lo = std::max(lo, a);
    hi = std::min(hi, b);
  }
  void unite(const Interval& o) {
    if (o.empty()) return;
    lo = std::min(lo, o.lo);
    hi = std::max(hi, o.hi);
  }
};

// x-range of points on the line y = row within `band` of centre c.
Interval diskRow(cv::Point2d c, double band, double row) {
  const double dy = row - c.y;
  Interval out;
  if (std::fabs(dy) <= band) {
    const double half = std::sqrt(band * band - dy * dy);
    out.lo = c.x - half;
    out.hi = c.x + half;
  }
  return out;
}

// Restrict `out` to the x with lo <= k * x + m <= hi.
void slab(Interval& out, double k, double m, double lo, double hi) {
  if (k == 0.0) {
    if (!(lo <= m && m <= hi)) out = Interval{};
    return;
  }
  double a = (lo - m) / k;
  double b = (hi - m) / k;
  if (a > b) std::swap(a, b);
  out.intersect(a, b);
}

// x-range of points on the line y = row within `band` of segment ab (a convex capsule, so the
// union of the strip and the two end disks is one interval).
Interval capsuleRow(cv::Point2d a, cv::Point2d b, double band, double row) {
  Interval out = diskRow(a, band, row);
  out.unite(diskRow(b, band, row));
  const cv::Point2d d = b - a;
  const double len2 = d.dot(d);
  if (len2 > 0.0) {
    Interval strip{-INFINITY, INFINITY};
    // Projection (p - a).d in [0, len2], p = (x, row).
    slab(strip, d.x, (row - a.y) * d.y - a.x * d.x, 0.0, len2);
    // Perpendicular distance |d x (p - a)| <= band * |d|.
    const double reach = band * std::sqrt(len2);
    slab(strip, -d.y, d.x * (row - a.y) + d.y * a.x, -reach, reach);
    out.unite(strip);
  }
  return out;
}

void checkMask(const cv::Mat& m, const char* name) {
  if (m.type() != CV_8UC1) {
    throw InvalidInputError(std::string("compareMasks: ") + name +
                            " must be a single-channel CV_8U mask");
  }
}

cv::Mat fillPolyMask(const Paths& paths, cv::Size size) {
  cv::Mat mask(size, CV_8UC1, cv::Scalar(0));
  std::vector<std::vector<cv::Point>> contours =
      toFixedPointContours(paths, kDefaultShift).contours.contours;
  contours.erase(std::remove_if(contours.begin(), contours.end(),
                                [](const std::vector<cv::Point>& c) { return c.empty(); }),
                 contours.end());
  if (!contours.empty()) {
    cv::fillPoly(mask, contours, cv::Scalar(255), cv::LINE_8, kDefaultShift);
  }
  return mask;
}

// The raster counterpart of a boolean operation on 0/255 masks.
cv::Mat combine(ClipOp op, const cv::Mat& a, const cv::Mat& b) {
  cv::Mat out;
  switch (op) {
    case ClipOp::Intersection:
      cv::bitwise_and(a, b, out);
      break;
    case ClipOp::Union:
      cv::bitwise_or(a, b, out);
      break;
    case ClipOp::Difference:
      cv::bitwise_and(a, ~b, out);
      break;
    case ClipOp::Xor:
      cv::bitwise_xor(a, b, out);
      break;
  }
  return out;
}

}  // namespace

std::ostream& operator<<(std::ostream& os, const MaskComparison& c) {
  return os << "IoU " << c.iou << " (only expected " << c.onlyExpected << ", only actual "
            << c.onlyActual << ", both " << c.both << "); off band " << c.boundaryBand
            << " px: IoU " << c.offBandIou << " (only expected " << c.offBandOnlyExpected
            << ", only actual " << c.offBandOnlyActual << ", " << c.bandPixels
            << " band pixels ignored)";
}

cv::Mat boundaryBandMask(const Paths& paths, double band, cv::Size size) {
  if (!(band >= 0.0) || !std::isfinite(band)) {
    throw InvalidInputError("boundary band must be a finite number >= 0, got " +
                            std::to_string(band));
  }
  cv::Mat mask(size, CV_8UC1, cv::Scalar(0));
  for (std::size_t p = 0; p < paths.size(); ++p) {
    const Path& path = paths[p];
    for (std::size_t i = 0; i < path.size(); ++i) {
      const cv::Point2d a(path[i].x, path[i].y);
      const cv::Point2d b(path[(i + 1) % path.size()].x, path[(i + 1) % path.size()].y);
      if (!std::isfinite(a.x) || !std::isfinite(a.y)) {
        throw InvalidInputError("boundary band: path " + std::to_string(p) + ", vertex " +
                                std::to_string(i) + " is not finite");
      }
      const double top = std::max(std::ceil(std::min(a.y, b.y) - band), 0.0);
      const double bottom = std::min(std::floor(std::max(a.y, b.y) + band), size.height - 1.0);
      for (double row = top; row <= bottom; row += 1.0) {
        const Interval x = capsuleRow(a, b, band, row);
        if (x.empty()) continue;
        const double first = std::max(std::ceil(x.lo), 0.0);
        const double last = std::min(std::floor(x.hi), size.width - 1.0);
        if (first > last) continue;
        auto* line = mask.ptr<std::uint8_t>(int(row));
        std::fill(line + int(first), line + int(last) + 1, std::uint8_t(255));
      }
    }
  }
  return mask;
}

MaskComparison compareMasks(cv::InputArray expectedIn, cv::InputArray actualIn, double boundaryBand,
                            const Paths& edges) {
  const cv::Mat expected = expectedIn.getMat();
  const cv::Mat actual = actualIn.getMat();
  checkMask(expected, "expected");
  checkMask(actual, "actual");
  if (expected.size() != actual.size()) {
    throw InvalidInputError("compareMasks: expected is " + std::to_string(expected.cols) + "x" +
                            std::to_string(expected.rows) + " but actual is " +
                            std::to_string(actual.cols) + "x" + std::to_string(actual.rows));
  }
  const cv::Mat band = boundaryBandMask(edges, boundaryBand, expected.size());
  MaskComparison c;
  c.boundaryBand = boundaryBand;
  std::int64_t offBandBoth = 0;
  for (int r = 0; r < expected.rows; ++r) {
    const auto* e = expected.ptr<std::uint8_t>(r);
    const auto* a = actual.ptr<std::uint8_t>(r);
    const auto* b = band.ptr<std::uint8_t>(r);
    for (int x = 0; x < expected.cols; ++x) {
      const bool ei = e[x] != 0, ai = a[x] != 0, inBand = b[x] != 0;
      c.both += ei && ai;
      c.onlyExpected += ei && !ai;
      c.onlyActual += ai && !ei;
      if (inBand) {
        ++c.bandPixels;
      } else {
        offBandBoth += ei && ai;
        c.offBandOnlyExpected += ei && !ai;
        c.offBandOnlyActual += ai && !ei;
      }
    }
  }
  const auto iou = [](std::int64_t both, std::int64_t onlyE, std::int64_t onlyA) {
    const std::int64_t any = both + onlyE + onlyA;
    return any == 0 ? 1.0 : double(both) / double(any);
  };
  c.iou = iou(c.both, c.onlyExpected, c.onlyActual);
  c.offBandIou = iou(offBandBoth, c.offBandOnlyExpected, c.offBandOnlyActual);
  return c;
}

namespace {

Paths shifted(const Paths& paths, Point by) {
  Paths out = paths;
  for (Path& path : out) {
    for (Point& p : path) p += by;
  }
  return out;
}

// The part of the image the masks can differ in. For an intersection, every mask is off
// outside the ROI's bounding box, except where the result itself strays (a bug the check must
// see: the result's box is included) and where cv::fillPoly sets pixels up to 1.87 px outside a
// polygon (kOpenCvBand): the union of both boxes grown by the wider band plus a pixel, cut to
// the image. Other operations, or nothing in the image: the whole image.
cv::Rect comparedWindow(const Paths& roi, const PolygonSet& result, cv::Size size,
                        const MaskCheckOptions& options) {
  const cv::Rect image(0, 0, size.width, size.height);
  if (options.op != ClipOp::Intersection) return image;
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  const auto take = [&](const Paths& paths) {
    for (const Path& path : paths) {
      for (const Point& p : path) {
        x0 = std::min(x0, p.x);
        y0 = std::min(y0, p.y);
        x1 = std::max(x1, p.x);
        y1 = std::max(y1, p.y);
      }
    }
  };
  take(roi);
  take(result.toPaths());
  const double grow = std::max(options.exactBand, options.openCvBand) + 1;
  if (!(x0 <= x1) || !std::isfinite(x0) || !std::isfinite(x1)) return image;
  const auto clamp = [](double v, int hi) {
    return static_cast<int>(std::clamp(v, 0.0, static_cast<double>(hi)));
  };
  const int left = clamp(std::floor(x0 - grow), size.width);
  const int top = clamp(std::floor(y0 - grow), size.height);
  const int right = clamp(std::ceil(x1 + grow) + 1, size.width);
  const int bottom = clamp(std::ceil(y1 + grow) + 1, size.height);
  const cv::Rect window(left, top, right - left, bottom - top);
  return window.area() > 0 ? window : image;
}

}  // namespace

MaskCheck checkRoiClip(const Paths& subjectIn, const Paths& roiIn, const PolygonSet& resultIn,
                       FillRule subjectRule, FillRule roiRule, cv::Size sizeIn,
                       const MaskCheckOptions& options) {
  // Only the window where the masks can differ is rasterised; moving everything by whole pixels
  // keeps every pixel's verdict (pixel centres and the grid are both integer-aligned).
  const cv::Rect window = comparedWindow(roiIn, resultIn, sizeIn, options);
  const Point by(-window.x, -window.y);
  const Paths subject = shifted(subjectIn, by);
  const Paths roi = shifted(roiIn, by);
  PolygonSet result = resultIn;
  for (Polygon& polygon : result.polygons) {
    for (Point& p : polygon.outer) p += by;
    for (Path& hole : polygon.holes) {
      for (Point& p : hole) p += by;
    }
  }
  const cv::Size size = window.size();

  MaskCheck check;
  const cv::Mat vectorMask = rasterize(result, size, options.grid);

  Paths edges = subject;
  edges.insert(edges.end(), roi.begin(), roi.end());

  const cv::Mat rasterMask =
      combine(options.op, rasterize(subject, subjectRule, size, options.grid),
              rasterize(roi, roiRule, size, options.grid));
  check.vectorVsRaster = compareMasks(rasterMask, vectorMask, options.exactBand, edges);

  if (subjectRule == FillRule::EvenOdd && roiRule == FillRule::EvenOdd) {
    const cv::Mat openCvMask =
        combine(options.op, fillPolyMask(subject, size), fillPolyMask(roi, size));
    check.vectorVsOpenCv = compareMasks(openCvMask, vectorMask, options.openCvBand, edges);
  }
  return check;
}

}  // namespace roiclip::opencv
