// SPDX-License-Identifier: MIT
// PreparedRegion: the clip operand snapped once, and a workspace of its own. With a fitted grid
// the region's grid is fitted to its grown box (regionGrid()); subjects that grid does not take
// as the free function would (beyond its range, or off a grid that holds the region exactly) go
// to the free function.
#include <algorithm>
#include <cmath>

#include <roiclip/roiclip.hpp>

#include "pipeline.hpp"
#include "workspace.hpp"

namespace roiclip {
namespace {

// The bounding box of every finite vertex, grown by `grow` times its larger side on every side.
detail::Box boxOf(const Paths& paths, double grow) {
  detail::Box box;
  box.add(paths);
  if (box.empty()) return box;
  const double margin = grow * std::max({box.maxX - box.minX, box.maxY - box.minY, 1.0});
  box.minX -= margin;
  box.maxX += margin;
  box.minY -= margin;
  box.maxY += margin;
  return box;
}

// With a fitted grid the region gets a grid fitted to its box grown by this many times its side
// on every side, so that subjects around it (the rest of an image) snap to the same grid.
constexpr double kFittedMargin = 2.0;

// The fitted grid of a region: the power-of-two grid of its grown box when that holds the
// region exactly, else the finest decimal grid of the grown box that does (so subjects written
// with as many decimals or fewer stay on it), else the power-of-two grid again (`exact` false).
Grid regionGrid(const Paths& paths, bool& exact) {
  const detail::Box box = boxOf(paths, kFittedMargin);
  exact = true;
  if (box.empty()) return Grid::fixed(1.0);
  const Grid binary = detail::fitBinaryGrid(box);
  if (detail::holdsExactly(binary, paths)) return binary;
  if (const auto decimal = detail::fitDecimalGrid(box, paths, {}, detail::DecimalPick::Finest)) {
    return *decimal;
  }
  exact = false;
  return binary;
}

}  // namespace

struct PreparedRegion::Impl {
  Impl(const Paths& paths, FillRule r, const Options& o)
      : rule(r),
        options(o),
        grid(o.grid.isFitted() ? regionGrid(paths, regionExact) : resolveGrid(o.grid, paths)),
        region(detail::snapOperand(paths, 1, r, grid)) {
    if (options.grid.isFitted()) source = paths;
  }
  // True when the prepared grid gives what the free function gives for `paths`: always on a
  // fixed grid; on a fitted one when every finite vertex lies in the grid's range and, if the
  // grid holds the region exactly, the subject too (the free function's grid then holds both
  // exactly, and exact inputs give the same correctly rounded output on any grid).
  // `box` receives the box of the paths' finite vertices (empty on a fixed grid: no pass).
  [[nodiscard]] bool takes(const Paths& paths, detail::Box& box) const {
    box = {};
    if (!options.grid.isFitted()) return true;  // a fixed grid: snapping reports what is not
    box = boxOf(paths, 0.0);
    for (const double x : {box.minX, box.maxX}) {
      if (!box.empty() && !grid.toUnits(x, grid.origin.x)) return false;
    }
    for (const double y : {box.minY, box.maxY}) {
      if (!box.empty() && !grid.toUnits(y, grid.origin.y)) return false;
    }
    return !regionExact || detail::holdsExactly(grid, paths);
  }
  FillRule rule;
  Options options;
  bool regionExact = true;  // the fitted grid holds every region vertex exactly
  Grid grid;
  detail::SnappedOperand region;
  Paths source;  // the region as given, for subjects the prepared grid does not take
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
  detail::Box box;
  if (!impl_->takes(subject, box)) {
    return roiclip::clip(op, subject, impl_->source, subjectRule, impl_->rule, impl_->options);
  }
  const detail::SnappedOperand& region = impl_->region;
  const detail::BoxPlace place = op == ClipOp::Intersection
                                     ? detail::placeBox(box, impl_->grid, region)
                                     : detail::BoxPlace::Unknown;
  if (place == detail::BoxPlace::Outside) return {};  // as the free function, unsnapped
  const detail::WorkspaceLease ws(impl_->workspace);
  detail::SnappedOperand s = detail::snapOperand(subject, 0, subjectRule, impl_->grid, true, &*ws);
  PolygonSet result =
      detail::clipSnapped(op, s, region, impl_->grid, impl_->options.limits, *ws, place);
  detail::giveBackRings(s, 0, *ws);
  return result;
}

PolygonSet PreparedRegion::clip(ClipOp op, const PolygonSet& subject) const {
  return clip(op, subject.toPaths(), kPolygonSetFillRule);
}

PolygonSet PreparedRegion::intersect(const Paths& subject, FillRule subjectRule) const {
  return clip(ClipOp::Intersection, subject, subjectRule);
}

Paths PreparedRegion::clipLines(const Paths& lines, LinePart part) const {
  detail::Box box;
  if (!impl_->takes(lines, box)) {
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
