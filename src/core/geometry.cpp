// SPDX-License-Identifier: MIT
// Small helpers on the public geometry types.
#include <algorithm>
#include <cctype>
#include <string>

#include <roiclip/roiclip.hpp>

namespace roiclip {

double signedArea(const Path& path) {
  const std::size_t n = path.size();
  if (n < 3) return 0.0;
  // Shoelace relative to the first point keeps the products small and the sum accurate.
  const Point o = path[0];
  double twice = 0.0;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const Point a = path[i] - o;
    const Point b = path[i + 1] - o;
    twice += a.x * b.y - b.x * a.y;
  }
  return 0.5 * twice;
}

double PolygonSet::area() const {
  double total = 0.0;
  for (const Polygon& p : polygons) {
    total -= signedArea(p.outer);
    for (const Path& h : p.holes) total -= signedArea(h);
  }
  return total;
}

std::size_t PolygonSet::ringCount() const {
  std::size_t n = 0;
  for (const Polygon& p : polygons) n += 1 + p.holes.size();
  return n;
}

Paths PolygonSet::toPaths() const {
  Paths out;
  out.reserve(ringCount());
  for (const Polygon& p : polygons) {
    out.push_back(p.outer);
    for (const Path& h : p.holes) out.push_back(h);
  }
  return out;
}

namespace {
std::string normalized(const char* name) {
  std::string s;
  for (const char* c = name; c != nullptr && *c != '\0'; ++c) {
    if (*c != '-' && *c != '_') s.push_back(char(std::tolower(static_cast<unsigned char>(*c))));
  }
  return s;
}
}  // namespace

FillRule parseFillRule(const char* name) {
  const std::string s = normalized(name);
  if (s == "evenodd") return FillRule::EvenOdd;
  if (s == "nonzero") return FillRule::NonZero;
  if (s == "positive") return FillRule::Positive;
  if (s == "negative") return FillRule::Negative;
  throw InvalidInputError(std::string("unknown fill rule '") + (name ? name : "") +
                          "' (expected evenodd, nonzero, positive or negative)");
}

const char* toString(FillRule rule) {
  switch (rule) {
    case FillRule::EvenOdd:
      return "evenodd";
    case FillRule::NonZero:
      return "nonzero";
    case FillRule::Positive:
      return "positive";
    case FillRule::Negative:
      return "negative";
  }
  return "?";
}

ClipOp parseClipOp(const char* name) {
  const std::string s = normalized(name);
  if (s == "intersection" || s == "intersect" || s == "and") return ClipOp::Intersection;
  if (s == "union" || s == "or") return ClipOp::Union;
  if (s == "difference" || s == "diff" || s == "minus") return ClipOp::Difference;
  if (s == "xor") return ClipOp::Xor;
  throw InvalidInputError(std::string("unknown operation '") + (name ? name : "") +
                          "' (expected intersection, union, difference or xor)");
}

const char* toString(ClipOp op) {
  switch (op) {
    case ClipOp::Intersection:
      return "intersection";
    case ClipOp::Union:
      return "union";
    case ClipOp::Difference:
      return "difference";
    case ClipOp::Xor:
      return "xor";
  }
  return "?";
}

}  // namespace roiclip
