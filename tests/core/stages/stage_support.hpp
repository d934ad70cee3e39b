// SPDX-License-Identifier: MIT
// Helpers of the stage tests: run stages 0 to 1 on pixel inputs, name arrangement vertices, and
// find points just below and above a piece.
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <roiclip/roiclip.hpp>

#include "pipeline.hpp"
#include "workspace.hpp"

namespace roiclip::stages {

/// Grid{1}: grid units are pixels, so arrangement vertices read as the input's points.
inline const Grid kUnitGrid{1.0};

inline detail::BooleanSpec simplifyWith(FillRule rule) {
  detail::BooleanSpec how;
  how.subjectRule = rule;
  how.recordWindings = true;
  return how;
}

inline detail::BooleanSpec clipWith(ClipOp op) {
  detail::BooleanSpec how;
  how.binary = true;
  how.op = op;
  how.recordWindings = true;
  return how;
}

/// Stages 0 and 1 (with 2 inside the sweep) of the general path.
inline detail::Arrangement arrange(const Paths& subject, const Paths* clipPaths,
                                   const detail::BooleanSpec& how, const Grid& grid = kUnitGrid) {
  std::vector<detail::InputEdge> edges;
  detail::appendInputEdges(subject, 0, grid, edges);
  if (clipPaths != nullptr) detail::appendInputEdges(*clipPaths, 1, grid, edges);
  return detail::splitEdges(edges, {}, how);
}

inline std::string name(const detail::XPoint& p) {
  const auto str = [](detail::i128 v) { return std::to_string(static_cast<long long>(v)); };
  if (p.w == 1) return "(" + str(p.x) + "," + str(p.y) + ")";
  return "(" + str(p.x) + "/" + str(p.w) + "," + str(p.y) + "/" + str(p.w) + ")";
}

/// "(x,y)" of every arrangement vertex, by vertex id.
inline std::vector<std::string> vertexNames(const detail::Arrangement& a) {
  std::vector<std::string> names;
  for (std::size_t v = 0; v < a.vertices.size(); ++v) names.push_back(name(a.point(int(v))));
  return names;
}

/// Points at distance d below and above the middle of a piece (in grid units). Below a vertical
/// piece is its right side: the sweep orders vertical edges as very steep rising ones.
inline std::pair<Point, Point> sidePoints(const detail::Arrangement& a, const detail::EdgePiece& p,
                                          double d) {
  const detail::XPoint l = a.point(p.left);
  const detail::XPoint r = a.point(p.right);
  const Point mid((l.fx + r.fx) / 2, (l.fy + r.fy) / 2);
  if (p.ax == p.bx) return {mid + Point(d, 0), mid - Point(d, 0)};
  return {mid - Point(0, d), mid + Point(0, d)};
}

/// A star-shaped ring of n vertices around `centre`: sorted random angles, radii uniform in
/// [minFraction, 1] * radius, coordinates rounded to integers (so rounding may make it touch
/// itself now and then).
inline Path starShapedRing(std::mt19937& rng, int n, Point centre, double radius,
                           double minFraction) {
  std::vector<double> angles(static_cast<std::size_t>(n));
  for (double& a : angles) a = std::uniform_real_distribution<double>(0, 2 * M_PI)(rng);
  std::sort(angles.begin(), angles.end());
  Path path;
  for (double a : angles) {
    const double r = radius * std::uniform_real_distribution<double>(minFraction, 1.0)(rng);
    path.emplace_back(std::round(centre.x + r * std::cos(a)),
                      std::round(centre.y + r * std::sin(a)));
  }
  return path;
}

/// simplify() on stages 0 to 4, without the simple-ring shortcut.
inline PolygonSet generalSimplify(const Paths& paths, FillRule rule) {
  const Grid grid = resolveGrid(Options{}.grid, paths);
  const detail::Rings rings = detail::snapRings(paths, 0, grid);
  std::vector<detail::InputEdge> edges;
  detail::appendRingEdges(rings, 0, edges);
  detail::BooleanSpec spec;
  spec.subjectRule = rule;
  const detail::Arrangement a = detail::splitEdges(edges, {}, spec);
  const detail::Contours c = detail::traceContours(a);
  return detail::buildNesting(a, c, grid);
}

/// intersect() with both operands through the sweep: no convex pre-clip, no Weiler-Atherton.
inline PolygonSet generalIntersect(const Paths& s, const Paths& c, FillRule rule,
                                   FillRule clipRule) {
  const Grid grid = resolveGrid(Options{}.grid, s, c);
  detail::SnappedOperand so = detail::snapOperand(s, 0, rule, grid, false);
  const detail::SnappedOperand co = detail::snapOperand(c, 1, clipRule, grid, false);
  detail::Workspace ws;
  return detail::clipSnapped(ClipOp::Intersection, so, co, grid, Limits{}, ws);
}

/// Shoelace sum of a traced ring in the raw frame (grid units).
inline double rawSignedArea(const detail::Arrangement& a, const detail::TracedRing& ring) {
  double twice = 0;
  for (std::size_t i = 0; i < ring.vertices.size(); ++i) {
    const detail::XPoint p = a.point(ring.vertices[i]);
    const detail::XPoint q = a.point(ring.vertices[(i + 1) % ring.vertices.size()]);
    twice += p.fx * q.fy - q.fx * p.fy;
  }
  return twice / 2;
}

}  // namespace roiclip::stages
