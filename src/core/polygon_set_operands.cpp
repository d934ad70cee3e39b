// SPDX-License-Identifier: MIT
// PolygonSet operands of clip() and its shorthands: a conversion to the set's rings under
// kPolygonSetFillRule, then the Paths entry points (no other code path).
#include <roiclip/roiclip.hpp>

namespace roiclip {

PolygonSet clip(ClipOp op, const PolygonSet& subject, const Paths& clipPaths, FillRule clipRule,
                const Grid& grid) {
  return clip(op, subject.toPaths(), clipPaths, kPolygonSetFillRule, clipRule, grid);
}

PolygonSet clip(ClipOp op, const Paths& subject, const PolygonSet& clipSet, FillRule subjectRule,
                const Grid& grid) {
  return clip(op, subject, clipSet.toPaths(), subjectRule, kPolygonSetFillRule, grid);
}

PolygonSet clip(ClipOp op, const PolygonSet& subject, const PolygonSet& clipSet, const Grid& grid) {
  return clip(op, subject.toPaths(), clipSet.toPaths(), kPolygonSetFillRule, kPolygonSetFillRule,
              grid);
}

PolygonSet intersect(const PolygonSet& s, const Paths& c, FillRule rule, const Grid& grid) {
  return clip(ClipOp::Intersection, s, c, rule, grid);
}
PolygonSet intersect(const Paths& s, const PolygonSet& c, FillRule rule, const Grid& grid) {
  return clip(ClipOp::Intersection, s, c, rule, grid);
}
PolygonSet intersect(const PolygonSet& s, const PolygonSet& c, const Grid& grid) {
  return clip(ClipOp::Intersection, s, c, grid);
}

PolygonSet unite(const PolygonSet& s, const Paths& c, FillRule rule, const Grid& grid) {
  return clip(ClipOp::Union, s, c, rule, grid);
}
PolygonSet unite(const Paths& s, const PolygonSet& c, FillRule rule, const Grid& grid) {
  return clip(ClipOp::Union, s, c, rule, grid);
}
PolygonSet unite(const PolygonSet& s, const PolygonSet& c, const Grid& grid) {
  return clip(ClipOp::Union, s, c, grid);
}

PolygonSet subtract(const PolygonSet& s, const Paths& c, FillRule rule, const Grid& grid) {
  return clip(ClipOp::Difference, s, c, rule, grid);
}
PolygonSet subtract(const Paths& s, const PolygonSet& c, FillRule rule, const Grid& grid) {
  return clip(ClipOp::Difference, s, c, rule, grid);
}
PolygonSet subtract(const PolygonSet& s, const PolygonSet& c, const Grid& grid) {
  return clip(ClipOp::Difference, s, c, grid);
}

PolygonSet symmetricDifference(const PolygonSet& s, const Paths& c, FillRule rule,
                               const Grid& grid) {
  return clip(ClipOp::Xor, s, c, rule, grid);
}
PolygonSet symmetricDifference(const Paths& s, const PolygonSet& c, FillRule rule,
                               const Grid& grid) {
  return clip(ClipOp::Xor, s, c, rule, grid);
}
PolygonSet symmetricDifference(const PolygonSet& s, const PolygonSet& c, const Grid& grid) {
  return clip(ClipOp::Xor, s, c, grid);
}

}  // namespace roiclip
