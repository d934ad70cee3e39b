// SPDX-License-Identifier: MIT
// PreparedRegion: the clip operand snapped once, and a workspace of its own.
#include <algorithm>
#include <cmath>

#include <roiclip/roiclip.hpp>

#include "pipeline.hpp"
#include "workspace.hpp"

namespace roiclip {
namespace {

// The bounding box of every finite vertex, as one closed path of its corners (empty when there
// is none), grown by `grow` times its larger side on every side.
Paths boxOf(const Paths& paths, double grow) {
  detail::Box box;
  box.add(paths);
  if (box.empty()) return {};
  const double margin = grow * std::max({box.maxX - box.minX, box.maxY - box.minY, 1.0});
  return {{{box.minX - margin, box.minY - margin},
           {box.maxX + margin, box.minY - margin},
           {box.maxX + margin, box.maxY + margin},
           {box.minX - margin, box.maxY + margin}}};
}

// With a fitted grid the region gets a grid fitted to its box grown by this many times its side
// on every side, so that subjects around it (the rest of an image) snap to the same grid.
constexpr double kFittedMargin = 2.0;

}  // namespace

struct PreparedRegion::Impl {
  Impl(const Paths& paths, FillRule r, const Options& o)
      : rule(r),
        options(o),
        grid(o.grid.isFitted() ? resolveGrid(o.grid, boxOf(paths, kFittedMargin))
                               : resolveGrid(o.grid, paths)),
        region(detail::snapOperand(paths, 1, r, grid)) {
    if (options.grid.isFitted()) source = paths;
  }
  // True when every finite vertex of `paths` lies in the prepared grid's range.
  [[nodiscard]] bool inRange(const Paths& paths) const {
    if (!options.grid.isFitted()) return true;  // a fixed grid: snapping reports what is not
    for (const Path& corner : boxOf(paths, 0.0)) {
      for (const Point& p : corner) {
        if (!grid.toUnits(p.x, grid.origin.x) || !grid.toUnits(p.y, grid.origin.y)) return false;
      }
    }
    return true;
  }
  FillRule rule;
  Options options;
  Grid grid;
  detail::SnappedOperand region;
  Paths source;  // the region as given, for subjects beyond the fitted grid's range
  mutable detail::Workspace workspace;
};

PreparedRegion::PreparedRegion(const Paths& region, FillRule rule, const Options& options)
    : impl_(std::make_unique<Impl>(region, rule, options)) {}

PreparedRegion::PreparedRegion(const PolygonSet& region, const Options& options)
    : PreparedRegion(region.toPaths(), kPolygonSetFillRule, options) {}

PreparedRegion::~PreparedRegion() = default;
PreparedRegion::PreparedRegion(PreparedRegion&& other) noexcept = default;
PreparedRegion& PreparedRegion::operator=(PreparedRegion&& other) noexcept = default;

PolygonSet PreparedRegion::clip(ClipOp op, const Paths& subject, FillRule subjectRule) const {
  if (!impl_->inRange(subject)) {
    return roiclip::clip(op, subject, impl_->source, subjectRule, impl_->rule, impl_->options);
  }
  detail::SnappedOperand s = detail::snapOperand(subject, 0, subjectRule, impl_->grid);
  const detail::WorkspaceLease ws(impl_->workspace);
  return detail::clipSnapped(op, s, impl_->region, impl_->grid, impl_->options.limits, *ws);
}

PolygonSet PreparedRegion::clip(ClipOp op, const PolygonSet& subject) const {
  return clip(op, subject.toPaths(), kPolygonSetFillRule);
}

PolygonSet PreparedRegion::intersect(const Paths& subject, FillRule subjectRule) const {
  return clip(ClipOp::Intersection, subject, subjectRule);
}

Paths PreparedRegion::clipLines(const Paths& lines, LinePart part) const {
  if (!impl_->inRange(lines)) {
    return roiclip::clipLines(lines, impl_->source, impl_->rule, part, impl_->options);
  }
  std::vector<detail::InputEdge> edges;
  std::vector<std::size_t> firstEdge;
  detail::appendLineEdges(lines, impl_->grid, edges, firstEdge);
  const detail::WorkspaceLease ws(impl_->workspace);
  return detail::clipLinesSnapped(edges, firstEdge, impl_->region, part, impl_->grid,
                                  impl_->options.limits, *ws);
}

bool PreparedRegion::convex() const { return impl_->region.convex != 0; }

void PreparedRegion::releaseMemory() {
  const detail::WorkspaceLease ws(impl_->workspace);
  if (&*ws == &impl_->workspace) ws->release();
}

}  // namespace roiclip
