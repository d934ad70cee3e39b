// The pipeline, in the order of the paper: split every self- and mutual intersection, classify
// by winding number under the fill rules, trace simple contours with the stack method, fix the
// orientation and nest holes in their outer rings.
#include <roiclip/roiclip.hpp>

#include "pipeline.hpp"

namespace roiclip {
namespace {

PolygonSet run(const Paths& subject, const Paths* clipPaths, const detail::Combination& how,
               const Grid& grid) {
  std::vector<detail::InputEdge> edges;
  detail::appendInputEdges(subject, 0, grid, edges);
  if (clipPaths != nullptr) detail::appendInputEdges(*clipPaths, 1, grid, edges);
  const detail::Arrangement arrangement = detail::splitEdges(edges);
  const std::vector<detail::Side> sides = detail::classifyPieces(arrangement, how);
  const detail::Contours contours = detail::traceContours(arrangement, sides);
  return detail::buildNesting(arrangement, sides, contours, grid);
}

}  // namespace

PolygonSet simplify(const Paths& paths, FillRule rule, const Grid& grid) {
  detail::Combination how;
  how.subjectRule = rule;
  return run(paths, nullptr, how, grid);
}

PolygonSet clip(ClipOp op, const Paths& subject, const Paths& clipPaths, FillRule subjectRule,
                FillRule clipRule, const Grid& grid) {
  detail::Combination how;
  how.binary = true;
  how.op = op;
  how.subjectRule = subjectRule;
  how.clipRule = clipRule;
  return run(subject, &clipPaths, how, grid);
}

PolygonSet intersect(const Paths& subject, const Paths& clipPaths, FillRule rule,
                     const Grid& grid) {
  return clip(ClipOp::Intersection, subject, clipPaths, rule, rule, grid);
}
PolygonSet unite(const Paths& subject, const Paths& clipPaths, FillRule rule, const Grid& grid) {
  return clip(ClipOp::Union, subject, clipPaths, rule, rule, grid);
}
PolygonSet subtract(const Paths& subject, const Paths& clipPaths, FillRule rule, const Grid& grid) {
  return clip(ClipOp::Difference, subject, clipPaths, rule, rule, grid);
}
PolygonSet symmetricDifference(const Paths& subject, const Paths& clipPaths, FillRule rule,
                               const Grid& grid) {
  return clip(ClipOp::Xor, subject, clipPaths, rule, rule, grid);
}

}  // namespace roiclip
