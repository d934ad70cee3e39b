// SPDX-License-Identifier: MIT
// PolygonSet operands of clip() and its shorthands: a conversion to the set's rings under
// kPolygonSetFillRule, then the Paths entry points (no other code path).
#include <roiclip/roiclip.hpp>

namespace roiclip {

PolygonSet clip(ClipOp op, const PolygonSet& subject, const Paths& clipPaths, FillRule clipRule,
                const Options& options) {
  return clip(op, subject.toPaths(), clipPaths, kPolygonSetFillRule, clipRule, options);
}

PolygonSet clip(ClipOp op, const Paths& subject, const PolygonSet& clipSet, FillRule subjectRule,
                const Options& options) {
  return clip(op, subject, clipSet.toPaths(), subjectRule, kPolygonSetFillRule, options);
}

PolygonSet clip(ClipOp op, const PolygonSet& subject, const PolygonSet& clipSet,
                const Options& options) {
  return clip(op, subject.toPaths(), clipSet.toPaths(), kPolygonSetFillRule, kPolygonSetFillRule,
              options);
}

PolygonSet intersect(const PolygonSet& s, const Paths& c, FillRule rule, const Options& options) {
  return clip(ClipOp::Intersection, s, c, rule, options);
}
PolygonSet intersect(const Paths& s, const PolygonSet& c, FillRule rule, const Options& options) {
  return clip(ClipOp::Intersection, s, c, rule, options);
}
PolygonSet intersect(const PolygonSet& s, const PolygonSet& c, const Options& options) {
  return clip(ClipOp::Intersection, s, c, options);
}

PolygonSet unite(const PolygonSet& s, const Paths& c, FillRule rule, const Options& options) {
  return clip(ClipOp::Union, s, c, rule, options);
}
PolygonSet unite(const Paths& s, const PolygonSet& c, FillRule rule, const Options& options) {
  return clip(ClipOp::Union, s, c, rule, options);
}
PolygonSet unite(const PolygonSet& s, const PolygonSet& c, const Options& options) {
  return clip(ClipOp::Union, s, c, options);
}

PolygonSet subtract(const PolygonSet& s, const Paths& c, FillRule rule, const Options& options) {
  return clip(ClipOp::Difference, s, c, rule, options);
}
PolygonSet subtract(const Paths& s, const PolygonSet& c, FillRule rule, const Options& options) {
  return clip(ClipOp::Difference, s, c, rule, options);
}
PolygonSet subtract(const PolygonSet& s, const PolygonSet& c, const Options& options) {
  return clip(ClipOp::Difference, s, c, options);
}

PolygonSet symmetricDifference(const PolygonSet& s, const Paths& c, FillRule rule,
                               const Options& options) {
  return clip(ClipOp::Xor, s, c, rule, options);
}
PolygonSet symmetricDifference(const Paths& s, const PolygonSet& c, FillRule rule,
                               const Options& options) {
  return clip(ClipOp::Xor, s, c, rule, options);
}
PolygonSet symmetricDifference(const PolygonSet& s, const PolygonSet& c, const Options& options) {
  return clip(ClipOp::Xor, s, c, options);
}

}  // namespace roiclip
