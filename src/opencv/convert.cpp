// SPDX-License-Identifier: MIT
// Conversions between OpenCV contours and roiclip paths.
#include <roiclip/opencv/convert.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

#include <opencv2/imgproc.hpp>

namespace roiclip::opencv {
namespace {

std::string contourName(std::size_t index) { return "contour " + std::to_string(index); }

const char* depthName(int depth) {
  switch (depth) {
    case CV_8U:
      return "CV_8U";
    case CV_8S:
      return "CV_8S";
    case CV_16U:
      return "CV_16U";
    case CV_16S:
      return "CV_16S";
    case CV_32S:
      return "CV_32S";
    case CV_32F:
      return "CV_32F";
    case CV_64F:
      return "CV_64F";
    default:
      return "an unsupported depth";
  }
}

// Integer pairs x0 y0 x1 y1 ... read as points, a forward range: a vector takes them in one
// allocation, each point built in place (resize() and a loop zero-filled them first: W1-100k
// 1.9% of its instructions). Its points are values, not references into storage.
struct IntPairPoints {
  using iterator_category = std::forward_iterator_tag;
  using value_type = Point;
  using difference_type = std::ptrdiff_t;
  using pointer = void;
  using reference = Point;
  const int* v;
  Point operator*() const { return Point(double(v[0]), double(v[1])); }
  IntPairPoints& operator++() {
    v += 2;
    return *this;
  }
  bool operator==(const IntPairPoints& o) const { return v == o.v; }
  bool operator!=(const IntPairPoints& o) const { return v != o.v; }
};

// The n points x0 y0 x1 y1 ... at v (integer coordinates are always finite).
template <typename T>
void appendPoints(const T* v, std::size_t n, std::size_t index, Path& out) {
  if constexpr (std::is_same_v<T, int>) {
    out.insert(out.end(), IntPairPoints{v}, IntPairPoints{v + 2 * n});
  } else {
    out.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double x = double(v[2 * i]);
      const double y = double(v[2 * i + 1]);
      if (!std::isfinite(x) || !std::isfinite(y)) {
        throw InvalidInputError(contourName(index) + ", point " + std::to_string(i) + ": " +
                                (std::isfinite(x) ? "y" : "x") + " is not a finite number");
      }
      out.emplace_back(x, y);
    }
  }
}

Path convertContour(const cv::Mat& input, std::size_t index) {
  Path path;
  if (input.empty()) return path;
  const int n = input.checkVector(2);
  if (n < 0) {
    throw InvalidInputError(contourName(index) + ": expected a vector of 2-channel points (" +
                            "CV_32SC2, CV_32FC2 or CV_64FC2), got " + std::to_string(input.rows) +
                            "x" + std::to_string(input.cols) + " with " +
                            std::to_string(input.channels()) + " channel(s) of " +
                            depthName(input.depth()));
  }
  // Sub-matrices are not continuous; a copy makes the points one flat array.
  const cv::Mat m = input.isContinuous() ? input : input.clone();
  switch (m.depth()) {
    case CV_32S:
      appendPoints(m.ptr<int>(), std::size_t(n), index, path);
      break;
    case CV_32F:
      appendPoints(m.ptr<float>(), std::size_t(n), index, path);
      break;
    case CV_64F:
      appendPoints(m.ptr<double>(), std::size_t(n), index, path);
      break;
    default:
      throw InvalidInputError(contourName(index) + ": point type " + depthName(m.depth()) +
                              " is not supported (use CV_32S, CV_32F or CV_64F)");
  }
  return path;
}

// Vectors of vectors of two ints (std::vector<std::vector<cv::Point>>, findContours' output),
// read in place: _InputArray::getMat(i) wraps each inner vector the same way (its bytes through
// std::vector<std::vector<uchar>>), but builds a cv::Mat per contour, about 400 instructions
// each (W4: 20,000 small contours per row). False for any other kind or type.
bool appendIntPointVectors(const cv::_InputArray& contours, Paths& out) {
  if (contours.kind() != cv::_InputArray::STD_VECTOR_VECTOR || contours.type() != CV_32SC2) {
    return false;
  }
  const auto& vectors = *static_cast<const std::vector<std::vector<uchar>>*>(contours.getObj());
  out.reserve(vectors.size());
  for (const std::vector<uchar>& bytes : vectors) {
    const std::size_t index = out.size();
    appendPoints(reinterpret_cast<const int*>(bytes.data()), bytes.size() / (2 * sizeof(int)),
                 index, out.emplace_back());
  }
  return true;
}

bool isArrayOfArrays(const cv::_InputArray& a) {
  const cv::_InputArray::KindFlag k = a.kind();
  return k == cv::_InputArray::NONE || k == cv::_InputArray::STD_VECTOR_VECTOR ||
         k == cv::_InputArray::STD_VECTOR_MAT || k == cv::_InputArray::STD_ARRAY_MAT ||
         k == cv::_InputArray::STD_VECTOR_UMAT;
}

// Depth of every contour in a findContours hierarchy; throws on bad indices and cycles.
std::vector<int> hierarchyDepths(const cv::Mat& h, std::size_t count) {
  const int n = h.checkVector(4, CV_32S);
  if (n < 0) {
    throw InvalidInputError("hierarchy: expected CV_32SC4 [next, previous, firstChild, parent] " +
                            std::string("entries, got ") + std::to_string(h.channels()) +
                            " channel(s) of " + depthName(h.depth()));
  }
  if (std::size_t(n) != count) {
    throw InvalidInputError("hierarchy: has " + std::to_string(n) + " entries for " +
                            std::to_string(count) + " contours");
  }
  const cv::Mat flat = h.isContinuous() ? h : h.clone();
  const cv::Vec4i* e = flat.ptr<cv::Vec4i>();
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < 4; ++k) {
      if (e[i][k] < -1 || e[i][k] >= n) {
        throw InvalidInputError("hierarchy: entry " + std::to_string(i) + " refers to contour " +
                                std::to_string(e[i][k]) + ", which does not exist");
      }
    }
  }
  std::vector<int> depth(std::size_t(n), -1);
  std::vector<int> chain;
  for (int i = 0; i < n; ++i) {
    chain.clear();
    int j = i;
    while (j != -1 && depth[std::size_t(j)] < 0) {
      chain.push_back(j);
      if (int(chain.size()) > n) {
        throw InvalidInputError("hierarchy: the parent links of contour " + std::to_string(i) +
                                " form a cycle");
      }
      j = e[j][3];
    }
    int d = j == -1 ? -1 : depth[std::size_t(j)];
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) depth[std::size_t(*it)] = ++d;
  }
  return depth;
}

