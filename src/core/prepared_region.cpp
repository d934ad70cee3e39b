// SPDX-License-Identifier: MIT
// PreparedRegion: the clip operand snapped once, and a workspace of its own.
#include <roiclip/roiclip.hpp>

#include "pipeline.hpp"
#include "workspace.hpp"

namespace roiclip {

struct PreparedRegion::Impl {
  Impl(const Paths& paths, FillRule rule, const Grid& g)
      : grid(g), region(detail::snapOperand(paths, 1, rule, g)) {}
  Grid grid;
  detail::SnappedOperand region;
  mutable detail::Workspace workspace;
};

PreparedRegion::PreparedRegion(const Paths& region, FillRule rule, const Grid& grid)
    : impl_(std::make_unique<Impl>(region, rule, grid)) {}

PreparedRegion::PreparedRegion(const PolygonSet& region, const Grid& grid)
    : PreparedRegion(region.toPaths(), kPolygonSetFillRule, grid) {}

PreparedRegion::~PreparedRegion() = default;
PreparedRegion::PreparedRegion(PreparedRegion&& other) noexcept = default;
PreparedRegion& PreparedRegion::operator=(PreparedRegion&& other) noexcept = default;

PolygonSet PreparedRegion::clip(ClipOp op, const Paths& subject, FillRule subjectRule) const {
  detail::SnappedOperand s = detail::snapOperand(subject, 0, subjectRule, impl_->grid);
  const detail::WorkspaceLease ws(impl_->workspace);
  return detail::clipSnapped(op, s, impl_->region, impl_->grid, *ws);
}

PolygonSet PreparedRegion::clip(ClipOp op, const PolygonSet& subject) const {
  return clip(op, subject.toPaths(), kPolygonSetFillRule);
}

PolygonSet PreparedRegion::intersect(const Paths& subject, FillRule subjectRule) const {
  return clip(ClipOp::Intersection, subject, subjectRule);
}

Paths PreparedRegion::clipLines(const Paths& lines, LinePart part) const {
  std::vector<detail::InputEdge> edges;
  std::vector<std::size_t> firstEdge;
  detail::appendLineEdges(lines, impl_->grid, edges, firstEdge);
  const detail::WorkspaceLease ws(impl_->workspace);
  return detail::clipLinesSnapped(edges, firstEdge, impl_->region, part, impl_->grid, *ws);
}

bool PreparedRegion::convex() const { return impl_->region.convex != 0; }

void PreparedRegion::releaseMemory() {
  const detail::WorkspaceLease ws(impl_->workspace);
  if (&*ws == &impl_->workspace) ws->release();
}

}  // namespace roiclip
