// SPDX-License-Identifier: MIT
#include "workloads.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>

#include <glm/common.hpp>
#include <nlohmann/json.hpp>
#include <roiclip/roiclip.hpp>

namespace roiclip::bench {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Integer cross product of (a - c) and (b - c); exact for the integer coordinates used here.
double crossAround(const Point& c, const Point& a, const Point& b) {
  return (a.x - c.x) * (b.y - c.y) - (a.y - c.y) * (b.x - c.x);
}

struct BlobShape {
  Point centre;
  double radius = 0.0;
  double amplitude[6] = {};
  double phase[6] = {};
  [[nodiscard]] double radiusAt(double angle) const {
    double r = 1.0;
    for (int k = 0; k < 6; ++k) r += amplitude[k] * std::cos(double(k + 2) * angle + phase[k]);
    return radius * r;
  }
};

// Trace the blob's boundary as integer points, keeping only points at strictly increasing angle
// around the centre so that the ring is star-shaped and therefore simple.
Path traceBlob(const BlobShape& shape, std::size_t samples) {
  Path ring;
  ring.reserve(samples / 4);
  for (std::size_t i = 0; i < samples; ++i) {
    const double a = 2.0 * kPi * double(i) / double(samples);
    const double r = shape.radiusAt(a);
    const Point p{std::round(shape.centre.x + r * std::cos(a)),
                  std::round(shape.centre.y + r * std::sin(a))};
    if (!ring.empty() && !(crossAround(shape.centre, ring.back(), p) > 0.0)) continue;
    ring.push_back(p);
  }
  while (ring.size() > 3 && !(crossAround(shape.centre, ring.back(), ring.front()) > 0.0)) {
    ring.pop_back();
  }
  return ring;
}

}  // namespace

double snapToGrid(double v) { return std::nearbyint(v * kGridScale) / kGridScale; }

Path blobContour(std::size_t vertices, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  BlobShape shape;
  for (int k = 0; k < 6; ++k) {
    // Low harmonics dominate, like a real blob; the sum stays well below 1 so r > 0.
    shape.amplitude[k] = 0.12 * (unit(rng) - 0.5) / double(k + 1);
    shape.phase[k] = 2.0 * kPi * unit(rng);
  }
  // An 8-connected digital circle of radius R has about 4*sqrt(2)*R pixels; refine R from there.
  shape.radius = double(vertices) / (4.0 * std::sqrt(2.0));
  Path ring;
  for (int attempt = 0; attempt < 4; ++attempt) {
    const double extent = shape.radius * 1.5 + 8.0;
    shape.centre = Point{std::round(extent), std::round(extent)};
    ring = traceBlob(shape, 8 * vertices);
    const double ratio = double(vertices) / double(ring.size());
    if (std::fabs(ratio - 1.0) < 0.005) break;
    shape.radius *= ratio;
  }
  return ring;
}

Path twistedContour(std::size_t vertices, std::size_t twists, std::uint32_t seed) {
  Path ring = blobContour(vertices, seed);
  std::mt19937 rng(seed ^ 0x9e3779b9u);
  const std::size_t slot = ring.size() / std::max<std::size_t>(twists, 1);
  std::uniform_int_distribution<std::size_t> length(4, 40);
  for (std::size_t t = 0; t < twists && slot > 64; ++t) {
    const std::size_t begin = t * slot + std::uniform_int_distribution<std::size_t>(1, 16)(rng);
    const std::size_t end = std::min(begin + length(rng), ring.size() - 1);
    // Reversing a run of a nearly straight chain swaps its ends: the two new edges cross.
    std::reverse(ring.begin() + std::ptrdiff_t(begin), ring.begin() + std::ptrdiff_t(end));
  }
  return ring;
}

Path randomPolygon(std::size_t vertices, double size, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coord(0.0, size);
  Path ring;
  ring.reserve(vertices);
  for (std::size_t i = 0; i < vertices; ++i) {
    ring.push_back({snapToGrid(coord(rng)), snapToGrid(coord(rng))});
  }
  return ring;
}

Path perspectiveQuad(const Path& ring, std::uint32_t seed) {
  Point lo = ring.front(), hi = ring.front();
  for (const Point& p : ring) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const Point centre = 0.5 * (lo + hi);
  const Point half = 0.5 * (hi - lo);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double angle = (10.0 + 20.0 * unit(rng)) * kPi / 180.0;
  const double c = std::cos(angle), s = std::sin(angle);
  // Corners in order of increasing angle in the raw frame; the +-15% jitter keeps them convex
  // while breaking any symmetry (a real tag-derived ROI is a perspective-distorted square).
  // At 0.8 of the half-extent the corners stick out of a round blob and the edge midpoints stay
  // inside it, so the contour crosses every side of the quad.
  const Point unitCorners[4] = {{0.8, 0.8}, {-0.8, 0.8}, {-0.8, -0.8}, {0.8, -0.8}};
  Path quad;
  for (const Point& u : unitCorners) {
    const double jx = 1.0 + 0.3 * (unit(rng) - 0.5);
    const double jy = 1.0 + 0.3 * (unit(rng) - 0.5);
    const Point local{u.x * half.x * jx, u.y * half.y * jy};
    const Point rotated{c * local.x - s * local.y, s * local.x + c * local.y};
    quad.push_back(
        {snapToGrid(centre.x + rotated.x + 0.37), snapToGrid(centre.y + rotated.y + 0.61)});
  }
  if (signedArea(quad) < 0.0) std::reverse(quad.begin(), quad.end());
  return quad;
}

void writeCaseJson(const std::string& file, const Paths& subject, const Paths& clip, ClipOp op,
                   FillRule subjectRule, FillRule clipRule) {
  const auto toJson = [](const Paths& paths) {
    nlohmann::json out = nlohmann::json::array();
    for (const Path& path : paths) {
      nlohmann::json ring = nlohmann::json::array();
      for (const Point& p : path) ring.push_back({p.x, p.y});
      out.push_back(ring);
    }
    return out;
  };
  const nlohmann::json doc = {{"subject", toJson(subject)},
                              {"clip", toJson(clip)},
                              {"op", toString(op)},
                              {"subjectFillRule", toString(subjectRule)},
                              {"clipFillRule", toString(clipRule)}};
  std::ofstream out(file);
  out << doc.dump() << '\n';
  if (!out) throw InvalidInputError("cannot write benchmark case file " + file);
}

}  // namespace roiclip::bench
