// SPDX-License-Identifier: MIT
// The pipeline, in the order of the paper: split every self- and mutual intersection, classify
// by winding number under the fill rules, trace simple contours with the stack method, fix the
// orientation and nest holes in their outer rings.
#include <roiclip/roiclip.hpp>

#include "pipeline.hpp"

namespace roiclip {
namespace detail {
namespace {

PolygonSet resolve(const std::vector<InputEdge>& edges, const std::vector<ExactEdge>& exactEdges,
                   const Combination& how, const Grid& grid) {
  const Arrangement arrangement = splitEdges(edges, exactEdges, how);  // stages 1 and 2
  const Contours contours = traceContours(arrangement);
  return buildNesting(arrangement, contours, grid);
}

// The pre-clipped edges, kept per thread between calls (see recycle()).
thread_local std::vector<ExactEdge> tClipped;

// Intersection with one convex ring: pre-clip the other operand to it, then resolve that alone.
PolygonSet intersectConvexRing(const Paths& other, FillRule otherRule, int otherOperand,
                               const std::vector<IPoint>& convexRing, FillRule convexRule,
                               const Grid& grid, const Limits& limits) {
  if (!isFilled(convexRule, convexOrientation(convexRing))) return {};
  Combination how;
  how.subjectRule = otherRule;
  how.maxCrossings = limits.maxCrossings;
  const RecycleOnExit<ExactEdge> recycled(tClipped);
  preclipConvex(snapRings(other, otherOperand, grid), convexRing, tClipped);
  return resolve({}, tClipped, how, grid);
}

}  // namespace

PolygonSet booleanGeneral(const Paths& subject, const Paths* clipPaths, const Combination& how,
                          const Grid& grid) {
  std::vector<InputEdge> edges;
  appendInputEdges(subject, 0, grid, edges);
  if (clipPaths != nullptr) appendInputEdges(*clipPaths, 1, grid, edges);
  return resolve(edges, {}, how, grid);
}

}  // namespace detail

void releaseThreadBuffers() {
  std::vector<detail::ExactEdge>().swap(detail::tClipped);
  detail::releasePreclipBuffers();
  detail::releaseSweepBuffers();
}

PolygonSet simplify(const Paths& paths, FillRule rule, const Options& options) {
  detail::Combination how;
  how.subjectRule = rule;
  how.maxCrossings = options.limits.maxCrossings;
  return detail::booleanGeneral(paths, nullptr, how, resolveGrid(options.grid, paths));
}

PolygonSet clip(ClipOp op, const Paths& subject, const Paths& clipPaths, FillRule subjectRule,
                FillRule clipRule, const Options& options) {
  const Grid grid = resolveGrid(options.grid, subject, clipPaths);  // one grid for both operands
  if (op == ClipOp::Intersection) {
    // The region-of-interest case: a convex clip ring takes the linear pre-clip path.
    const auto clipRings = detail::snapRings(clipPaths, 1, grid);
    if (clipRings.size() == 1 && detail::convexOrientation(clipRings[0]) != 0) {
      return detail::intersectConvexRing(subject, subjectRule, 0, clipRings[0], clipRule, grid,
                                         options.limits);
    }
    const auto subjectRings = detail::snapRings(subject, 0, grid);
    if (subjectRings.size() == 1 && detail::convexOrientation(subjectRings[0]) != 0) {
      return detail::intersectConvexRing(clipPaths, clipRule, 1, subjectRings[0], subjectRule, grid,
                                         options.limits);
    }
  }
  detail::Combination how;
  how.binary = true;
  how.op = op;
  how.subjectRule = subjectRule;
  how.clipRule = clipRule;
  how.maxCrossings = options.limits.maxCrossings;
  return detail::booleanGeneral(subject, &clipPaths, how, grid);
}

PolygonSet intersect(const Paths& subject, const Paths& clipPaths, FillRule rule,
                     const Options& options) {
  return clip(ClipOp::Intersection, subject, clipPaths, rule, rule, options);
}
PolygonSet unite(const Paths& subject, const Paths& clipPaths, FillRule rule,
                 const Options& options) {
  return clip(ClipOp::Union, subject, clipPaths, rule, rule, options);
}
PolygonSet subtract(const Paths& subject, const Paths& clipPaths, FillRule rule,
                    const Options& options) {
  return clip(ClipOp::Difference, subject, clipPaths, rule, rule, options);
}
PolygonSet symmetricDifference(const Paths& subject, const Paths& clipPaths, FillRule rule,
                               const Options& options) {
  return clip(ClipOp::Xor, subject, clipPaths, rule, rule, options);
}

}  // namespace roiclip