int toInt(double v, double factor, std::size_t ring, std::size_t vertex) {
  const double scaled = std::round(v * factor);
  if (!(std::fabs(scaled) <= double(std::numeric_limits<int>::max()))) {
    throw InvalidInputError("ring " + std::to_string(ring) + ", vertex " + std::to_string(vertex) +
                            ": coordinate " + std::to_string(v) + " does not fit in an int" +
                            (factor != 1.0 ? " at this shift" : ""));
  }
  return int(scaled);
}

template <typename PointT>
PointT convertPoint(const Point& p, double factor, std::size_t ring, std::size_t vertex) {
  if constexpr (std::is_same_v<PointT, cv::Point>) {
    return {toInt(p.x, factor, ring, vertex), toInt(p.y, factor, ring, vertex)};
  } else {
    using V = decltype(PointT{}.x);
    return {V(p.x), V(p.y)};
  }
}

template <typename PointT>
std::vector<PointT> convertRing(const Path& ring, double factor, std::size_t index) {
  std::vector<PointT> out;
  out.reserve(ring.size());
  for (std::size_t i = 0; i < ring.size(); ++i) {
    out.push_back(convertPoint<PointT>(ring[i], factor, index, i));
  }
  return out;
}

template <typename PointT>
Contours<PointT> convertSet(const PolygonSet& set, double factor) {
  Contours<PointT> out;
  const std::size_t rings = set.ringCount();
  out.contours.reserve(rings);
  out.hierarchy.reserve(rings);
  int previousOuter = -1;
  for (const Polygon& polygon : set.polygons) {
    const int outer = int(out.contours.size());
    out.contours.push_back(convertRing<PointT>(polygon.outer, factor, std::size_t(outer)));
    out.hierarchy.emplace_back(-1, previousOuter, -1, -1);
    if (previousOuter >= 0) out.hierarchy[std::size_t(previousOuter)][0] = outer;
    previousOuter = outer;
    int previousHole = -1;
    for (const Path& hole : polygon.holes) {
      const int h = int(out.contours.size());
      out.contours.push_back(convertRing<PointT>(hole, factor, std::size_t(h)));
      out.hierarchy.emplace_back(-1, previousHole, -1, outer);
      if (previousHole >= 0) {
        out.hierarchy[std::size_t(previousHole)][0] = h;
      } else {
        out.hierarchy[std::size_t(outer)][2] = h;
      }
      previousHole = h;
    }
  }
  return out;
}

void checkShift(int shift) {
  if (shift < 0 || shift > 16) {
    throw InvalidInputError("shift must be in 0..16 (cv::fillPoly's limit), got " +
                            std::to_string(shift));
  }
}

// cv::fillPoly and cv::polylines reject empty contours.
std::vector<std::vector<cv::Point>> nonEmpty(std::vector<std::vector<cv::Point>> contours) {
  contours.erase(std::remove_if(contours.begin(), contours.end(),
                                [](const std::vector<cv::Point>& c) { return c.empty(); }),
                 contours.end());
  return contours;
}

void fill(cv::InputOutputArray image, const FixedPointContours& c, const cv::Scalar& color,
          int lineType) {
  const auto contours = nonEmpty(c.contours.contours);
  if (!contours.empty()) cv::fillPoly(image, contours, color, lineType, c.shift);
}

void outline(cv::InputOutputArray image, const FixedPointContours& c, bool closed,
             const cv::Scalar& color, int thickness, int lineType) {
  const auto contours = nonEmpty(c.contours.contours);
  if (!contours.empty())
    cv::polylines(image, contours, closed, color, thickness, lineType, c.shift);
}

}  // namespace

Path fromContour(cv::InputArray contour) { return convertContour(contour.getMat(), 0); }

Paths fromContours(cv::InputArrayOfArrays contours) {
  if (!isArrayOfArrays(contours)) {
    throw InvalidInputError(
        "contours: expected an array of contours (std::vector<std::vector<cv::Point>> or "
        "std::vector<cv::Mat>), got a single array");
  }
  Paths out;
  if (appendIntPointVectors(contours, out)) return out;
  const std::size_t n = contours.empty() ? 0 : contours.total();
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) out.push_back(convertContour(contours.getMat(int(i)), i));
  return out;
}

Paths fromContours(cv::InputArrayOfArrays contours, cv::InputArray hierarchy) {
  Paths out = fromContours(contours);
  const cv::Mat h = hierarchy.getMat();
  if (h.empty()) return out;
  const std::vector<int> depth = hierarchyDepths(h, out.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    const double area = signedArea(out[i]);
    const bool hole = depth[i] % 2 == 1;
    // roiclip's output orientation: outer rings negative, holes positive.
    if ((hole && area < 0) || (!hole && area > 0)) std::reverse(out[i].begin(), out[i].end());
  }
  return out;
}

std::vector<ContourGroup> groupContours(cv::InputArrayOfArrays contours, cv::InputArray hierarchy) {
  Paths rings = fromContours(contours, hierarchy);
  std::vector<ContourGroup> groups;
  const cv::Mat h = hierarchy.getMat();
  if (h.empty()) {
    for (std::size_t i = 0; i < rings.size(); ++i)
      groups.push_back({int(i), {std::move(rings[i])}});
    return groups;
  }
  const std::vector<int> depth = hierarchyDepths(h, rings.size());
  const cv::Mat flat = h.isContinuous() ? h : h.clone();
  const cv::Vec4i* e = flat.ptr<cv::Vec4i>();
  std::vector<std::size_t> groupOf(rings.size());
  for (std::size_t i = 0; i < rings.size(); ++i) {
    if (depth[i] % 2 != 0) continue;
    groupOf[i] = groups.size();
    groups.push_back({int(i), {std::move(rings[i])}});
  }
  // A second pass: a hand-made hierarchy may list a hole before its outer contour.
  for (std::size_t i = 0; i < rings.size(); ++i) {
    if (depth[i] % 2 == 0) continue;
    groups[groupOf[std::size_t(e[i][3])]].rings.push_back(std::move(rings[i]));
  }
  return groups;
}

// Snap-rounded first: rounding each vertex on its own can make rings cross.
Contours<cv::Point> toContours(const PolygonSet& set) {
  return convertSet<cv::Point>(roundTo(set, 1.0), 1.0);
}

Contours<cv::Point2f> toContours2f(const PolygonSet& set) {
  return convertSet<cv::Point2f>(set, 1.0);
}

Contours<cv::Point2d> toContours2d(const PolygonSet& set) {
  return convertSet<cv::Point2d>(set, 1.0);
}

// Snap-rounded onto the 2^-shift grid first, as toContours(): its vertices scale to exact ints.
FixedPointContours toFixedPointContours(const PolygonSet& set, int shift) {
  checkShift(shift);
  return {convertSet<cv::Point>(roundTo(set, std::ldexp(1.0, -shift)), std::ldexp(1.0, shift)),
          shift};
}

FixedPointContours toFixedPointContours(const Paths& paths, int shift) {
  checkShift(shift);
  FixedPointContours out;
  out.shift = shift;
  const double factor = std::ldexp(1.0, shift);
  for (std::size_t i = 0; i < paths.size(); ++i) {
    out.contours.contours.push_back(convertRing<cv::Point>(paths[i], factor, i));
    out.contours.hierarchy.emplace_back(i + 1 < paths.size() ? int(i + 1) : -1, int(i) - 1, -1, -1);
  }
  return out;
}

void fillPolygonSet(cv::InputOutputArray image, const PolygonSet& set, const cv::Scalar& color,
                    int lineType) {
  fill(image, toFixedPointContours(set), color, lineType);
}

void drawPolygonSet(cv::InputOutputArray image, const PolygonSet& set, const cv::Scalar& color,
                    int thickness, int lineType) {
  outline(image, toFixedPointContours(set), true, color, thickness, lineType);
}

void fillPaths(cv::InputOutputArray image, const Paths& paths, FillRule rule,
               const cv::Scalar& color, int lineType) {
  if (rule != FillRule::EvenOdd) {
    fillPolygonSet(image, simplify(paths, rule), color, lineType);
    return;
  }
  fill(image, toFixedPointContours(paths), color, lineType);
}

void drawPaths(cv::InputOutputArray image, const Paths& paths, const cv::Scalar& color,
               int thickness, int lineType, bool closed) {
  outline(image, toFixedPointContours(paths), closed, color, thickness, lineType);
}

}  // namespace roiclip::opencv
